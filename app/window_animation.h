// The window's animation (P) and what runs while it plays: the first light's orbit, the clock a `time`
// parameter follows, the frame index techniques with per-frame noise read (FrameInput::frame), the
// temporal view's monitor and the focused view's recording (E). GuiApp owns one; window_animation.cpp
// advances it.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "scene/motion_path.h"
#include "path_reference.h"
#include "scene/scene.h"
#include "temporal_monitor.h"
#include "view_recorder.h"

namespace airlight {

// Whether `camera` and `lights` are where `pose` put them (the camera's frame and every light's place).
inline bool samePose(const viz::scene::Pose& pose, const viz::scene::Camera& camera,
                     const std::vector<viz::scene::Light>& lights) {
    if (pose.camera.position != camera.position || pose.camera.forward != camera.forward ||
        pose.camera.up != camera.up || pose.lights.size() != lights.size())
        return false;
    for (std::size_t i = 0; i < lights.size(); ++i)
        if (pose.lights[i].position != lights[i].position || pose.lights[i].direction != lights[i].direction ||
            pose.lights[i].intensity != lights[i].intensity)
            return false;
    return true;
}

struct WindowAnimation {
    bool playing = false;                     // P: the animation runs
    double clock = 0.0;                       // seconds played
    double turn = 0.0;                        // the light's turn (0..1)
    int frame = 0;                            // frames played (FrameInput::frame)
    std::optional<viz::scene::Light> light;   // the first light as it was when play started
    glm::dvec3 centre{0.0};                   // the point it circles (--path: the camera's target at start)
    TemporalMonitor temporal;                 // L_air's change from frame to frame (and its error's)
    PathReference reference;                  // --path: the reference's frames, while a temporal view shows
    ViewRecorder recorder;                    // E while playing: the focused view's frames (a GIF)
    // --path: the motion played instead of the light's orbit, frames of its loop, where play started from
    // (each frame is the path's pure function of it) and the frame shown.
    std::optional<viz::scene::MotionPath> path;
    int pathFrames = 120;
    std::optional<viz::scene::Pose> pathStart;
    std::optional<viz::scene::Pose> pathShown;  // the pose the last path frame set
    double pathClock = 0.0;                     // `clock` when the loop started
    std::uint64_t pathScene = 0;                // the scene's geometry hash then
    int pathFrame = 0;
    double recordStart = 0.0;                 // `clock` when the recording started

    // --path: where the loop's frames are computed from: the start, with what the path does not move as
    // it is now (a light dragged during a camera orbit).
    viz::scene::Pose loopStart(const viz::scene::Camera& camera, const std::vector<viz::scene::Light>& lights) const {
        viz::scene::Pose start = *pathStart;
        if (!path->movesCamera()) start.camera = camera;
        if (!path->movesLight()) start.lights = lights;
        return start;
    }
};

}  // namespace airlight
