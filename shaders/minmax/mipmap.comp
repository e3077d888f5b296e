#version 450 core
// minmax/mipmap.comp: one pass of the 1D min-max mipmap (Chen et al. 2011, section 3.3) for every row at
// once. Row i of uTree holds the tree of slice i in Ahnentafel order (node 1 the root, node k's children
// 2k and 2k + 1, leaves n .. 2n - 1; texel x = node, .r = min, .g = max). uLevel < 0 copies the rectified
// row into the leaves; uLevel = l builds the 2^l nodes of level l from level l + 1. Levels are disjoint
// ranges of one texture, so the passes read what the previous pass wrote (barrier between passes)
// instead of ping-ponging two textures. Mirrored by minmax::buildTree (minmax_tree.h).
layout(local_size_x = 64, local_size_y = 1) in;

layout(r32f, binding = 0) uniform readonly image2D uRectified;
layout(rg32f, binding = 1) uniform image2D uTree;
uniform int uLevel;
uniform int uLeaves;
uniform int uSlices;

void main() {
    int j = int(gl_GlobalInvocationID.x);
    int row = int(gl_GlobalInvocationID.y);
    if (row >= uSlices) return;
    if (uLevel < 0) {
        if (j >= uLeaves) return;
        float s = imageLoad(uRectified, ivec2(j, row)).r;
        imageStore(uTree, ivec2(uLeaves + j, row), vec4(s, s, 0.0, 0.0));
        return;
    }
    int count = 1 << uLevel;
    if (j >= count) return;
    int node = count + j;
    vec2 a = imageLoad(uTree, ivec2(2 * node, row)).rg;
    vec2 b = imageLoad(uTree, ivec2(2 * node + 1, row)).rg;
    imageStore(uTree, ivec2(node, row), vec4(min(a.x, b.x), max(a.y, b.y), 0.0, 0.0));
}
