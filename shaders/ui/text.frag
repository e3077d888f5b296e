#version 450 core
// Coverage from the single-channel glyph atlas times the vertex colour; solid rectangles sample an
// opaque texel of the same atlas. Output is premultiplied-free straight alpha (blend SRC_ALPHA).
layout(binding = 0) uniform sampler2D uAtlas;

in vec2 vUv;
in vec4 vColour;
out vec4 fragColour;

void main() {
    float coverage = texture(uAtlas, vUv).r;
    fragColour = vec4(vColour.rgb, vColour.a * coverage);
}
