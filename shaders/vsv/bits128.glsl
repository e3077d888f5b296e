// 128-bit voxel columns in one uvec4 (bit k = bit k & 31 of component k >> 5); GLSL mirror of
// viz/techniques/vsv/bits128.h, see there for the layout and the plain/fast variants.
#ifndef VSV_BITS128_GLSL
#define VSV_BITS128_GLSL

bool testBitPlain(uvec4 b, int k) { return ((b[k >> 5] >> uint(k & 31)) & 1u) != 0u; }

// Two selects instead of an indexed component read (dynamic vector indexing compiles poorly).
bool testBitFast(uvec4 b, int k) {
    uint comp = uint(k) >> 5;
    uint mask = 1u << (uint(k) & 31u);
    uvec2 pair = (comp & 2u) != 0u ? b.zw : b.xy;
    uint word = (comp & 1u) != 0u ? pair.y : pair.x;
    return (word & mask) != 0u;
}

// Bits [0, k) set, 0 <= k <= 128.
uvec4 lowMask(int k) {
    ivec4 n = ivec4(k) - ivec4(0, 32, 64, 96);
    uvec4 m;
    for (int c = 0; c < 4; ++c) m[c] = n[c] >= 32 ? 0xffffffffu : (n[c] <= 0 ? 0u : (1u << uint(n[c])) - 1u);
    return m;
}

// Set bits in [first, last).
int countBits(uvec4 b, int first, int last) {
    uvec4 m = lowMask(last) & ~lowMask(first);
    ivec4 c = bitCount(b & m);
    return c.x + c.y + c.z + c.w;
}

float litFractionPlain(uvec4 c0, uvec4 c1, int k, float wTheta, float wPhi) {
    int k1 = min(k + 1, 127);
    float lit00 = testBitPlain(c0, k) ? 0.0 : 1.0;
    float lit10 = testBitPlain(c1, k) ? 0.0 : 1.0;
    float lit01 = testBitPlain(c0, k1) ? 0.0 : 1.0;
    float lit11 = testBitPlain(c1, k1) ? 0.0 : 1.0;
    return (1.0 - wTheta) * (1.0 - wPhi) * lit00 + wTheta * (1.0 - wPhi) * lit10 +
           (1.0 - wTheta) * wPhi * lit01 + wTheta * wPhi * lit11;
}

// Weighted fraction of clear voxels among bits k, k + 1 of two theta-neighbour columns: the pairs are
// selected for both columns at once, the clear ones keep their weight (mix), one dot sums them.
float litFractionFast(uvec4 c0, uvec4 c1, int k, float wTheta, float wPhi) {
    int k1 = min(k + 1, 127);
    float wBoth = wTheta * wPhi;
    vec4 weight = vec4(1.0 - wPhi - (wTheta - wBoth), wTheta - wBoth, wPhi - wBoth, wBoth);
    uint comp0 = uint(k) >> 5, comp1 = uint(k1) >> 5;
    uvec4 pair0 = (comp0 & 2u) != 0u ? uvec4(c0.zw, c1.zw) : uvec4(c0.xy, c1.xy);
    uvec4 pair1 = (comp1 & 2u) != 0u ? uvec4(c0.zw, c1.zw) : uvec4(c0.xy, c1.xy);
    uvec4 v;
    v.xy = ((comp0 & 1u) != 0u ? pair0.yw : pair0.xz) & uvec2(1u << (uint(k) & 31u));
    v.zw = ((comp1 & 1u) != 0u ? pair1.yw : pair1.xz) & uvec2(1u << (uint(k1) & 31u));
    return dot(mix(weight, vec4(0.0), notEqual(v, uvec4(0u))), vec4(1.0));
}

#endif  // VSV_BITS128_GLSL
