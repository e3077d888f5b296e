#version 450 core
// probe/alu.frag: the probe's arithmetic (probe/alu.glsl) once per pixel as a fragment pass (drawn with
// render/fullscreen.vert, one triangle over the viewport).
#include "probe/alu.glsl"
layout(location = 0) out vec4 oColour;

void main() {
    oColour = probeAlu(ivec2(gl_FragCoord.xy));
}
