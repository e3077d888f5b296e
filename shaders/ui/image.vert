#version 450 core
// One pane of the GUI: a quad covering uRect (framebuffer pixels, origin top-left, y down), drawn as a
// 4-vertex triangle strip from gl_VertexID. vPane is the pane coordinate, (0,0) top-left, (1,1)
// bottom-right.
uniform vec4 uRect;      // x0, y0, x1, y1
uniform vec2 uViewport;  // framebuffer size in pixels

out vec2 vPane;

void main() {
    vec2 corner = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1));
    vec2 p = mix(uRect.xy, uRect.zw, corner);
    vec2 ndc = p / uViewport * 2.0 - 1.0;
    gl_Position = vec4(ndc.x, -ndc.y, 0.0, 1.0);
    vPane = corner;
}
