// The power-law fit of `airlight bench` (cost ~ work^k), checked against series built from known laws.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "report/bench_table.h"

namespace {

using viz::report::fitPowerLaw;

// work 1e3 .. 1e6 in 8 steps; cost = c * work^k times a multiplicative noise of up to +-noise.
std::vector<double> costs(const std::vector<double>& work, double c, double k, double noise, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> jitter(1.0 - noise, 1.0 + noise);
    std::vector<double> ms;
    for (double w : work) ms.push_back(c * std::pow(w, k) * jitter(rng));
    return ms;
}

std::vector<double> workRange() {
    std::vector<double> work;
    for (int i = 0; i < 8; ++i) work.push_back(1e3 * std::pow(10.0, i * 3.0 / 7.0));
    return work;
}

}  // namespace

TEST(BenchFit, ASyntheticLinearCostHasExponentOne) {
    const std::vector<double> work = workRange();
    for (unsigned seed = 1; seed <= 20; ++seed) {
        const auto fit = fitPowerLaw(work, costs(work, 2e-4, 1.0, 0.1, seed));
        EXPECT_NEAR(fit.exponent, 1.0, 0.05) << "seed " << seed;
        EXPECT_GT(fit.r2, 0.99);
        EXPECT_EQ(fit.points, 8);
    }
    // Without noise the line is exact: the coefficient is the cost at work 1.
    const auto exact = fitPowerLaw(work, costs(work, 2e-4, 1.0, 0.0, 1));
    EXPECT_NEAR(exact.exponent, 1.0, 1e-12);
    EXPECT_NEAR(exact.coefficient, 2e-4, 2e-4 * 1e-10);
    EXPECT_NEAR(exact.r2, 1.0, 1e-12);
}

TEST(BenchFit, QuadraticSquareRootAndConstantCostsGiveTheirExponents) {
    const std::vector<double> work = workRange();
    EXPECT_NEAR(fitPowerLaw(work, costs(work, 1e-9, 2.0, 0.05, 3)).exponent, 2.0, 0.05);
    EXPECT_NEAR(fitPowerLaw(work, costs(work, 0.5, 0.5, 0.05, 4)).exponent, 0.5, 0.05);
    EXPECT_NEAR(fitPowerLaw(work, std::vector<double>(work.size(), 7.0)).exponent, 0.0, 1e-12);
    // A fixed cost plus a linear one: the exponent lies between 0 and 1 (fixed costs dominate the small end).
    std::vector<double> affine;
    for (double w : work) affine.push_back(5.0 + 1e-5 * w);
    const double k = fitPowerLaw(work, affine).exponent;
    EXPECT_GT(k, 0.0);
    EXPECT_LT(k, 1.0);
}

TEST(BenchFit, PointsThatCannotBeFittedAreLeftOutAndTooFewGiveNaN) {
    // Zero, negative and non-finite points are left out; what is left is exactly linear.
    const std::vector<double> work = {0.0, 10.0, 100.0, -5.0, 1000.0, 1e4};
    const std::vector<double> ms = {1.0, 1.0, 10.0, 3.0, NAN, 1000.0};
    const auto fit = fitPowerLaw(work, ms);
    EXPECT_EQ(fit.points, 3);
    EXPECT_NEAR(fit.exponent, 1.0, 1e-12);
    // One distinct work value: no slope.
    EXPECT_TRUE(std::isnan(fitPowerLaw({100.0, 100.0}, {1.0, 2.0}).exponent));
    EXPECT_TRUE(std::isnan(fitPowerLaw({}, {}).exponent));
}

TEST(BenchFit, EverySeriesIsFittedOnItsOwn) {
    std::vector<viz::report::BenchRow> rows;
    for (double w : {1e3, 1e4, 1e5}) {
        rows.push_back({"grate", "raymarch", "size", "", w, "march", 1e-3 * w, "c", "r", 1, 0.0});
        rows.push_back({"grate", "raymarch", "size", "", w, "compose", 2.0, "c", "r", 1, 0.0});
        rows.push_back({"grate", "slices", "size", "", w, "march", 1e-9 * w * w, "c", "r", 1, 0.0});
    }
    const auto fits = viz::report::fitSeries(rows);
    ASSERT_EQ(fits.size(), 3u);
    EXPECT_EQ(fits[0].stage, "march");
    EXPECT_NEAR(fits[0].fit.exponent, 1.0, 1e-12);
    EXPECT_EQ(fits[1].stage, "compose");
    EXPECT_NEAR(fits[1].fit.exponent, 0.0, 1e-12);
    EXPECT_EQ(fits[2].technique, "slices");
    EXPECT_NEAR(fits[2].fit.exponent, 2.0, 1e-12);
}
