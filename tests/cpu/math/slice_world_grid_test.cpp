// slices' plane_grid=world (slice_geometry.h, worldGridRange), checked against what it promises in world
// terms: slab boundaries on multiples of the spacing in world depth, the fitted range covered, the count
// and spacing bounds, the nearest slab's part in front of the eye measured by brute force, and boundaries
// that stay put in the world when the eye moves along its forward axis.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "techniques/slices/slice_geometry.h"

namespace {

viz::PlaneRange fittedRange(double near, double far, int planes) {
    viz::PlaneRange r;
    r.empty = false;
    r.near = near;
    r.far = far;
    r.planes = planes;
    r.spacing = (far - near) / planes;
    return r;
}

// Distance of x from the nearest integer.
double offInteger(double x) { return std::abs(x - std::round(x)); }

TEST(SliceWorldGrid, SlabsSitOnAWorldGridAndCoverTheFittedRange) {
    std::mt19937 random(5u);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 2000; ++trial) {
        const int n = 1 + int(unit(random) * 300.0);
        const double near = unit(random) < 0.3 ? 0.0 : unit(random) * 20.0;
        const double far = near + 0.01 + unit(random) * 50.0;
        const double eyeDepth = (unit(random) - 0.5) * std::pow(10.0, unit(random) * 6.0);
        const viz::PlaneRange fitted = fittedRange(near, far, n);
        const viz::PlaneRange r = viz::worldGridRange(fitted, eyeDepth);
        SCOPED_TRACE(trial);
        ASSERT_FALSE(r.empty);
        // Spacing: the fitted one rounded up to a power of 2^(1/4).
        EXPECT_GE(r.spacing, fitted.spacing * (1.0 - 1e-12));
        EXPECT_LT(r.spacing, fitted.spacing * std::pow(2.0, 0.25) * (1.0 + 1e-12));
        EXPECT_LT(offInteger(4.0 * std::log2(r.spacing)), 1e-9);
        // Boundaries on the world grid, the fitted range inside, whole slabs.
        const double tolerance = 1e-9 * (std::abs(eyeDepth) + far) / r.spacing;
        EXPECT_LT(offInteger((r.near + eyeDepth) / r.spacing), tolerance);
        EXPECT_LT(offInteger((r.far + eyeDepth) / r.spacing), tolerance);
        EXPECT_LE(r.near, near + 1e-9 * (std::abs(eyeDepth) + far));
        EXPECT_GE(r.far, far - 1e-9 * (std::abs(eyeDepth) + far));
        EXPECT_NEAR(r.far - r.near, r.planes * r.spacing, 1e-6 * r.spacing + 1e-9 * std::abs(eyeDepth));
        EXPECT_LE(r.planes, n + 2);
        EXPECT_GE(r.planes, 1);
        // The nearest slab [near, near + spacing]: the part at depth >= 0, by sampling it.
        int inFront = 0;
        constexpr int kSamples = 100000;
        for (int k = 0; k < kSamples; ++k)
            if (r.near + (k + 0.5) / kSamples * r.spacing >= 0.0) ++inFront;
        EXPECT_NEAR(r.nearestWeight, double(inFront) / kSamples, 2.0 / kSamples);
    }
}

TEST(SliceWorldGrid, BoundariesStayPutWhenTheEyeOrTheLightVolumeMoves) {
    // A light volume at world depths [worldNear, worldFar]; the eye at world depth e sees it at
    // [worldNear - e, worldFar - e] (clamped at 0 in front of the eye, as planeRange does). N = 64 over a
    // depth of 9 is a spacing of 0.1406, rounded up to 2^-2.75 = 0.1487.
    const int n = 64;
    auto boundaries = [&](double worldNear, double worldFar, double e, bool world) {
        const viz::PlaneRange fitted = fittedRange(std::max(worldNear - e, 0.0), worldFar - e, n);
        const viz::PlaneRange r = world ? viz::worldGridRange(fitted, e) : fitted;
        std::vector<double> out;  // world depths
        for (int k = 0; k <= r.planes; ++k) out.push_back(r.near + k * r.spacing + e);
        return std::make_pair(r.spacing, out);
    };
    // Whether every boundary of b is (to 1e-9) a boundary of a.
    auto within = [](const std::vector<double>& a, const std::vector<double>& b) {
        for (double x : b)
            if (std::none_of(a.begin(), a.end(), [&](double y) { return std::abs(x - y) < 1e-9; })) return false;
        return true;
    };
    const auto [spacing, first] = boundaries(3.0, 12.0, 0.0, true);
    EXPECT_NEAR(spacing, std::exp2(-2.75), 1e-12);
    for (double e : {0.013, 0.25, 1.0, 2.9}) {  // the eye moves along its axis
        const auto [s, b] = boundaries(3.0, 12.0, e, true);
        EXPECT_EQ(s, spacing) << e;
        EXPECT_TRUE(within(first, b)) << e;
    }
    for (double far : {12.1, 12.3, 12.5}) {  // the light volume grows (the light moved)
        const auto [s, b] = boundaries(3.0, far, 0.0, true);
        EXPECT_EQ(s, spacing) << far;
        // The same grid, extended by the slabs that cover the longer range.
        EXPECT_EQ(b.front(), first.front()) << far;
        for (double x : b) EXPECT_LT(offInteger((x - first.front()) / spacing), 1e-9) << far;
        EXPECT_GT(b.size(), first.size()) << far;
        // The fitted planes, by contrast, respace over the new depth range.
        EXPECT_FALSE(within(boundaries(3.0, 12.0, 0.0, false).second, boundaries(3.0, far, 0.0, false).second)) << far;
    }
}

}  // namespace
