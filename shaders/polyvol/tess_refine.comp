#version 450 core
// polyvol/tess_refine.comp: one refinement step from the coarse grid (Billeter et al. section 4.1, with
// compute shaders and indirect dispatch instead of geometry shaders and transform feedback). Each
// invocation takes one quad of level k: split quads put their four children in the next list; leaves
// put their triangles in the key list. A leaf whose edge neighbour (same level) is split gets that edge's
// midpoint: with the 4 edges that is 16 patterns; the polygon of corners and midpoints (CCW in texel
// space, i.e. seen from the light, like the static grid) is fanned from its first midpoint, 2 + m <= 6
// triangles, or split along the (0,0)-(1,1) diagonal as in the static grid when m = 0. Keys:
// light_volume_mesh.h with a key stride of N + 1 (a cube's face f starts at f (N + 1)^2).
// Two passes over the same quads, with tess_scan.comp between them, so that the lists come out in the
// input's order whatever order the GPU runs the work groups in (the volume pass adds the triangles up in
// list order, and float sums depend on it): uPass = 0 writes each work group's totals (children,
// triangles) to uGroups; tess_scan.comp turns them into the groups' offsets; uPass = 1 writes each quad's
// children and triangles at its group's offset plus the sum of those before it in the group.
layout(local_size_x = 64) in;

uniform int uLevel;
uniform int uMapSize;
uniform int uFromGrid;     // 1: the input is every quad of level uLevel (the coarse grid)
uniform int uStopLevel;    // stepping: quads of this level are leaves even if flagged
uniform uint uListCapacity;
uniform uint uKeyCapacity;
uniform int uWriteLevels;
uniform uint uKeyBase;     // the face's first key: face (N + 1)^2
uniform int uPass;         // 0: the work groups' totals; 1: the lists (above)
layout(binding = 11) uniform usampler2D uFlags;  // texture unit 11 (units below 10 are the scene's)
layout(r8, binding = 1) uniform writeonly image2D uLevels;  // leaf level per finest quad, / 16 (the face's layer)

layout(std430, binding = 4) buffer Counters {
    uint inCount;
    uint outCount;
    uint triangles;
    uint overflow;
    uint dispatchArgs[3];
    uint drawArgs[4];
};
layout(std430, binding = 5) readonly buffer InQuads { uint inQuads[]; };
layout(std430, binding = 6) writeonly buffer OutQuads { uint outQuads[]; };
layout(std430, binding = 7) writeonly buffer Keys { uint keys[]; };
// Per work group: pass 0 writes (children, triangles); pass 1 reads (first child slot, first triangle).
layout(std430, binding = 8) buffer Groups { uvec2 groups[]; };

shared uvec2 sCounts[64];  // per invocation, then its inclusive prefix sum over the group

// Whether quad q of `level` is split in this run: flagged, and above the stepping stop (a quad at or
// below uStopLevel stays a leaf, so its neighbours must not add midpoints on their shared edge). The
// ring on the grid border is refined to the finest level whatever the stop: the closure to the light
// (or the cap) meets the grid at every border texel, and a coarser border would leave T-junctions.
bool isSplit(ivec2 q, int level) {
    int quads = uMapSize >> level;
    if (level == 0 || any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, ivec2(quads)))) return false;
    bool border = q.x == 0 || q.y == 0 || q.x == quads - 1 || q.y == quads - 1;
    if (level <= uStopLevel && !border) return false;
    return (texelFetch(uFlags, q, level).r & 2u) != 0u;
}

uint vertexKey(ivec2 v) { return uKeyBase + uint(v.y) * uint(uMapSize + 1) + uint(v.x); }

void main() {
    // No early return: every invocation reaches the group's barriers.
    uint index = gl_GlobalInvocationID.x;
    uint local = gl_LocalInvocationIndex;
    int quads = uMapSize >> uLevel;
    ivec2 q = ivec2(0);
    bool valid;
    if (uFromGrid != 0) {
        valid = index < uint(quads * quads);
        if (valid) q = ivec2(int(index) % quads, int(index) / quads);
    } else {
        valid = index < inCount;
        if (valid) {
            uint code = inQuads[index];
            q = ivec2(code & 0xFFFFu, code >> 16);
        }
    }
    bool split = valid && isSplit(q, uLevel);
    bool leaf = valid && !split;

    // Leaf: polygon corners and midpoints, counter-clockwise in texel space.
    int s = 1 << uLevel;
    int h = s >> 1;
    ivec2 o = q * s;
    uint poly[8];
    int n = 0;
    int firstMid = -1;
    if (leaf) {
        bool mid[4] = bool[4](isSplit(q + ivec2(0, -1), uLevel), isSplit(q + ivec2(1, 0), uLevel),
                              isSplit(q + ivec2(0, 1), uLevel), isSplit(q + ivec2(-1, 0), uLevel));
        const ivec2 kCorner[4] = ivec2[4](ivec2(0, 0), ivec2(1, 0), ivec2(1, 1), ivec2(0, 1));
        for (int e = 0; e < 4; ++e) {
            poly[n++] = vertexKey(o + kCorner[e] * s);
            if (mid[e]) {
                if (firstMid < 0) firstMid = n;
                poly[n++] = vertexKey(o + (kCorner[e] + kCorner[(e + 1) & 3]) * h);
            }
        }
    }
    uvec2 mine = uvec2(split ? 4u : 0u, leaf ? uint(n - 2) : 0u);

    // Inclusive prefix sum over the group (Hillis-Steele, log2 64 steps in shared memory).
    sCounts[local] = mine;
    barrier();
    for (uint step = 1u; step < 64u; step <<= 1u) {
        uvec2 before = local >= step ? sCounts[local - step] : uvec2(0u);
        barrier();
        sCounts[local] += before;
        barrier();
    }
    if (uPass == 0) {
        if (local == 63u) groups[gl_WorkGroupID.x] = sCounts[63];
        return;
    }
    uvec2 at = groups[gl_WorkGroupID.x] + sCounts[local] - mine;  // first child slot, first triangle

    if (split) {
        if (at.x + 4u > uListCapacity) {
            atomicAdd(overflow, 1u);
            return;
        }
        for (uint c = 0u; c < 4u; ++c) {
            ivec2 child = 2 * q + ivec2(c & 1u, c >> 1u);
            outQuads[at.x + c] = uint(child.x) | (uint(child.y) << 16);
        }
        return;
    }
    if (!leaf) return;
    uint count = mine.y;
    if ((at.y + count) * 3u > uKeyCapacity) {
        atomicAdd(overflow, 1u);
        return;
    }
    uint k = at.y * 3u;
    if (firstMid < 0) {
        keys[k + 0u] = poly[0]; keys[k + 1u] = poly[1]; keys[k + 2u] = poly[2];
        keys[k + 3u] = poly[0]; keys[k + 4u] = poly[2]; keys[k + 5u] = poly[3];
    } else {
        for (int t = 0; t < n - 2; ++t) {
            keys[k++] = poly[firstMid];
            keys[k++] = poly[(firstMid + 1 + t) % n];
            keys[k++] = poly[(firstMid + 2 + t) % n];
        }
    }
    if (uWriteLevels != 0) {
        for (int y = 0; y < s; ++y)
            for (int x = 0; x < s; ++x) {
                ivec2 t = o + ivec2(x, y);
                if (all(lessThan(t, ivec2(uMapSize)))) imageStore(uLevels, t, vec4(float(uLevel) / 16.0));
            }
    }
}
