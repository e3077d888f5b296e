// The numbers behind a view's display strip (app/view_stats.h): channel values, NaN/Inf/negative
// counts, min/max and percentile ranges, the log mapping, histograms and difference images.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

#include "view_stats.h"

namespace airlight {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

viz::Image rgba(std::initializer_list<std::array<float, 4>> pixels) {
    viz::Image image(int(pixels.size()), 1, 4);
    int x = 0;
    for (const auto& p : pixels) {
        for (int c = 0; c < 4; ++c) image.at(x, 0, c) = p[std::size_t(c)];
        ++x;
    }
    return image;
}

TEST(ViewStats, ChannelValuesFollowTheChoiceAndTheMeaningfulChannels) {
    const viz::Image image = rgba({{1, 2, 3, 4}, {5, 6, 7, 8}});
    EXPECT_EQ(channelValues(image, Channel::Rgb, 3), (std::vector<float>{1, 2, 3, 5, 6, 7}));
    EXPECT_EQ(channelValues(image, Channel::G, 4), (std::vector<float>{2, 6}));
    EXPECT_EQ(channelValues(image, Channel::A, 4), (std::vector<float>{4, 8}));
    EXPECT_TRUE(channelValues(image, Channel::A, 3).empty());  // a read-back RGB image has no alpha
    EXPECT_EQ(channelValues(image, Channel::Rgb, 1), (std::vector<float>{1, 5}));
    const auto lum = channelValues(image, Channel::Luminance, 3);
    ASSERT_EQ(lum.size(), 2u);
    EXPECT_FLOAT_EQ(lum[0], 0.2126f * 1 + 0.7152f * 2 + 0.0722f * 3);
    EXPECT_EQ(channelValues(image, Channel::Luminance, 1), (std::vector<float>{1, 5}));
}

TEST(ViewStats, SpecialPixelsAreCountedOncePerPixelOverTheMeaningfulChannels) {
    const viz::Image image = rgba({{kNaN, -1, 0, 1}, {1, 1, kInf, 1}, {-kInf, 0, 0, 1}, {1, 1, 1, -5}, {-2, -3, 0, 1}});
    const SpecialCounts three = countSpecial(image, 3);
    EXPECT_EQ(three.nan, 1u);
    EXPECT_EQ(three.inf, 2u);
    EXPECT_EQ(three.negative, 3u);  // -1, -Inf, and the pixel with two negatives once; alpha -5 ignored
    EXPECT_EQ(countSpecial(image, 4).negative, 4u);
    EXPECT_EQ(countSpecial(image, 1).nan, 1u);
    EXPECT_EQ(countSpecial(image, 1).negative, 2u);  // -Inf and -2 in red
}

TEST(ViewStats, SentinelValuesAreCountedApartAndNeverAsNegative) {
    // -1 and 4 are sentinels: a pixel holding one is counted under it (once, whatever channels hold it),
    // and a negative that is not a sentinel still counts.
    const viz::Image image = rgba({{-1, 2, 0, 1}, {-1, -1, 4, 1}, {-2, 0, 0, 1}, {1, 1, 1, -1}, {kNaN, -1, 0, 1}});
    const SpecialCounts c = countSpecial(image, 3, {-1.0f, 4.0f});
    EXPECT_EQ(c.negative, 1u);  // the -2 only; alpha is not meaningful here
    EXPECT_EQ(c.nan, 1u);
    ASSERT_EQ(c.sentinel.size(), 2u);
    EXPECT_EQ(c.sentinel[0], 3u);  // pixels 0, 1 and 4
    EXPECT_EQ(c.sentinel[1], 1u);
    EXPECT_EQ(countSpecial(image, 3).negative, 4u);  // without sentinels every -1 is negative
    EXPECT_EQ(withoutSentinels({-1, 0.5f, 4, 3, -1}, {-1.0f, 4.0f}), (std::vector<float>{0.5f, 3}));
}

TEST(ViewStats, RangesSkipNonFiniteValues) {
    const std::vector<float> values = {3, kNaN, -2, kInf, 7, -kInf};
    const ValueRange r = finiteRange(values);
    ASSERT_TRUE(r.valid);
    EXPECT_EQ(r.lo, -2.0f);
    EXPECT_EQ(r.hi, 7.0f);
    EXPECT_FALSE(finiteRange({kNaN, kInf}).valid);
    EXPECT_FALSE(percentileRange({kNaN}, 0.001, 0.999).valid);
}

TEST(ViewStats, PercentilesIgnoreTheOutliersThatMinMaxShows) {
    // 0..999 plus one huge outlier: the 0.1 and 99.9 percentiles stay near the bulk of the values.
    std::vector<float> values;
    for (int i = 0; i < 1000; ++i) values.push_back(float(i));
    values.push_back(1e9f);
    values.push_back(kNaN);
    const ValueRange p = percentileRange(values, 0.001, 0.999);
    ASSERT_TRUE(p.valid);
    EXPECT_EQ(p.lo, 1.0f);    // nearest rank round(0.001 * 1000) = 1
    EXPECT_EQ(p.hi, 999.0f);  // round(0.999 * 1000) = 999
    EXPECT_EQ(finiteRange(values).hi, 1e9f);
    const ValueRange whole = percentileRange(values, 0.0, 1.0);
    EXPECT_EQ(whole.lo, 0.0f);
    EXPECT_EQ(whole.hi, 1e9f);
}

// Most values the same (a plane that lights 2 % of the pixels): the 2nd and 98th percentiles are both 0,
// and a range of a point would map every lit pixel to white. The range then runs over all the values;
// an image of one value has none (the caller keeps its declared range).
TEST(ViewStats, PercentilesThatCollapseToAPointWidenToTheValuesOrGiveNoRange) {
    std::vector<float> sparse(1000, 0.0f);
    sparse[17] = 0.004f, sparse[500] = 0.002f, sparse[900] = 0.001f;
    const ValueRange r = percentileRange(sparse, 0.02, 0.98);
    ASSERT_TRUE(r.valid);
    EXPECT_EQ(r.lo, 0.0f);
    EXPECT_EQ(r.hi, 0.004f);
    std::vector<float> negative(1000, 1.0f);
    negative[3] = -2.0f;
    const ValueRange n = percentileRange(negative, 0.02, 0.98);
    EXPECT_EQ(n.lo, -2.0f);
    EXPECT_EQ(n.hi, 1.0f);
    EXPECT_FALSE(percentileRange(std::vector<float>(50, 0.25f), 0.02, 0.98).valid);
    EXPECT_FALSE(percentileRange({0.25f, kNaN, kInf}, 0.0, 1.0).valid);
    // Spread values keep their percentiles.
    EXPECT_EQ(percentileRange({1, 2, 3, 4, 5}, 0.0, 0.5).hi, 3.0f);
}

TEST(ViewStats, TheLogMappingIsDefinedAtBothEnds) {
    EXPECT_FLOAT_EQ(mapToUnit(10.0f, 1.0f, 100.0f, true), 0.5f);
    EXPECT_FLOAT_EQ(mapToUnit(50.0f, 0.0f, 100.0f, false), 0.5f);
    const ValueRange safe = logSafeRange(0.0f, 2.0f);
    EXPECT_FLOAT_EQ(safe.lo, 2e-6f);
    EXPECT_FLOAT_EQ(mapToUnit(2.0f, 0.0f, 2.0f, true), 1.0f);
    EXPECT_TRUE(std::isfinite(mapToUnit(0.0f, 0.0f, 2.0f, true)));
    EXPECT_EQ(logSafeRange(-3.0f, -1.0f).hi, 1.0f);
    EXPECT_EQ(mapToUnit(5.0f, 1.0f, 1.0f, false), 0.0f);  // degenerate range
}

TEST(ViewStats, TheDivergingMapIsOddAndItsLogScaleSpreadsFourDecades) {
    // Linear: v over the larger end of the range, clamped.
    EXPECT_FLOAT_EQ(signedUnit(0.5f, -2.0f, 1.0f, false), 0.25f);
    EXPECT_FLOAT_EQ(signedUnit(-3.0f, -2.0f, 1.0f, false), -1.0f);
    // Log: 0 stays white, the ends stay full, and it is odd and increasing.
    EXPECT_FLOAT_EQ(signedUnit(0.0f, -1.0f, 1.0f, true), 0.0f);
    EXPECT_NEAR(signedUnit(1.0f, -1.0f, 1.0f, true), 1.0f, 1e-6f);
    float previous = -2.0f;
    for (float v = -1.0f; v <= 1.0f; v += 0.01f) {
        const float s = signedUnit(v, -1.0f, 1.0f, true);
        EXPECT_GT(s, previous) << v;
        EXPECT_NEAR(s, -signedUnit(-v, -1.0f, 1.0f, true), 1e-6f) << v;
        previous = s;
    }
    // Each decade below the top takes about a quarter of the half-scale: 1e-2 of the top is near 1/2
    // (log(101) / log(10001) = 0.501), where the linear map shows 0.01.
    EXPECT_NEAR(signedUnit(0.01f, -1.0f, 1.0f, true), std::log(101.0f) / std::log(10001.0f), 1e-5f);
    EXPECT_NEAR(signedUnit(-0.001f, -1.0f, 1.0f, true), -std::log(11.0f) / std::log(10001.0f), 1e-5f);
}

TEST(ViewStats, HistogramsCountEveryFiniteValueOnce) {
    const std::vector<float> values = {0.0f, 0.1f, 0.26f, 0.5f, 0.99f, 1.0f, -1.0f, 2.0f, kNaN, kInf};
    const Histogram h = histogram(values, 0.0f, 1.0f, 4, false);
    EXPECT_EQ(h.bins, (std::vector<std::size_t>{2, 1, 1, 2}));  // 1.0 goes in the last bin
    EXPECT_EQ(h.below, 1u);
    EXPECT_EQ(h.above, 1u);
    // Log bins: decades 1-10, 10-100; non-positive values are below.
    const Histogram g = histogram({0.0f, -2.0f, 2.0f, 20.0f, 50.0f}, 1.0f, 100.0f, 2, true);
    EXPECT_EQ(g.bins, (std::vector<std::size_t>{1, 2}));
    EXPECT_EQ(g.below, 2u);
}

TEST(ViewStats, DifferenceImagesSumTheColourChannels) {
    viz::Image a(2, 1, 3), b(2, 1, 3);
    const float av[6] = {1, 2, 3, 0.5f, 0.5f, 0.5f};
    const float bv[6] = {1, 1, 4, 1, 1, 1};
    std::copy(av, av + 6, a.pixels.begin());
    std::copy(bv, bv + 6, b.pixels.begin());
    const viz::Image abs = differenceImage(a, b, DifferenceMode::Absolute);
    ASSERT_EQ(abs.channels, 1);
    EXPECT_FLOAT_EQ(abs.at(0, 0), 2.0f);  // |0| + |1| + |-1|
    EXPECT_FLOAT_EQ(abs.at(1, 0), 1.5f);
    const viz::Image sgn = differenceImage(a, b, DifferenceMode::Signed);
    EXPECT_FLOAT_EQ(sgn.at(0, 0), 0.0f);
    EXPECT_FLOAT_EQ(sgn.at(1, 0), -1.5f);
    const viz::Image rel = differenceImage(a, b, DifferenceMode::Relative);
    EXPECT_FLOAT_EQ(rel.at(0, 0), 2.0f / 6.0f);
    EXPECT_FLOAT_EQ(rel.at(1, 0), 1.5f / 3.0f);
    // A black `other` leaves no scale: the relative figure is the absolute one, never Inf or NaN.
    const viz::Image black(2, 1, 3);
    const viz::Image fallback = differenceImage(a, black, DifferenceMode::Relative);
    EXPECT_FLOAT_EQ(fallback.at(0, 0), 6.0f);
    EXPECT_TRUE(std::isfinite(fallback.at(1, 0)));
}

}  // namespace
}  // namespace airlight
