#include "core/image_io.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/image_codec.h"

namespace viz {

std::string extensionOf(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

static std::uint8_t encodeSrgb8(float linear) {
    if (!(linear > 0.0f)) return 0;  // also NaN
    const float c = std::min(linear, 1.0f);
    const float s = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    return static_cast<std::uint8_t>(std::lround(std::clamp(s, 0.0f, 1.0f) * 255.0f));
}

std::vector<std::uint8_t> srgb8Pixels(const Image& image, float exposure, int channels) {
    VIZ_CHECK(channels == 1 || channels == 3, "srgb8Pixels: 1 or 3 channels");
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(image.width) * std::size_t(image.height) *
                                    std::size_t(channels));
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < channels; ++c) {
                const float v = image.at(x, y, image.channels < 3 ? 0 : c);
                bytes[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * std::size_t(channels) +
                      std::size_t(c)] = encodeSrgb8(v * exposure);
            }
    return bytes;
}

void writeImage(const Image& image, const std::string& path, float exposure) {
    const std::string ext = extensionOf(path);
    if (ext != ".exr" && ext != ".png")
        throw InputError("cannot write '" + path + "': the output must end in .exr or .png");
    VIZ_CHECK(!image.empty() && image.channels >= 1 && image.channels <= 4, "writeImage: empty image");
    const std::filesystem::path target(path);
    if (target.has_parent_path() && !std::filesystem::is_directory(target.parent_path()))
        throw InputError("cannot write '" + path + "': folder '" + target.parent_path().string() + "' does not exist");

    const std::string tmp = temporaryPathFor(target).string();
    std::string err;
    if (ext == ".exr") {
        err = codec::writeExr(tmp, image);
    } else {
        // PNG is for looking at: the first channel alone (grey) or RGB. A fourth channel is data in our
        // images (a mask channel, a count), not opacity: written as alpha it made pixels transparent.
        const int channels = image.channels < 3 ? 1 : 3;
        const std::vector<std::uint8_t> bytes = srgb8Pixels(image, exposure, channels);
        err = codec::writePng(tmp, image.width, image.height, channels, bytes.data());
    }
    const bool ok = err.empty();
    std::error_code ec;
    if (ok) std::filesystem::rename(tmp, target, ec);
    if (!ok || ec) {
        std::filesystem::remove(tmp, ec);
        throw InputError("cannot write '" + path + "': " + (err.empty() ? ec.message() : err));
    }
}

Image toDisplay(const Image& image, float lo, float hi) {
    Image out(image.width, image.height, 3);
    const float scale = hi > lo ? 1.0f / (hi - lo) : 1.0f;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            if (image.channels >= 3) {
                for (int c = 0; c < 3; ++c) out.at(x, y, c) = (image.at(x, y, c) - lo) * scale;
                continue;
            }
            const float v = image.at(x, y, 0);
            if (!std::isfinite(v)) {
                out.at(x, y, 0) = 1.0f, out.at(x, y, 1) = 0.0f, out.at(x, y, 2) = 1.0f;
                continue;
            }
            const float g = std::clamp((v - lo) * scale, 0.0f, 1.0f);
            // Display values are already in [0,1] perceptual units: undo the sRGB encode of writeImage.
            const float linear = g <= 0.04045f ? g / 12.92f : std::pow((g + 0.055f) / 1.055f, 2.4f);
            for (int c = 0; c < 3; ++c) out.at(x, y, c) = linear;
        }
    return out;
}

Image readImage(const std::string& path) { return codec::readImageFile(path); }

}  // namespace viz
