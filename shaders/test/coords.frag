#version 450 core
// Writes the window coordinates of each fragment (pixel centre, GL's origin at the bottom left) and a
// uniform, so the test can check the row order of readback and that uniforms reach the shader.
uniform float uTag;
layout(location = 0) out vec4 outColour;
void main() { outColour = vec4(gl_FragCoord.xy, uTag, 1.0); }
