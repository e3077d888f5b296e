// The OpenImageIO part of the image codec, built as a module that a program loads the first time it
// needs it (image_codec_portable.cpp, with VIZ_OIIO_MODULE): an image that is neither PNG nor EXR, an
// animated GIF, an animation's frame count and rate. PNG and EXR, the formats the program itself writes,
// go through stb_image and OpenEXR without it. Debian's OpenImageIO links some 260 shared libraries
// (video, GIS, DICOM, VDB); loading and relocating them took 0.45 s of CPU at every start of every
// program that linked it, for each `airlight` command and each test process.
//
// The module and the program are built together by one compiler, so C++ types cross the boundary. No
// exception does: each entry returns an empty string or a one-line reason, and the program throws.
#pragma once

#include <memory>
#include <string>

#include "core/animation_io.h"
#include "core/image.h"
#include "core/image_codec.h"

namespace viz::codec {

inline constexpr int kOiioModuleAbi = 1;

struct OiioModule {
    int abi = kOiioModuleAbi;  // the program refuses a module of another build
    std::string (*readImage)(const std::string& path, Image& image);
    std::string (*readAnimationInfo)(const std::string& path, AnimationInfo& info);
    std::string (*openGif)(const std::string& path, int width, int height, int frames, int fps,
                           std::unique_ptr<GifWriter>& writer);
};

}  // namespace viz::codec

// The module's one exported symbol (dlsym).
extern "C" const viz::codec::OiioModule* airlightOiioModule();
