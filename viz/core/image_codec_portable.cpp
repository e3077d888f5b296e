// The image formats without OpenImageIO (see image_codec.h): PNG through stb_image and stb_image_write,
// EXR through OpenEXR. The stb implementations are compiled here with internal linkage (STB_*_STATIC),
// apart from the copy tinygltf compiles for the scene loader.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>

#include <cstdio>
#include <cstring>
#include <exception>
#include <vector>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb_image.h>
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

#include "core/error.h"
#include "core/image_codec.h"

namespace viz::codec {

std::string backendName() { return "stb_image + OpenEXR"; }

namespace {

const char* channelName(int channels, int c) {
    static const char* const kRgba[] = {"R", "G", "B", "A"};
    return channels == 1 ? "Y" : kRgba[c];
}

bool isExr(const std::string& path) {
    unsigned char magic[4] = {};
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) return false;
    const bool read = std::fread(magic, 1, 4, f) == 4;
    std::fclose(f);
    return read && magic[0] == 0x76 && magic[1] == 0x2f && magic[2] == 0x31 && magic[3] == 0x01;
}

Image readExr(const std::string& path) {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i window = file.header().dataWindow();
    const int width = window.max.x - window.min.x + 1, height = window.max.y - window.min.y + 1;
    // R, G, B, A in that order when present (EXR lists channels alphabetically), else the file's order.
    std::vector<std::string> names;
    for (const char* n : {"R", "G", "B", "A"})
        if (file.header().channels().findChannel(n)) names.push_back(n);
    if (names.empty())
        for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it)
            names.push_back(it.name());
    if (names.empty() || names.size() > 4 || width <= 0 || height <= 0)
        throw InputError("cannot read image '" + path + "': " + std::to_string(names.size()) + " channels, " +
                         std::to_string(width) + "x" + std::to_string(height));
    Image image(width, height, int(names.size()));
    const std::size_t xStride = sizeof(float) * names.size(), yStride = xStride * std::size_t(width);
    char* base = reinterpret_cast<char*>(image.pixels.data()) - std::ptrdiff_t(window.min.x) * std::ptrdiff_t(xStride) -
                 std::ptrdiff_t(window.min.y) * std::ptrdiff_t(yStride);
    Imf::FrameBuffer buffer;
    for (std::size_t c = 0; c < names.size(); ++c)
        buffer.insert(names[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xStride, yStride));
    file.setFrameBuffer(buffer);
    file.readPixels(window.min.y, window.max.y);
    return image;
}

}  // namespace

std::string writeExr(const std::string& path, const Image& image) {
    try {
        Imf::Header header(image.width, image.height);
        header.compression() = Imf::ZIP_COMPRESSION;
        Imf::FrameBuffer buffer;
        const std::size_t xStride = sizeof(float) * std::size_t(image.channels);
        const std::size_t yStride = xStride * std::size_t(image.width);
        char* base = const_cast<char*>(reinterpret_cast<const char*>(image.pixels.data()));
        for (int c = 0; c < image.channels; ++c) {
            header.channels().insert(channelName(image.channels, c), Imf::Channel(Imf::FLOAT));
            buffer.insert(channelName(image.channels, c), Imf::Slice(Imf::FLOAT, base + std::size_t(c) * sizeof(float), xStride, yStride));
        }
        Imf::OutputFile file(path.c_str(), header);
        file.setFrameBuffer(buffer);
        file.writePixels(image.height);
        return {};
    } catch (const std::exception& e) {
        return e.what();
    }
}

std::string writePng(const std::string& path, int width, int height, int channels, const std::uint8_t* bytes) {
    return stbi_write_png(path.c_str(), width, height, channels, bytes, width * channels) ? std::string()
                                                                                       : std::string("PNG write failed");
}

Image readImageFile(const std::string& path) {
    if (isExr(path)) {
        try {
            return readExr(path);
        } catch (const InputError&) {
            throw;
        } catch (const std::exception& e) {
            throw InputError("cannot read image '" + path + "': " + e.what());
        }
    }
    int width = 0, height = 0, channels = 0;
    stbi_uc* data = stbi_load(path.c_str(), &width, &height, &channels, 0);
    if (!data)
        throw InputError("cannot read image '" + path + "': " + (stbi_failure_reason() ? stbi_failure_reason() : "unknown format") +
                         " (this build reads PNG and EXR)");
    Image image(width, height, channels);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = float(data[i]) / 255.0f;
    stbi_image_free(data);
    return image;
}

std::unique_ptr<GifWriter> openGif(const std::string& path, int, int, int, int) {
    throw InputError("cannot write '" + path + "': this build (the portable bundle, without OpenImageIO) writes no "
                     "animated GIF; write .mp4 or a folder of frames");
}

AnimationInfo readAnimationFileInfo(const std::string& path) {
    throw InputError("cannot read '" + path + "': this build (the portable bundle, without OpenImageIO) reads no "
                     "animations");
}

}  // namespace viz::codec
