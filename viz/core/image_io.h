// Writing and reading images (through core/image_codec.h: OpenImageIO, or stb_image and OpenEXR in the
// portable bundle). Every write goes to a temporary file in the target folder and is
// renamed into place, so a failed write never leaves a partial file.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/image.h"

namespace viz {

// EXR: 32-bit float, linear, the image's channels (RGB for 3). PNG: 8-bit sRGB after `exposure`
// (a scale on linear values) and clamping, RGB (a fourth channel is dropped: it is data, not opacity);
// one- and two-channel images are written grey from their first channel. Throws InputError on an
// unsupported extension or an unwritable path.
void writeImage(const Image& image, const std::string& path, float exposure = 1.0f);

// 8-bit sRGB bytes of an image as writeImage encodes a PNG: linear value * exposure, clamped to [0, 1],
// sRGB-encoded (NaN as 0). channels 3: RGB, a one- or two-channel image as grey from its first channel;
// channels 1: the first channel. Row 0 at the top, interleaved.
std::vector<std::uint8_t> srgb8Pixels(const Image& image, float exposure, int channels);

// Scale a scalar image linearly from [lo, hi] to [0, 1] for viewing (NaN/Inf shown as magenta when the
// result is RGB). Returns an RGB image.
Image toDisplay(const Image& image, float lo, float hi);

Image readImage(const std::string& path);

// Lower-case extension with the dot, e.g. ".exr".
std::string extensionOf(const std::string& path);

}  // namespace viz
