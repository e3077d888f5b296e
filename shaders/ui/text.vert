#version 450 core
// UI batch: solid rectangles and glyph quads in one draw call. Input positions are window pixels
// (origin top-left, y down); output is clip space. uv samples the glyph atlas (v = 0 its top row).
layout(location = 0) in vec2 aPosition;
layout(location = 1) in vec2 aUv;
layout(location = 2) in vec4 aColour;

uniform vec2 uViewport;  // framebuffer size in pixels

out vec2 vUv;
out vec4 vColour;

void main() {
    vec2 ndc = aPosition / uViewport * 2.0 - 1.0;
    gl_Position = vec4(ndc.x, -ndc.y, 0.0, 1.0);
    vUv = aUv;
    vColour = aColour;
}
