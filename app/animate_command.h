// `airlight animate`: one technique's frames along a motion path (scene/motion_path.h), written as an
// animated GIF, a video (ffmpeg) or a folder of numbered frames (core/animation_io.h).
#pragma once

#include "cli_args.h"

namespace airlight {

// The most frames one animation may have (--frames).
constexpr int kMaxAnimationFrames = 10000;

int runAnimate(Args& args);

}  // namespace airlight
