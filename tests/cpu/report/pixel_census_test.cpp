// The census every image writer runs before writing: a pixel counts in every class one of its channels
// falls in (-Inf is Inf and negative), checked against counts planted by hand.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "core/pixel_census.h"

namespace viz {
namespace {

TEST(PixelCensus, CountsPlantedPixelsInEveryClassTheyFallIn) {
    Image img(7, 5, 3);
    for (float& v : img.pixels) v = 0.25f;
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    img.at(0, 0, 0) = nan;                          // NaN
    img.at(1, 0, 1) = nan, img.at(1, 0, 2) = inf;   // NaN and Inf
    img.at(2, 0, 2) = -inf;                         // Inf and negative
    img.at(3, 0, 0) = inf, img.at(3, 0, 1) = -1.0f; // Inf and negative
    img.at(4, 4, 0) = -1e-30f;                      // negative
    img.at(5, 4, 1) = -0.0f;                        // -0 is not negative
    const PixelCensus c = census(img);
    EXPECT_EQ(c.pixels, 35u);
    EXPECT_EQ(c.nan, 2u);
    EXPECT_EQ(c.inf, 3u);
    EXPECT_EQ(c.negative, 3u);
    EXPECT_FALSE(c.clean());
    EXPECT_EQ(c.describe(), "2 NaN, 3 Inf, 3 negative of 35 pixels");
    // Only the first channel: (0,0) NaN, (3,0) Inf, (4,4) negative.
    const PixelCensus red = census(img, 1);
    EXPECT_EQ(red.nan, 1u);
    EXPECT_EQ(red.inf, 1u);
    EXPECT_EQ(red.negative, 1u);
}

TEST(PixelCensus, CleanAndEmptyImages) {
    Image img(3, 2, 1);
    EXPECT_TRUE(census(img).clean());
    EXPECT_TRUE(census(Image{}).clean());
    EXPECT_EQ(census(img).describe(), "no bad of 6 pixels");
}

}  // namespace
}  // namespace viz
