// Images written for looking at (PNG) and for their values (EXR).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/image.h"
#include "core/image_io.h"
#include "temp_dir.h"

namespace {

std::string tempPath(const std::string& name) {
    static const viz::testing::TempDir dir("image_io");
    return (dir / name).string();
}

// A 16-bit grey PNG of one row, `samples` wide, written here byte by byte (PNG specification: IHDR,
// one IDAT holding a zlib stream of one stored block, IEND; CRC-32 and Adler-32 computed bit by bit).
void writeGrey16Png(const std::string& path, const std::vector<std::uint16_t>& samples) {
    auto be32 = [](std::vector<unsigned char>& v, std::uint32_t x) {
        for (int s = 24; s >= 0; s -= 8) v.push_back(static_cast<unsigned char>(x >> s));
    };
    std::vector<unsigned char> file = {0x89, 'P', 'N', 'G', 0x0d, 0x0a, 0x1a, 0x0a};
    auto chunk = [&](const char* type, const std::vector<unsigned char>& data) {
        be32(file, std::uint32_t(data.size()));
        std::vector<unsigned char> body(type, type + 4);
        body.insert(body.end(), data.begin(), data.end());
        std::uint32_t crc = 0xffffffffu;
        for (unsigned char byte : body) {
            crc ^= byte;
            for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
        }
        file.insert(file.end(), body.begin(), body.end());
        be32(file, crc ^ 0xffffffffu);
    };
    std::vector<unsigned char> header;
    be32(header, std::uint32_t(samples.size()));
    be32(header, 1);
    header.insert(header.end(), {16, 0, 0, 0, 0});  // depth 16, grey, deflate, filter 0, no interlace
    chunk("IHDR", header);
    std::vector<unsigned char> row = {0};  // filter type 0
    for (std::uint16_t v : samples) row.push_back(static_cast<unsigned char>(v >> 8)), row.push_back(static_cast<unsigned char>(v));
    std::vector<unsigned char> zlib = {0x78, 0x01, 0x01};  // one final stored block
    const auto n = static_cast<std::uint16_t>(row.size());
    zlib.insert(zlib.end(), {static_cast<unsigned char>(n), static_cast<unsigned char>(n >> 8),
                             static_cast<unsigned char>(~n), static_cast<unsigned char>(~n >> 8)});
    zlib.insert(zlib.end(), row.begin(), row.end());
    std::uint32_t a = 1, b = 0;
    for (unsigned char byte : row) a = (a + byte) % 65521u, b = (b + a) % 65521u;
    be32(zlib, (b << 16) | a);
    chunk("IDAT", zlib);
    chunk("IEND", {});
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(file.data()), std::streamsize(file.size()));
}

}  // namespace

// A 16-bit PNG reads with its 16 bits: 1000 / 65535, not rounded to a byte.
TEST(ImageIo, SixteenBitPngKeepsItsPrecision) {
    const std::string path = tempPath("grey16.png");
    writeGrey16Png(path, {1000, 65535, 0});
    const viz::Image back = viz::readImage(path);
    std::filesystem::remove(path);
    ASSERT_EQ(back.width, 3);
    ASSERT_EQ(back.channels, 1);
    EXPECT_FLOAT_EQ(back.at(0, 0, 0), 1000.0f / 65535.0f);
    EXPECT_FLOAT_EQ(back.at(1, 0, 0), 1.0f);
    EXPECT_FLOAT_EQ(back.at(2, 0, 0), 0.0f);
}

// A file that is not there is named with the system's reason.
TEST(ImageIo, AMissingFileIsNamed) {
    try {
        (void)viz::readImage(tempPath("not-there.png"));
        FAIL() << "no exception";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("not-there.png"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("No such file"), std::string::npos) << e.what();
    }
}

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
