// The image formats (see image_codec.h): PNG through stb_image and stb_image_write, EXR through OpenEXR.
// The stb implementations are compiled here with internal linkage (STB_*_STATIC), apart from the copy
// tinygltf compiles for the scene loader. Built with VIZ_OIIO_MODULE (the app's default), everything
// else (other image formats, animated GIFs, animation info) goes to the OpenImageIO module
// (oiio_module.h), loaded the first time it is needed; without it (the bundle) those are errors.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
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

#ifdef VIZ_OIIO_MODULE
#include <dlfcn.h>

#include <filesystem>
#include <mutex>

#include "core/oiio_module.h"
#endif

namespace viz::codec {

#ifdef VIZ_OIIO_MODULE
std::string backendName() { return "stb_image + OpenEXR; OpenImageIO (loaded when needed) for other formats"; }
#else
std::string backendName() { return "stb_image + OpenEXR"; }
#endif

namespace {

#ifdef VIZ_OIIO_MODULE
// The module, loaded once: AIRLIGHT_OIIO_MODULE, else beside the executable, else where the build put it.
// Never unloaded (a GIF writer it made may outlive any scope). Null, with the reason, when none loads.
const OiioModule* oiioModule(std::string& why) {
    static std::once_flag once;
    static const OiioModule* module = nullptr;
    static std::string reason;
    std::call_once(once, [] {
        std::vector<std::string> candidates;
        if (const char* env = std::getenv("AIRLIGHT_OIIO_MODULE"); env != nullptr && env[0] != '\0') {
            candidates.push_back(env);
        } else {
            std::error_code ec;
            const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
            if (!ec) candidates.push_back((exe.parent_path() / VIZ_OIIO_MODULE_NAME).string());
            candidates.push_back(VIZ_OIIO_MODULE_PATH);
        }
        for (const std::string& path : candidates) {
            void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
            if (!handle) {
                if (reason.empty()) reason = dlerror();
                continue;
            }
            using Entry = const OiioModule* (*)();
            const auto entry = reinterpret_cast<Entry>(dlsym(handle, "airlightOiioModule"));
            const OiioModule* m = entry ? entry() : nullptr;
            if (m && m->abi == kOiioModuleAbi) {
                module = m;
                return;
            }
            reason = path + " is not this build's OpenImageIO module";
        }
    });
    why = reason;
    return module;
}
#endif

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
    if (std::FILE* f = std::fopen(path.c_str(), "rb")) {
        std::fclose(f);
    } else {
        throw InputError("cannot read image '" + path + "': " + std::strerror(errno));
    }
    int width = 0, height = 0, channels = 0;
    // A 16-bit PNG keeps its 16 bits.
    const bool wide = stbi_is_16_bit(path.c_str()) != 0;
    void* data = wide ? static_cast<void*>(stbi_load_16(path.c_str(), &width, &height, &channels, 0))
                      : static_cast<void*>(stbi_load(path.c_str(), &width, &height, &channels, 0));
    if (data) {
        Image image(width, height, channels);
        for (std::size_t i = 0; i < image.pixels.size(); ++i)
            image.pixels[i] = wide ? float(static_cast<const stbi_us*>(data)[i]) / 65535.0f
                                   : float(static_cast<const stbi_uc*>(data)[i]) / 255.0f;
        stbi_image_free(data);
        return image;
    }
    const std::string stbReason = stbi_failure_reason() ? stbi_failure_reason() : "unknown format";
#ifdef VIZ_OIIO_MODULE
    std::string why;
    if (const OiioModule* module = oiioModule(why)) {
        Image image;
        const std::string error = module->readImage(path, image);
        if (!error.empty()) throw InputError("cannot read image '" + path + "': " + error);
        return image;
    }
    throw InputError("cannot read image '" + path + "': " + stbReason + " (PNG and EXR only: " + why + ")");
#else
    throw InputError("cannot read image '" + path + "': " + stbReason + " (this build reads PNG and EXR)");
#endif
}

#ifdef VIZ_OIIO_MODULE
namespace {
// The loaded module, or the error "PREFIX no WHAT without OpenImageIO (why it did not load)".
const OiioModule& requireOiioModule(const std::string& prefix, const char* what) {
    std::string why;
    if (const OiioModule* module = oiioModule(why)) return *module;
    throw InputError(prefix + "no " + what + " without OpenImageIO (" + why + ")");
}
}  // namespace

std::unique_ptr<GifWriter> openGif(const std::string& path, int width, int height, int frames, int fps) {
    const std::string prefix = "cannot write '" + path + "': ";
    std::unique_ptr<GifWriter> writer;
    const std::string error = requireOiioModule(prefix, "animated GIF").openGif(path, width, height, frames, fps, writer);
    if (!error.empty()) throw InputError(prefix + error);
    return writer;
}

AnimationInfo readAnimationFileInfo(const std::string& path) {
    const std::string prefix = "cannot read '" + path + "': ";
    AnimationInfo info;
    const std::string error = requireOiioModule(prefix, "animations").readAnimationInfo(path, info);
    if (!error.empty()) throw InputError(prefix + error);
    return info;
}
#else
std::unique_ptr<GifWriter> openGif(const std::string& path, int, int, int, int) {
    throw InputError("cannot write '" + path + "': this build (the portable bundle, without OpenImageIO) writes no "
                     "animated GIF; write .mp4 or a folder of frames");
}

AnimationInfo readAnimationFileInfo(const std::string& path) {
    throw InputError("cannot read '" + path + "': this build (the portable bundle, without OpenImageIO) reads no "
                     "animations");
}
#endif

}  // namespace viz::codec
