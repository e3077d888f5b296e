// The window's animation (P): play and pause, each frame's step (the light's orbit, the clock, the
// --path loop's frames) and the reference's frames of the loop for the temporal views and the grid.
#include "gui_app.h"

namespace airlight {

void GuiApp::togglePlaying() {
    mAnimation.playing = !mAnimation.playing;
    mAnimation.temporal.reset();  // the temporal view measures from the frame play starts on
    if (!mAnimation.playing) {
        if (mComparison.isOpen()) mComparison.stopPlaying(comparisonRunner());  // back to the still frame
        mAnimation.reference.stop();
        stopRecording();
        // A CPU technique kept its still frame while playing (render), and difference views against one
        // kept its last image: both are asked again for the frame as play leaves it.
        mDirty = true;
        return;
    }
    mAnimation.light.reset();
    if (mAnimation.path) {
        // Every frame is the path's function of where play starts: the camera and lights as they are now.
        // Playing again after a pause continues the loop, unless the camera or the lights were moved in
        // between: then the loop starts again from there.
        if (!mAnimation.pathStart || !mAnimation.pathShown || mAnimation.pathScene != mScene.geometryKey ||
            !samePose(*mAnimation.pathShown, mController.camera(), mScene.lights))
            startPathLoop();
        return;
    }
    if (!mScene.lights.empty() && mScene.lights[0].type != viz::scene::LightType::Area) {
        mAnimation.light = mScene.lights[0];
        mAnimation.centre = mController.target();
        mAnimation.turn = 0.0;
    }
}

void GuiApp::advanceAnimation(double dt) {
    mAnimation.clock += dt;
    ++mAnimation.frame;
    if (technique().readsFrame(mState.settings)) mDirty = true;  // its noise changes every frame
    if (technique().controls().animationTime) {
        mState.settings[viz::kAnimationTime] = mAnimation.clock;
        mDirty = true;
    }
    // A path moves what every technique sees; the reference (seconds per frame on its worker) keeps the
    // still frame, as with the light's orbit, unless the comparison grid plays.
    if (mAnimation.path && mAnimation.pathStart && (technique().needsGl() || mComparison.isOpen())) {
        // Another scene loaded while playing: the loop starts again from it.
        if (mAnimation.pathScene != mScene.geometryKey) startPathLoop();
        // 30 path frames per second of play (under automation, one per window frame).
        const int frame = int(std::llround((mAnimation.clock - mAnimation.pathClock) * 30.0) % mAnimation.pathFrames);
        if (frame != mAnimation.pathFrame) playPathFrame(frame);
    }
    if (mAnimation.light && (technique().needsGl() || mComparison.isOpen()) && !mScene.lights.empty()) {
        mAnimation.turn = std::fmod(mAnimation.turn + dt / kLightTurnSeconds, 1.0);
        mScene.lights[0] = orbitLight(*mAnimation.light, mAnimation.centre, mAnimation.turn);
        mDirty = true;
    }
    // The comparison grid plays the same frame for every technique.
    if (mComparison.isOpen())
        mComparison.playFrame(mScene, mAnimation.frame, comparisonRunner(), mAnimation.path && mAnimation.path->movesCamera(),
                              pathReferenceFrame(true));
}

void GuiApp::startPathLoop() {
    mAnimation.pathStart = viz::scene::Pose{mController.camera(), mScene.lights};
    mAnimation.pathShown.reset();
    mAnimation.pathScene = mScene.geometryKey;
    mAnimation.centre = mController.target();
    mAnimation.pathClock = mAnimation.clock;
    mAnimation.pathFrame = 0;
}

void GuiApp::playPathFrame(int frame) {
    // What the path does not move stays as the user leaves it while playing (a light dragged during a
    // camera orbit); what it moves is its function of the start.
    viz::scene::applyPose(mAnimation.loopStart(mController.camera(), mScene.lights), mScene);
    try {
        const viz::scene::Pose pose = viz::scene::poseAt(*mAnimation.path, mScene, frame, mAnimation.pathFrames);
        viz::scene::applyPose(pose, mScene);
        if (mAnimation.path->movesCamera()) mController.place(pose.camera, mAnimation.centre);
        mAnimation.pathFrame = frame;
        mAnimation.pathShown = viz::scene::Pose{mController.camera(), mScene.lights};
    } catch (const viz::InputError& e) {
        // A scene picked or reloaded since start that the path cannot move: play stops, saying why.
        mError = "--path: " + std::string(e.what());
        mAnimation.playing = false;
        mAnimation.pathStart.reset();
        mAnimation.pathShown.reset();
    }
    mDirty = true;
}

std::shared_ptr<const viz::Image> GuiApp::pathReferenceFrame(bool forGrid) {
    // One loop's reference frames are rendered at a time: the comparison grid's while it is open (its
    // tiles score their flicker), else the main views' while a temporal view is shown; nothing when
    // nobody looks (the reference is seconds a frame).
    const std::vector<std::string> shown = shownContents();
    const bool temporalShown = std::find(shown.begin(), shown.end(), kTemporalChangeId) != shown.end() ||
                               std::find(shown.begin(), shown.end(), kTemporalErrorChangeId) != shown.end();
    if (!mAnimation.playing || !mAnimation.path || !mAnimation.pathStart || !(temporalShown || mComparison.isOpen())) {
        mAnimation.reference.stop();
        return nullptr;
    }
    // The frame shown is one of the loop's only while nothing moved it since the path set it.
    if (!mAnimation.pathShown || !samePose(*mAnimation.pathShown, mController.camera(), mScene.lights)) return nullptr;
    // The main views' loop at the full size (a reduced frame while dragging has none and keeps the loop
    // going); the grid's at its size, seen from its own camera unless the path moves the camera.
    const viz::scene::Pose start = mAnimation.loopStart(mController.camera(), mScene.lights);
    viz::scene::Pose gridStart = start;
    if (mComparison.isOpen() && !mAnimation.path->movesCamera()) gridStart.camera = mComparison.scene().camera;
    const glm::ivec2 size = mState.size;
    const glm::ivec2 gridSize = mComparison.isOpen() ? mComparison.size() : size;
    const viz::Settings settings = givenSettings("reference");
    const auto keyOf = [&](const viz::scene::Pose& from, glm::ivec2 at) {
        return pathLoopKey(mScene, *mAnimation.path, from, mAnimation.pathFrames, at.x, at.y, settings);
    };
    const bool gridDrives = mComparison.isOpen();
    const viz::scene::Pose& wantedStart = gridDrives ? gridStart : start;
    const glm::ivec2 wantedSize = gridDrives ? gridSize : size;
    const std::string wantedKey = keyOf(wantedStart, wantedSize);
    mAnimation.reference.follow(wantedKey, mAnimation.pathFrame, [&] {
        return makePathLoop(mScene, *mAnimation.path, wantedStart, mAnimation.pathFrames, wantedSize.x, wantedSize.y, settings);
    });
    // The other consumer has frames only where its loop is the same one.
    const std::string key = forGrid == gridDrives ? wantedKey : forGrid ? keyOf(gridStart, gridSize) : keyOf(start, size);
    return mAnimation.reference.frame(key, mAnimation.pathFrame);
}

}  // namespace airlight
