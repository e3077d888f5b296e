// The image file formats behind image_io and animation_io (image_codec_portable.cpp): PNG and EXR
// through stb_image(_write) and OpenEXR; other formats, animated GIFs and animation info through the
// OpenImageIO module (oiio_module.h), loaded when first needed. The self-contained bundle of
// scripts/bundle.sh has no module, since Debian's OpenImageIO pulls in some 330 MiB of format libraries
// (video, GIS, DICOM, VDB): an executable leaves it out with the target property VIZ_PORTABLE_IMAGE_IO
// (viz/core/CMakeLists.txt).
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "core/animation_io.h"
#include "core/image.h"

namespace viz::codec {

// Which of the two builds this is, in words.
std::string backendName();

// Each writer writes the whole file at `path` and returns an empty string, or a one-line reason.
// EXR: 32-bit float, zip compression, channels R, G, B, A (one channel: Y).
std::string writeExr(const std::string& path, const Image& image);
// PNG: 8-bit, `channels` 1 (grey) or 3 (RGB), rows top to bottom, interleaved.
std::string writePng(const std::string& path, int width, int height, int channels, const std::uint8_t* bytes);

// Reads an EXR or PNG (with the module: any format OpenImageIO knows) as float: PNG values / 255 (65535
// for 16-bit), EXR values as stored.
// Throws InputError naming the path.
Image readImageFile(const std::string& path);

// An animated GIF, frame by frame (RGB bytes, rows top to bottom), looping for ever.
class GifWriter {
public:
    virtual ~GifWriter() = default;
    virtual std::string addFrame(const std::uint8_t* rgb, int index) = 0;  // "" or a reason
    virtual std::string close() = 0;                                       // "" or a reason
};
// Throws InputError when this build writes no animated GIF.
std::unique_ptr<GifWriter> openGif(const std::string& path, int width, int height, int frames, int fps);

// readAnimationInfo (core/animation_io.h) of this build: throws InputError where it reads no animations.
AnimationInfo readAnimationFileInfo(const std::string& path);

}  // namespace viz::codec
