// The window's animation (P) and what runs while it plays: the first light's orbit, the clock a `time`
// parameter follows, the frame index techniques with per-frame noise read (FrameInput::frame), the
// temporal view's monitor and the focused view's recording (E). GuiApp owns one; gui.cpp advances it.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "temporal_monitor.h"
#include "view_recorder.h"

namespace airlight {

struct WindowAnimation {
    bool playing = false;                     // P: the animation runs
    double clock = 0.0;                       // seconds played
    double turn = 0.0;                        // the light's turn (0..1)
    int frame = 0;                            // frames played (FrameInput::frame)
    std::optional<viz::scene::Light> light;   // the first light as it was when play started
    glm::dvec3 centre{0.0};                   // the point it circles
    TemporalMonitor temporal;                 // L_air's change from frame to frame
    ViewRecorder recorder;                    // E while playing: the focused view's frames (a GIF)
    double recordStart = 0.0;                 // `clock` when the recording started
};

}  // namespace airlight
