#version 450 core
// polyvol/tess_levels.comp: one level of the mip-like hierarchy of "needs subdivision" flags (Billeter et
// al. section 4.1). Level k holds one texel per quad of 2^k x 2^k texels of the virtual (N + 1)^2 vertex
// grid (quad q spans vertices [2^k q, 2^k (q + 1)], virtual index N clamped onto N - 1). Two bits:
//   bit 0 M: some vertex of the quad has a Laplacian above the threshold (level 0: its 4 corners; the
//            ring of quads on the grid border is always marked, so the border stays at the finest level
//            and meets the closure's per-texel edges without T-junctions);
//   bit 1 S: the quad is split: M (k >= 1), or a child is split, or a child of an edge neighbour that
//            touches the shared edge is split. The last rule keeps neighbouring leaves within one level,
//            so every leaf edge has at most one extra vertex (its midpoint).
layout(local_size_x = 8, local_size_y = 8) in;

uniform int uLevel;
uniform int uMapSize;
uniform float uThreshold;
uniform int uFace;                                   // the edge map's layer
layout(binding = 10) uniform sampler2DArray uEdges;  // level 0 only (texture unit 10)
layout(binding = 11) uniform usampler2D uFlags;      // level uLevel - 1 is read (unit 11)
layout(r8ui, binding = 0) uniform writeonly uimage2D uOut;  // level uLevel

uint childFlags(ivec2 c, ivec2 size) {
    if (any(lessThan(c, ivec2(0))) || any(greaterThanEqual(c, size))) return 0u;
    return texelFetch(uFlags, c, uLevel - 1).r;
}

void main() {
    int quads = uMapSize >> uLevel;
    ivec2 q = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(q, ivec2(quads)))) return;
    uint flags = 0u;
    if (uLevel == 0) {
        int last = uMapSize - 1;
        bool marked = q.x == 0 || q.y == 0 || q.x == last || q.y == last;
        for (int c = 0; c < 4 && !marked; ++c) {
            ivec2 v = min(q + ivec2(c & 1, c >> 1), ivec2(last));
            marked = texelFetch(uEdges, ivec3(v, uFace), 0).r > uThreshold;
        }
        flags = marked ? 1u : 0u;
    } else {
        ivec2 size = ivec2(quads * 2);
        ivec2 base = 2 * q;
        uint m = 0u, s = 0u;
        for (int c = 0; c < 4; ++c) {
            uint f = childFlags(base + ivec2(c & 1, c >> 1), size);
            m |= f & 1u;
            s |= f >> 1;
        }
        for (int b = 0; b < 2; ++b) {
            s |= childFlags(base + ivec2(-1, b), size) >> 1;  // left neighbour's right column
            s |= childFlags(base + ivec2(2, b), size) >> 1;   // right neighbour's left column
            s |= childFlags(base + ivec2(b, -1), size) >> 1;  // lower neighbour's top row
            s |= childFlags(base + ivec2(b, 2), size) >> 1;   // upper neighbour's bottom row
        }
        flags = m | ((m | s) << 1);
    }
    imageStore(uOut, q, uvec4(flags));
}
