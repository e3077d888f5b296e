#include "view_recorder.h"

#include <algorithm>
#include <cmath>

#include "core/animation_io.h"
#include "core/error.h"
#include "core/image_io.h"

namespace airlight {

void ViewRecorder::start(const std::string& path) {
    *this = ViewRecorder{};
    mPath = path;
}

bool ViewRecorder::add(const viz::Image& image, float exposure) {
    if (!recording() || image.empty()) return true;
    if (mFrames == 0) {
        mWidth = image.width;
        mHeight = image.height;
    } else if (image.width != mWidth || image.height != mHeight) {
        return true;
    }
    const std::vector<std::uint8_t> bytes = viz::srgb8Pixels(image, exposure, 3);
    mBytes.insert(mBytes.end(), bytes.begin(), bytes.end());
    ++mFrames;
    return mFrames < kMaxFrames && mBytes.size() + bytes.size() <= kMaxBytes;
}

std::string ViewRecorder::finish(int fps) {
    const std::string path = mPath;
    const int frames = mFrames;
    if (!recording()) return "";
    if (frames < 2) {
        *this = ViewRecorder{};
        return "recording stopped: fewer than two frames, nothing written";
    }
    std::string notice;
    try {
        viz::AnimationWriter writer(path, {mWidth, mHeight, frames, std::clamp(fps, 1, viz::kMaxFramesPerSecond), false});
        // Back to linear values that encode to the same bytes.
        viz::Image frame(mWidth, mHeight, 3);
        const std::size_t size = std::size_t(mWidth) * std::size_t(mHeight) * 3;
        for (int f = 0; f < frames; ++f) {
            for (std::size_t i = 0; i < size; ++i) {
                const float v = float(mBytes[std::size_t(f) * size + i]) / 255.0f;
                frame.pixels[i] = v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
            }
            writer.add(frame, 1.0f);
        }
        writer.commit();
        notice = "recorded " + path + " (" + std::to_string(frames) + " frames, " + std::to_string(fps) + " per second)";
    } catch (const viz::InputError& e) {
        notice = std::string("recording not written: ") + e.what();
    }
    *this = ViewRecorder{};
    return notice;
}

}  // namespace airlight
