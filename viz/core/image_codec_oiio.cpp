// The image formats through OpenImageIO (see image_codec.h).
#include <OpenImageIO/imageio.h>

#include <vector>

#include "core/error.h"
#include "core/image_codec.h"

namespace viz::codec {

std::string backendName() { return "OpenImageIO"; }

namespace {

std::string writeWith(const std::string& path, const OIIO::ImageSpec& spec, OIIO::TypeDesc type, const void* data) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out) return OIIO::geterror();
    bool ok = out->open(path, spec) && out->write_image(type, data);
    const std::string err = out->geterror();
    ok = out->close() && ok;
    return ok ? std::string() : (err.empty() ? std::string("write failed") : err);
}

class OiioGif : public GifWriter {
public:
    OiioGif(const std::string& path, int width, int height, int frames, int fps)
        : mPath(path), mSpec(width, height, 3, OIIO::TypeDesc::UINT8), mFrames(frames) {
        mOutput = OIIO::ImageOutput::create(path);
        if (!mOutput || !mOutput->supports("multiimage") || !mOutput->supports("appendsubimage"))
            throw InputError("cannot write '" + path + "': this OpenImageIO writes no animated GIF");
        const int rate[2] = {fps, 1};
        mSpec.attribute("FramesPerSecond", OIIO::TypeRational, rate);
        mSpec.attribute("oiio:LoopCount", 0);  // loop for ever
    }
    ~OiioGif() override {
        if (mOutput) mOutput->close();
    }
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

}  // namespace

std::string writeExr(const std::string& path, const Image& image) {
    OIIO::ImageSpec spec(image.width, image.height, image.channels, OIIO::TypeDesc::FLOAT);
    spec.attribute("compression", "zip");
    return writeWith(path, spec, OIIO::TypeDesc::FLOAT, image.pixels.data());
}

std::string writePng(const std::string& path, int width, int height, int channels, const std::uint8_t* bytes) {
    return writeWith(path, OIIO::ImageSpec(width, height, channels, OIIO::TypeDesc::UINT8), OIIO::TypeDesc::UINT8, bytes);
}

Image readImageFile(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw InputError("cannot read image '" + path + "': " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    Image image(spec.width, spec.height, spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
        throw InputError("cannot read image '" + path + "': " + in->geterror());
    return image;
}

std::unique_ptr<GifWriter> openGif(const std::string& path, int width, int height, int frames, int fps) {
    return std::make_unique<OiioGif>(path, width, height, frames, fps);
}

AnimationInfo readAnimationFileInfo(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw InputError("cannot read '" + path + "': " + OIIO::geterror());
    AnimationInfo info;
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
    return info;
}

}  // namespace viz::codec
