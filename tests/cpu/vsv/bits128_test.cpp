// 128-bit voxel column helpers: the fast bit selection and interpolation agree with the plain ones.
#include <gtest/gtest.h>

#include <random>

#include "techniques/vsv/bits128.h"

namespace viz::vsv {
namespace {

Bits128 randomBits(std::mt19937& rng) {
    Bits128 b;
    for (auto& w : b.w) w = uint32_t(rng());
    return b;
}

TEST(Bits128, SetBitTouchesExactlyThatBitForAll128Positions) {
    for (int k = 0; k < 128; ++k) {
        Bits128 b;
        setBit(b, k);
        for (int j = 0; j < 128; ++j) {
            EXPECT_EQ(testBitPlain(b, j), j == k) << k << " " << j;
            EXPECT_EQ(testBitFast(b, j), j == k) << k << " " << j;
        }
        EXPECT_EQ(countBits(b, 0, 128), 1);
    }
}

TEST(Bits128, FastSelectionEqualsPlainForAllPositionsIncludingBit127) {
    std::mt19937 rng(7);
    for (int trial = 0; trial < 200; ++trial) {
        const Bits128 b = randomBits(rng);
        for (int k = 0; k < 128; ++k) ASSERT_EQ(testBitFast(b, k), testBitPlain(b, k)) << k;
    }
    Bits128 top;
    top.w[3] = 0x80000000u;
    EXPECT_TRUE(testBitFast(top, 127));
    EXPECT_TRUE(testBitPlain(top, 127));
    EXPECT_FALSE(testBitFast(top, 126));
}

TEST(Bits128, CountBitsMatchesAPerBitCount) {
    std::mt19937 rng(11);
    for (int trial = 0; trial < 50; ++trial) {
        const Bits128 b = randomBits(rng);
        for (int first = 0; first <= 128; first += 7)
            for (int last = first; last <= 128; last += 5) {
                int n = 0;
                for (int k = first; k < last; ++k) n += testBitPlain(b, k) ? 1 : 0;
                ASSERT_EQ(countBits(b, first, last), n) << first << " " << last;
            }
    }
    EXPECT_EQ(countBits(Bits128{{~0u, ~0u, ~0u, ~0u}}, 0, 128), 128);
}

TEST(Bits128, FastInterpolationEqualsPlainForAllPositions) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int trial = 0; trial < 100; ++trial) {
        const Bits128 a = randomBits(rng), b = randomBits(rng);
        for (int k = 0; k < 128; ++k) {
            const float wt = unit(rng), wp = unit(rng);
            ASSERT_NEAR(litFractionFast(a, b, k, wt, wp), litFractionPlain(a, b, k, wt, wp), 1e-6f) << k;
        }
    }
    // Corners select single voxels: weight 1 on (c1, bit k + 1) reads exactly that bit.
    Bits128 c0, c1;
    setBit(c1, 100);
    EXPECT_FLOAT_EQ(litFractionFast(c0, c1, 99, 1.0f, 1.0f), 0.0f);
    EXPECT_FLOAT_EQ(litFractionFast(c0, c1, 99, 0.0f, 1.0f), 1.0f);
    EXPECT_FLOAT_EQ(litFractionFast(c0, c1, 100, 0.5f, 0.0f), 0.5f);
}

}  // namespace
}  // namespace viz::vsv
