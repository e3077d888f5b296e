// The image file formats behind image_io and animation_io, in one of two builds: OpenImageIO (the app's
// default, image_codec_oiio.cpp) or stb_image(_write) and OpenEXR alone (image_codec_portable.cpp), for
// the self-contained bundle of scripts/bundle.sh, since Debian's OpenImageIO pulls in some 330 MiB of
// format libraries (video, GIS, DICOM, VDB). An executable picks the portable one with the target
// property VIZ_PORTABLE_IMAGE_IO (viz/core/CMakeLists.txt).
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "core/animation_io.h"
#include "core/image.h"

namespace viz::codec {

// "OpenImageIO" or "stb_image + OpenEXR".
std::string backendName();

// Each writer writes the whole file at `path` and returns an empty string, or a one-line reason.
// EXR: 32-bit float, zip compression, channels R, G, B, A (one channel: Y).
std::string writeExr(const std::string& path, const Image& image);
// PNG: 8-bit, `channels` 1 (grey) or 3 (RGB), rows top to bottom, interleaved.
std::string writePng(const std::string& path, int width, int height, int channels, const std::uint8_t* bytes);

// Reads an EXR or PNG (OpenImageIO: any format it knows) as float: PNG bytes / 255, EXR values as stored.
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
