// The report's silhouette pixels (report/first_hits.h): which pixels the rasterised and traced first hits
// disagree on, and the relative L2 over the rest, on images whose answers are worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "report/error_metrics.h"
#include "report/first_hits.h"

namespace viz::report {
namespace {

Image distances(int w, int h, float v) {
    Image image(w, h, 1);
    for (float& p : image.pixels) p = v;
    return image;
}

TEST(FirstHits, PixelsAgreeWithinATenthOfAPercentOfTheTracedDistance) {
    Image traced = distances(4, 2, 100.0f), drawn = distances(4, 2, 100.0f);
    drawn.at(0, 0) = 100.09f;                                   // 0.09 % off: agrees
    drawn.at(1, 0) = 99.85f;                                    // 0.15 % short: a nearer surface
    drawn.at(2, 0) = 1e6f;                                      // the rasteriser sees sky
    traced.at(3, 0) = 36.9f;                                    // the ray hits a trunk the raster misses
    drawn.at(0, 1) = std::numeric_limits<float>::quiet_NaN();   // never agrees
    traced.at(1, 1) = std::numeric_limits<float>::infinity();
    const FirstHitMask m = firstHitAgreement(traced, drawn);
    EXPECT_EQ(m.width, 4);
    EXPECT_EQ(m.height, 2);
    const std::vector<std::uint8_t> expected = {1, 0, 0, 0, 0, 0, 1, 1};
    EXPECT_EQ(m.agree, expected);
    EXPECT_EQ(m.disagreeing, 5u);
}

// Two pixels, three channels: the reference 1 everywhere; the test off by 0.1 in every channel of the
// pixel kept and by 10 in the one left out. Kept: sqrt(3 * 0.01) / sqrt(3) = 0.1; all: the full figure.
TEST(FirstHits, RelativeL2LeavesOutExactlyTheDisagreeingPixels) {
    Image reference(2, 1, 3), test(2, 1, 3);
    for (float& v : reference.pixels) v = 1.0f;
    for (int c = 0; c < 3; ++c) test.at(0, 0, c) = 1.1f, test.at(1, 0, c) = 11.0f;
    FirstHitMask mask{2, 1, {1, 0}, 1};
    EXPECT_NEAR(relativeL2Over(test, reference, mask), 0.1, 1e-6);
    const double all = std::sqrt((3 * 0.01 + 3 * 100.0) / 6.0);
    EXPECT_NEAR(relativeL2Over(test, reference, FirstHitMask{2, 1, {1, 1}, 0}), all, 1e-5);
    EXPECT_NEAR(compareImages(test, reference).relativeL2, all, 1e-5);  // the report's unmasked figure
    // A NaN in a pixel left out does not matter; in a pixel kept it makes the figure undefined.
    test.at(1, 0, 1) = std::numeric_limits<float>::quiet_NaN();
    EXPECT_NEAR(relativeL2Over(test, reference, mask), 0.1, 1e-6);
    test.at(0, 0, 2) = std::numeric_limits<float>::quiet_NaN();
    EXPECT_TRUE(std::isnan(relativeL2Over(test, reference, mask)));
    // Nothing kept but black reference and no difference: zero, as compareImages says of two black images.
    Image black(1, 1, 3);
    EXPECT_EQ(relativeL2Over(black, black, FirstHitMask{1, 1, {1}, 0}), 0.0);
    EXPECT_EQ(relativeL2Over(black, black, FirstHitMask{1, 1, {0}, 1}), 0.0);
}

}  // namespace
}  // namespace viz::report
