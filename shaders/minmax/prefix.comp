#version 450 core
// minmax/prefix.comp: prefix sums of Gamma_i(gamma) T(alpha, gamma) per slice (Chen et al. 2011, sections
// 3.2 and 3.4; `integrand=svd`). T is the light's angular emission along light ray (alpha, gamma): colour
// * intensity * A_spot * cookie for a spot (A_spot varies with alpha too, so every slice needs its own
// table), colour * intensity for a directional light (one row shared by all slices: uSharedRow).
// Table row i, texel k (k = 0 .. uTexels) holds sum over texels j < k of Gamma_i(gamma_j) T(alpha_i, gamma_j)
// dgamma at the texel centres gamma_j = gammaLo + (j + 1/2) dgamma, dgamma = (gammaHi - gammaLo) / uTexels
// (uTexels: the table's own resolution, lower than the shadow map's). The 3 N floats of texel k (rank i,
// channel c at q = 3 i + c) are spread over layers q / 4, component q % 4 of an RGBA32F array; the traversal
// reads them with hardware linear filtering along gamma. Two ways to scan a row (prefix_sums):
// sequential: one invocation scans one row, uTexels iterations in order. LOG2_PASSES (the paper's log2
// passes, in one dispatch): one work group of kScanWidth invocations per row; each invocation sums its
// chunk of consecutive texels, the chunk totals are scanned in log2(kScanWidth) Hillis-Steele passes in
// shared memory, and each invocation writes its chunk's prefixes from its chunk's offset (the texel terms
// evaluated a second time rather than held: 3 N floats per texel). Point lights (EPIPOLAR_POINT): T is the constant
// colour * intensity, but every row covers its own gamma range [0, gRowGammaHi[row]] (selectRow), so each
// row has its own table; Gamma_i is still sampled over the SVD's range [uGammaLo, uGammaHi] = [0, pi].
#ifdef LOG2_PASSES
const int kScanWidth = 32;  // a GPU subgroup; on llvmpipe 8, 32 and 128 were all slower than sequential
layout(local_size_x = kScanWidth, local_size_y = 1) in;
#else
layout(local_size_x = 64, local_size_y = 1) in;
#endif

#include "common/host_device.glsl"
#include "common/lights.glsl"
#include "minmax/epipolar.glsl"

layout(rgba32f, binding = 0) uniform writeonly image2DArray uPrefix;
uniform int uLight;
uniform int uRows;
uniform int uTexels;
// The rank: a compile-time constant (MINMAX_RANK, from the run's settings), so that the loops over it unroll
// and the per-rank sums stay in registers instead of a dynamically indexed array.
const int kRank = MINMAX_RANK;
uniform bool uSharedRow;
// Gamma_i at 64 gamma samples (inclusive ends), rank-major, four to a vec4: a float array of 512 takes 512
// vec4 slots of NVIDIA's default uniform block and fails to link there.
uniform vec4 uGammaBasis[8 * 16];
float gammaBasisAt(int j) { return uGammaBasis[j >> 2][j & 3]; }

float gammaBasis(int i, float gamma) {
    float x = clamp((gamma - uGammaLo) / (uGammaHi - uGammaLo), 0.0, 1.0) * 63.0;
    int k = min(int(floor(x)), 62);
    float f = x - float(k);
    return mix(gammaBasisAt(i * 64 + k), gammaBasisAt(i * 64 + k + 1), f);
}

// Adds texel k's term Gamma_i(gamma_k) T(alpha, gamma_k) dgamma (rank i, channel c at 3 i + c) to sums.
void addTexelTerm(GpuLight L, float alpha, int k, inout float sums[24]) {
    float step = (MINMAX_GAMMA_HI - MINMAX_GAMMA_LO) / float(uTexels);
    float gamma = MINMAX_GAMMA_LO + (float(k) + 0.5) * step;
    vec3 T = L.radiant.rgb;
    if (!uSharedRow) {
        vec3 p = lightRayPoint(alpha, gamma);
        T = lightIntensity(L, p);
    }
    for (int i = 0; i < kRank; ++i) {
        float w = gammaBasis(i, gamma) * step;
        sums[3 * i] += w * T.r;
        sums[3 * i + 1] += w * T.g;
        sums[3 * i + 2] += w * T.b;
    }
}

void storePrefix(int k, int row, float sums[24]) {
    int layers = (3 * kRank + 3) / 4;
    for (int layer = 0; layer < layers; ++layer) {
        vec4 v = vec4(sums[4 * layer], sums[4 * layer + 1], sums[4 * layer + 2], sums[4 * layer + 3]);
        imageStore(uPrefix, ivec3(k, row, layer), v);
    }
}

#ifdef LOG2_PASSES
shared float sTotals[kScanWidth * 24];

void main() {
    int row = int(gl_WorkGroupID.x);  // one work group per row: the whole group returns together
    if (row >= uRows) return;
    int lane = int(gl_LocalInvocationID.x);
    GpuLight L = gLights[uLight];
    selectRow(row);
    float alpha = sliceAlpha(row);
    int channels = 3 * kRank;
    // Texels [first, last) are this invocation's chunk.
    int chunk = (uTexels + kScanWidth - 1) / kScanWidth;
    int first = min(lane * chunk, uTexels), last = min(first + chunk, uTexels);
    float sums[24];
    for (int q = 0; q < 24; ++q) sums[q] = 0.0;
    for (int k = first; k < last; ++k) addTexelTerm(L, alpha, k, sums);
    for (int q = 0; q < channels; ++q) sTotals[lane * 24 + q] = sums[q];
    barrier();
    // Inclusive scan of the chunk totals: after the pass with offset o, lane j holds the sum of lanes
    // j - 2o + 1 .. j.
    for (int offset = 1; offset < kScanWidth; offset *= 2) {
        float add[24];
        for (int q = 0; q < channels; ++q) add[q] = lane >= offset ? sTotals[(lane - offset) * 24 + q] : 0.0;
        barrier();
        for (int q = 0; q < channels; ++q) sTotals[lane * 24 + q] += add[q];
        barrier();
    }
    // The chunk's offset: the sum of the chunks before it (exclusive).
    for (int q = 0; q < 24; ++q) sums[q] = lane > 0 && q < channels ? sTotals[(lane - 1) * 24 + q] : 0.0;
    for (int k = first; k < last; ++k) {
        storePrefix(k, row, sums);
        addTexelTerm(L, alpha, k, sums);
    }
    if (last == uTexels && first < last) storePrefix(uTexels, row, sums);  // the row's total
}
#else
void main() {
    int row = int(gl_GlobalInvocationID.x);
    if (row >= uRows) return;
    GpuLight L = gLights[uLight];
    selectRow(row);
    float alpha = sliceAlpha(row);
    float sums[24];
    for (int q = 0; q < 24; ++q) sums[q] = 0.0;
    for (int k = 0; k <= uTexels; ++k) {
        storePrefix(k, row, sums);
        if (k == uTexels) break;
        addTexelTerm(L, alpha, k, sums);
    }
}
#endif
