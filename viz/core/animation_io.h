// Writing an animation: an animated GIF (OpenImageIO, one subimage per frame, with a frame rate), a video
// (.mp4, raw frames piped to ffmpeg) or a folder of numbered frames (PNG, and EXR when asked). Nothing
// appears at the target until every frame is in: the GIF and the video are written to a temporary name
// beside it and renamed, the frames into a staging folder (core/staged_folder.h).
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "core/image.h"

namespace viz {

enum class AnimationFormat { Gif, Video, Frames };

// .gif, .mp4, or a folder: a path ending in '/' or naming an existing folder. Anything else throws
// InputError naming the choices.
AnimationFormat animationFormatOf(const std::string& out);

// GIF stores each frame's delay in hundredths of a second: 1..100 frames per second, exact where 100 / fps
// is a whole number (25, 20, 50, ...); OpenImageIO rounds the rest down (30 plays at 33).
constexpr int kMaxFramesPerSecond = 100;

struct AnimationSpec {
    int width = 0;
    int height = 0;
    int frames = 0;      // how many add() calls commit() expects
    int fps = 25;
    bool exr = false;    // Frames: also frame_NNNN.exr (linear float, the image as given)
};

class AnimationWriter {
public:
    // Checks what can be checked before the first frame (the folder exists; for .mp4, ffmpeg is on PATH)
    // and opens the temporary output. Throws InputError naming the problem.
    AnimationWriter(const std::string& out, const AnimationSpec& spec);
    ~AnimationWriter();  // without commit(): removes everything written
    AnimationWriter(const AnimationWriter&) = delete;
    AnimationWriter& operator=(const AnimationWriter&) = delete;

    // The next frame: linear RGB (or one channel, grey), spec.width x spec.height, encoded to 8-bit sRGB
    // after `exposure` as a PNG is (core/image_io.h). Throws InputError when the encoder fails.
    void add(const Image& frame, float exposure);
    // After the last frame: moves the output into place. Throws InputError when it cannot.
    void commit();

    class Sink;

private:
    AnimationSpec mSpec;
    int mAdded = 0;
    std::unique_ptr<Sink> mSink;
};

// What is read back from an animation file (OpenImageIO builds; the portable one reads none): the first frame's size, how many frames
// (subimages) and the frame rate (0 when the file states none). Throws InputError when it cannot read it.
struct AnimationInfo {
    int width = 0;
    int height = 0;
    int frames = 0;
    double fps = 0.0;
};
AnimationInfo readAnimationInfo(const std::string& path);

// frame_0000.png: the name of frame `index` of `count` (at least 4 digits, more for long animations).
std::string frameFileName(int index, int count, const std::string& extension);

}  // namespace viz
