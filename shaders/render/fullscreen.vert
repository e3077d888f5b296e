#version 450 core
// One triangle covering the viewport, from gl_VertexID alone (no vertex buffer). vUv in [0,1]^2 over the
// viewport, GL convention (v = 0 at the bottom row).
out vec2 vUv;

void main() {
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    vUv = p;
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
