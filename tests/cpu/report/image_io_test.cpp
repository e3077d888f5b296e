// Images written for looking at (PNG) and for their values (EXR).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "core/image.h"
#include "core/image_io.h"

namespace {

std::string tempPath(const std::string& name) {
    return (std::filesystem::temp_directory_path() / ("airlight_image_io_" + name)).string();
}

}  // namespace

// A four-channel image whose fourth channel is 0 (slices' accumulation, polyvol's positive terms) is
// written to PNG as RGB: its colour stays, not made transparent or black by an alpha of 0.
TEST(ImageIo, PngDropsTheFourthChannelAndKeepsTheColour) {
    viz::Image image(4, 2, 4);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x) {
            image.at(x, y, 0) = 0.5f;
            image.at(x, y, 1) = 0.25f;
            image.at(x, y, 2) = 1.0f;
            image.at(x, y, 3) = 0.0f;
        }
    const std::string path = tempPath("rgba.png");
    viz::writeImage(image, path);
    const viz::Image back = viz::readImage(path);
    std::filesystem::remove(path);
    ASSERT_EQ(back.channels, 3);
    // readImage gives the stored (sRGB-encoded) values: IEC 61966-2-1 of the linear ones, within a byte.
    const auto srgb = [](double v) { return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055; };
    EXPECT_NEAR(back.at(1, 1, 0), srgb(0.5), 0.5 / 255.0);
    EXPECT_NEAR(back.at(1, 1, 1), srgb(0.25), 0.5 / 255.0);
    EXPECT_NEAR(back.at(1, 1, 2), 1.0, 0.5 / 255.0);
}

// EXR keeps every channel exactly, the fourth included.
TEST(ImageIo, ExrKeepsEveryChannel) {
    viz::Image image(3, 2, 4);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = 0.1f * float(i) - 0.7f;
    const std::string path = tempPath("rgba.exr");
    viz::writeImage(image, path);
    const viz::Image back = viz::readImage(path);
    std::filesystem::remove(path);
    ASSERT_EQ(back.channels, 4);
    EXPECT_EQ(back.pixels, image.pixels);
}
