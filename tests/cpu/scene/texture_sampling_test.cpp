// sRGB decoding and texture sampling conventions (v = 0 at the top row, clamp to edge).
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "cpu/scene/texture_mean_oracle.h"
#include "scene/texture_sampling.h"

namespace viz::scene {
namespace {

Texture twoByTwo() {
    // Top row: black, white; bottom row: sRGB 188 grey, red.
    Texture t;
    t.width = 2;
    t.height = 2;
    t.rgba8 = {0, 0, 0, 255, 255, 255, 255, 255, 188, 188, 188, 255, 255, 0, 0, 255};
    return t;
}

TEST(TextureSampling, SrgbDecoding) {
    EXPECT_EQ(srgbToLinear(0), 0.0f);
    EXPECT_EQ(srgbToLinear(255), 1.0f);
    // IEC 61966-2-1: 10/255 is on the linear segment c/12.92; 188/255 is about 0.5029 linear
    // (0.7373 sRGB -> ((0.7373 + 0.055) / 1.055)^2.4).
    EXPECT_NEAR(srgbToLinear(10), (10.0 / 255.0) / 12.92, 1e-7);
    EXPECT_NEAR(srgbToLinear(188), 0.5029, 1e-4);
    for (int i = 1; i < 256; ++i) EXPECT_GT(srgbToLinear(std::uint8_t(i)), srgbToLinear(std::uint8_t(i - 1)));
}

TEST(TextureSampling, TexelCentresReturnTheTexel) {
    const Texture t = twoByTwo();
    EXPECT_EQ(sampleLinearRgb(t, {0.25, 0.25}), glm::vec3(0.0f));             // top-left
    EXPECT_EQ(sampleLinearRgb(t, {0.75, 0.25}), glm::vec3(1.0f));             // top-right
    EXPECT_EQ(sampleLinearRgb(t, {0.75, 0.75}), glm::vec3(1.0f, 0.0f, 0.0f)); // bottom-right
    EXPECT_EQ(sampleNearestRgb(t, {0.1, 0.9}), glm::vec3(srgbToLinear(188)));
}

TEST(TextureSampling, BilinearFiltersLinearValues) {
    const Texture t = twoByTwo();
    // Halfway between black and white along the top row: 0.5 in linear space (not sRGB 128).
    EXPECT_NEAR(sampleLinearRgb(t, {0.5, 0.25}).x, 0.5f, 1e-6);
    // Centre: average of the four decoded texels.
    const glm::vec3 avg = (glm::vec3(0.0f) + glm::vec3(1.0f) + glm::vec3(srgbToLinear(188)) + glm::vec3(1, 0, 0)) / 4.0f;
    const glm::vec3 c = sampleLinearRgb(t, {0.5, 0.5});
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(c[i], avg[i], 1e-6);
}

TEST(TextureSampling, ClampsToEdge) {
    const Texture t = twoByTwo();
    EXPECT_EQ(sampleLinearRgb(t, {-3.0, 0.25}), glm::vec3(0.0f));
    EXPECT_EQ(sampleLinearRgb(t, {0.0, 0.0}), glm::vec3(0.0f));
    EXPECT_EQ(sampleLinearRgb(t, {7.0, 7.0}), glm::vec3(1, 0, 0));
    EXPECT_EQ(sampleNearestRgb(t, {1.0, 1.0}), glm::vec3(1, 0, 0));
}

// averageLinearRgb integrates the bilinear filter exactly: against the mean of a fine grid of
// sampleLinearRgb samples (midpoint rule, error O(1/n^2) on a piecewise bilinear function) over
// rectangles inside texels, across texel centres, at the clamped edges and over the whole texture.
TEST(TextureSampling, AverageIsTheMeanOfTheBilinearFilter) {
    Texture t;
    t.width = 5;
    t.height = 3;
    for (int i = 0; i < t.width * t.height; ++i) {
        t.rgba8.push_back(std::uint8_t((37 * i) % 256));
        t.rgba8.push_back(std::uint8_t((91 * i + 50) % 256));
        t.rgba8.push_back(std::uint8_t(255 - (13 * i) % 256));
        t.rgba8.push_back(255);
    }
    const std::vector<std::pair<glm::dvec2, glm::dvec2>> rects = {
        {{0.0, 0.0}, {1.0, 1.0}},        // the whole texture
        {{0.0, 0.0}, {0.05, 0.1}},       // the clamped corner
        {{0.95, 0.9}, {1.0, 1.0}},       // the other one
        {{0.31, 0.2}, {0.36, 0.45}},     // inside one texel column, across a row's centre
        {{0.13, 0.05}, {0.77, 0.93}},    // across many centres
        {{0.5, 0.5}, {0.5004, 0.5007}},  // tiny
    };
    for (const auto& [a, b] : rects) {
        const glm::dvec3 exact = averageLinearRgb(t, a, b);
        const glm::dvec3 fine = testing::gridMeanLinearRgb(t, a, b, 600);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(exact[c], fine[c], 2e-5) << a.x << "," << a.y << " " << c;
    }
    // Wider than kMaxExactTexels texels: the mean of a midpoint grid of the filter, still near the fine
    // mean (a smooth 600 x 400 ramp in each channel, whose grid error is O(1/128^2)).
    Texture big;
    big.width = 600;
    big.height = 400;
    for (int y = 0; y < big.height; ++y)
        for (int x = 0; x < big.width; ++x) {
            big.rgba8.push_back(std::uint8_t(x * 255 / (big.width - 1)));
            big.rgba8.push_back(std::uint8_t(y * 255 / (big.height - 1)));
            big.rgba8.push_back(std::uint8_t((x + y) * 255 / (big.width + big.height - 2)));
            big.rgba8.push_back(255);
        }
    {
        const glm::dvec3 a = averageLinearRgb(big, {0.05, 0.1}, {0.9, 0.8});
        const glm::dvec3 fine = testing::gridMeanLinearRgb(big, {0.05, 0.1}, {0.9, 0.8}, 1000);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], fine[c], 1e-4) << c;
    }
    // An empty rectangle is the filter at its point; a single texel's texture is its colour everywhere.
    EXPECT_NEAR(averageLinearRgb(t, {0.4, 0.4}, {0.4, 0.4}).x, sampleLinearRgb(t, {0.4, 0.4}).x, 1e-7);
    Texture one;
    one.width = one.height = 1;
    one.rgba8 = {200, 100, 50, 255};
    EXPECT_NEAR(averageLinearRgb(one, {0.1, 0.2}, {0.7, 0.9}).y, srgbToLinear(100), 1e-7);
}

}  // namespace
}  // namespace viz::scene
