// sRGB decoding and texture sampling conventions (v = 0 at the top row, clamp to edge).
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace viz::scene
