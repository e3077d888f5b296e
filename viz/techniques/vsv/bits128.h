// 128-bit voxel columns: one RGBA32UI texel of the epipolar grid holds 128 binary voxels along phi,
// bit k of the column = bit (k & 31) of component k >> 5 (x = bits 0..31, y = 32..63, z = 64..95,
// w = 96..127). Pure CPU mirror of shaders/vsv/bits128.glsl; both are checked against each other.
// Two ways to read one bit: the plain one indexes the component directly; the fast one picks the
// component with two selects (first the pair zw or xy by bit 6, then one of the pair by bit 5), which
// avoids dynamic indexing of a vector on GPUs (Wyman and Dai 2013, appendix A).
#pragma once

#include <array>
#include <bit>
#include <cstdint>

namespace viz::vsv {

struct Bits128 {
    std::array<uint32_t, 4> w{0u, 0u, 0u, 0u};
    bool operator==(const Bits128&) const = default;
};

inline void setBit(Bits128& b, int k) { b.w[std::size_t(k >> 5)] |= 1u << (k & 31); }

// Plain: index the component.
inline bool testBitPlain(const Bits128& b, int k) { return (b.w[std::size_t(k >> 5)] >> (k & 31) & 1u) != 0u; }

// Fast: two selects instead of an indexed read; the same expression as the GLSL mirror.
inline bool testBitFast(const Bits128& b, int k) {
    const uint32_t comp = uint32_t(k) >> 5;
    const uint32_t mask = 1u << (uint32_t(k) & 31u);
    const uint32_t lo = (comp & 2u) != 0u ? b.w[2] : b.w[0];
    const uint32_t hi = (comp & 2u) != 0u ? b.w[3] : b.w[1];
    const uint32_t word = (comp & 1u) != 0u ? hi : lo;
    return (word & mask) != 0u;
}

inline Bits128 bitOr(const Bits128& a, const Bits128& b) {
    return {{a.w[0] | b.w[0], a.w[1] | b.w[1], a.w[2] | b.w[2], a.w[3] | b.w[3]}};
}

// Bits [0, k) set, 0 <= k <= 128.
inline Bits128 lowMask(int k) {
    Bits128 m;
    for (int c = 0; c < 4; ++c) {
        const int n = k - 32 * c;
        m.w[std::size_t(c)] = n >= 32 ? 0xffffffffu : n <= 0 ? 0u : (1u << n) - 1u;
    }
    return m;
}

// Number of set bits in [first, last), 0 <= first <= last <= 128.
inline int countBits(const Bits128& b, int first, int last) {
    int n = 0;
    for (int c = 0; c < 4; ++c) {
        const uint32_t m = lowMask(last).w[std::size_t(c)] & ~lowMask(first).w[std::size_t(c)];
        n += std::popcount(b.w[std::size_t(c)] & m);
    }
    return n;
}

// Interpolated shadow of four voxels (Wyman and Dai 2013, listing 2): bits k and k + 1 of two columns
// c0, c1 adjacent along theta, weights wTheta (toward c1) and wPhi (toward bit k + 1); returns the
// weighted fraction of *lit* (clear) voxels. Plain version: bilinear weights, direct reads.
// k in [0, 127]; bit k + 1 = 128 is clamped to 127.
inline float litFractionPlain(const Bits128& c0, const Bits128& c1, int k, float wTheta, float wPhi) {
    const int k1 = k + 1 > 127 ? 127 : k + 1;
    const float lit00 = testBitPlain(c0, k) ? 0.0f : 1.0f;
    const float lit10 = testBitPlain(c1, k) ? 0.0f : 1.0f;
    const float lit01 = testBitPlain(c0, k1) ? 0.0f : 1.0f;
    const float lit11 = testBitPlain(c1, k1) ? 0.0f : 1.0f;
    return (1.0f - wTheta) * (1.0f - wPhi) * lit00 + wTheta * (1.0f - wPhi) * lit10 +
           (1.0f - wTheta) * wPhi * lit01 + wTheta * wPhi * lit11;
}

// Fast version: the four weights written with one product (wTheta * wPhi), the two components per
// column picked by selects, and the sum of weights of clear bits taken at once (a dot product in GLSL).
inline float litFractionFast(const Bits128& c0, const Bits128& c1, int k, float wTheta, float wPhi) {
    const int k1 = k + 1 > 127 ? 127 : k + 1;
    const float wBoth = wTheta * wPhi;
    const std::array<float, 4> weight{1.0f - wPhi - (wTheta - wBoth), wTheta - wBoth, wPhi - wBoth, wBoth};
    auto pick = [](const Bits128& a, const Bits128& b, int bit, uint32_t& va, uint32_t& vb) {
        const uint32_t comp = uint32_t(bit) >> 5;
        const uint32_t mask = 1u << (uint32_t(bit) & 31u);
        // (a.lo, a.hi, b.lo, b.hi) of the selected pair, then one of each pair.
        const bool upper = (comp & 2u) != 0u;
        const uint32_t a0 = upper ? a.w[2] : a.w[0], a1 = upper ? a.w[3] : a.w[1];
        const uint32_t b0 = upper ? b.w[2] : b.w[0], b1 = upper ? b.w[3] : b.w[1];
        va = ((comp & 1u) != 0u ? a1 : a0) & mask;
        vb = ((comp & 1u) != 0u ? b1 : b0) & mask;
    };
    std::array<uint32_t, 4> v{};
    pick(c0, c1, k, v[0], v[1]);
    pick(c0, c1, k1, v[2], v[3]);
    float sum = 0.0f;
    for (std::size_t i = 0; i < 4; ++i) sum += v[i] != 0u ? 0.0f : weight[i];
    return sum;
}

}  // namespace viz::vsv
