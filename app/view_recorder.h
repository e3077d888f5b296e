// Recording the focused view while an animation plays (E while P plays; E again, or P, stops): each new
// frame of the view as the export key's PNG would show it, kept as 8-bit sRGB, written as an animated
// GIF when the recording stops (core/animation_io.h). At most kMaxFrames frames and kMaxBytes of them:
// past either the recording stops by itself and is written.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/image.h"

namespace airlight {

class ViewRecorder {
public:
    static constexpr int kMaxFrames = 600;
    static constexpr std::size_t kMaxBytes = std::size_t(512) << 20;

    // Starts a recording to `path` (.gif).
    void start(const std::string& path);
    bool recording() const { return !mPath.empty(); }
    // The next frame: linear RGB, scaled by `exposure` and encoded as a PNG is. A frame of another size
    // than the first is left out (the window's half-size frames while dragging). Returns false when the
    // recording is full (then finish() it).
    bool add(const viz::Image& image, float exposure);
    int frames() const { return mFrames; }
    // Writes the GIF at `fps` (1..100) and ends the recording; returns what happened, for the status line.
    // Nothing is written for fewer than two frames.
    std::string finish(int fps);

private:
    std::string mPath;
    int mWidth = 0, mHeight = 0, mFrames = 0;
    std::vector<std::uint8_t> mBytes;  // frames one after another, RGB
};

}  // namespace airlight
