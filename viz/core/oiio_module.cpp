// The OpenImageIO module (oiio_module.h): any image format OpenImageIO reads, animated GIFs, animation
// info. Nothing here throws to the program.
#include "core/oiio_module.h"

#include <OpenImageIO/imageio.h>

#include <exception>
#include <vector>

namespace viz::codec {
namespace {

class OiioGif : public GifWriter {
public:
    OiioGif(const std::string& path, int width, int height, int frames, int fps)
        : mPath(path), mSpec(width, height, 3, OIIO::TypeDesc::UINT8), mFrames(frames) {
        mOutput = OIIO::ImageOutput::create(path);
        const int rate[2] = {fps, 1};
        mSpec.attribute("FramesPerSecond", OIIO::TypeRational, rate);
        mSpec.attribute("oiio:LoopCount", 0);  // loop for ever
    }
    ~OiioGif() override {
        if (mOutput) mOutput->close();
    }
    bool usable() const { return mOutput && mOutput->supports("multiimage") && mOutput->supports("appendsubimage"); }
    std::string addFrame(const std::uint8_t* rgb, int index) override {
        bool ok = true;
        if (index == 0) {
            const std::vector<OIIO::ImageSpec> specs(std::size_t(mFrames), mSpec);
            ok = mOutput->open(mPath, mFrames, specs.data());
        } else {
            ok = mOutput->open(mPath, mSpec, OIIO::ImageOutput::AppendSubimage);
        }
        ok = ok && mOutput->write_image(OIIO::TypeDesc::UINT8, rgb);
        return ok ? std::string() : mOutput->geterror();
    }
    std::string close() override {
        const bool ok = mOutput->close();
        const std::string error = mOutput->geterror();
        mOutput.reset();
        return ok ? std::string() : (error.empty() ? std::string("write failed") : error);
    }

private:
    std::string mPath;
    OIIO::ImageSpec mSpec;
    int mFrames;
    std::unique_ptr<OIIO::ImageOutput> mOutput;
};

std::string reason(const std::string& error) { return error.empty() ? std::string("unknown error") : error; }

std::string moduleReadImage(const std::string& path, Image& image) try {
    auto in = OIIO::ImageInput::open(path);
    if (!in) return reason(OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    image = Image(spec.width, spec.height, spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
        return reason(in->geterror());
    return {};
} catch (const std::exception& e) {
    return e.what();
}

std::string moduleAnimationInfo(const std::string& path, AnimationInfo& info) try {
    auto in = OIIO::ImageInput::open(path);
    if (!in) return reason(OIIO::geterror());
    info = AnimationInfo{};
    info.width = in->spec().width;
    info.height = in->spec().height;
    const OIIO::ParamValue* rate = in->spec().find_attribute("FramesPerSecond", OIIO::TypeRational);
    if (rate) {
        const int* r = static_cast<const int*>(rate->data());
        if (r[1] != 0) info.fps = double(r[0]) / double(r[1]);
    }
    int frames = 1;
    while (in->seek_subimage(frames, 0)) ++frames;
    info.frames = frames;
    return {};
} catch (const std::exception& e) {
    return e.what();
}

std::string moduleOpenGif(const std::string& path, int width, int height, int frames, int fps, std::unique_ptr<GifWriter>& writer) try {
    auto gif = std::make_unique<OiioGif>(path, width, height, frames, fps);
    if (!gif->usable()) return "this OpenImageIO writes no animated GIF";
    writer = std::move(gif);
    return {};
} catch (const std::exception& e) {
    return e.what();
}

}  // namespace
}  // namespace viz::codec

extern "C" __attribute__((visibility("default"))) const viz::codec::OiioModule* airlightOiioModule() {
    static const viz::codec::OiioModule module{viz::codec::kOiioModuleAbi, viz::codec::moduleReadImage,
                                               viz::codec::moduleAnimationInfo, viz::codec::moduleOpenGif};
    return &module;
}
