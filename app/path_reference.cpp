#include "path_reference.h"

#include <exception>
#include <sstream>
#include <utility>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "scene/scene_source.h"
#include "techniques/registry.h"
#include "window_common.h"

namespace airlight {

std::string pathLoopKey(std::uint64_t geometryHash, const viz::scene::Scene& scene, const viz::scene::MotionPath& path,
                        const viz::scene::Pose& start, int frames, int width, int height, const viz::Settings& settings) {
    // The start pose, the medium and every light's properties through the scene hash of a scene without
    // geometry (the geometry's own hash stands for it).
    viz::scene::Scene posed;
    posed.medium = scene.medium;
    viz::scene::applyPose(start, posed);
    std::ostringstream key;
    key.precision(17);
    key << "geometry " << geometryHash << " pose " << viz::scene::sceneContentHash(posed) << " path "
        << viz::scene::describeMotionPath(path) << " frames " << frames << " size " << width << "x" << height;
    for (const auto& [name, value] : settings) key << " " << name << "=" << value;
    return key.str();
}

PathLoop makePathLoop(const viz::scene::Scene& scene, const viz::scene::MotionPath& path, const viz::scene::Pose& start,
                      int frames, int width, int height, const viz::Settings& settings) {
    PathLoop loop;
    loop.scene = scene;
    // Each frame's pose is the path's function of the start, as the window plays it.
    viz::scene::applyPose(start, loop.scene);
    for (int i = 0; i < frames; ++i) loop.poses.push_back(viz::scene::poseAt(path, loop.scene, i, frames));
    loop.width = width;
    loop.height = height;
    loop.settings = settings;
    return loop;
}

PathReference::PathReference() : mThread([this] { loop(); }) {}

PathReference::~PathReference() {
    {
        std::lock_guard lock(mMutex);
        mQuit = true;
    }
    mWake.notify_all();
    mThread.join();  // a reference frame being rendered finishes first (seconds at most)
}

void PathReference::start(PathLoop loop, int firstFrame) {
    {
        std::lock_guard lock(mMutex);
        const int n = int(loop.poses.size());
        mLoop = std::make_shared<const PathLoop>(std::move(loop));
        mNext = n > 0 ? ((firstFrame % n) + n) % n : 0;
        mDone = 0;
        mFrames.clear();
        mError.clear();
    }
    mWake.notify_all();
}

void PathReference::stop() {
    std::lock_guard lock(mMutex);
    mLoop.reset();
    mFrames.clear();
    mDone = 0;
    mError.clear();
}

std::shared_ptr<const viz::Image> PathReference::frame(const std::string& key, int frame) const {
    std::lock_guard lock(mMutex);
    if (!mLoop || mLoop->key != key) return nullptr;
    const auto it = mFrames.find(frame);
    return it == mFrames.end() ? nullptr : it->second;
}

int PathReference::ready() const {
    std::lock_guard lock(mMutex);
    return mLoop ? mDone : 0;
}

int PathReference::total() const {
    std::lock_guard lock(mMutex);
    return mLoop ? int(mLoop->poses.size()) : 0;
}

bool PathReference::busy() const {
    std::lock_guard lock(mMutex);
    return mLoop && mError.empty() && mDone < int(mLoop->poses.size());
}

std::string PathReference::error() const {
    std::lock_guard lock(mMutex);
    return mError;
}

std::string PathReference::currentKey() const {
    std::lock_guard lock(mMutex);
    return mLoop ? mLoop->key : std::string();
}

void PathReference::loop() {
    for (;;) {
        std::shared_ptr<const PathLoop> job;
        int index = 0;
        {
            std::unique_lock lock(mMutex);
            mWake.wait(lock, [&] { return mQuit || (mLoop && mError.empty() && mDone < int(mLoop->poses.size())); });
            if (mQuit) return;
            job = mLoop;
            index = mNext;
        }
        std::shared_ptr<viz::Image> airlight;
        std::string error;
        try {
            if (!mReference) mReference = viz::makeTechnique("reference");
            // One copy of the scene per loop; each frame only sets the camera and lights.
            if (mSceneOf != job) {
                mScene = job->scene;
                mSceneOf = job;
            }
            viz::scene::applyPose(job->poses[std::size_t(index)], mScene);
            // The window's settings for the reference, less the names only other techniques have (the
            // difference views read them the same way); a value out of range is the frame's error.
            std::string invalid;
            const viz::Settings settings = settingsFor(*mReference, job->settings, invalid);
            if (!invalid.empty()) throw viz::InputError(invalid);
            const viz::FrameInput input = viz::frameInput(&mScene, job->width, job->height, settings);
            airlight = std::make_shared<viz::Image>(mReference->run(input).airlight);
        } catch (const std::exception& e) {
            error = e.what();
        }
        std::lock_guard lock(mMutex);
        if (mLoop != job) continue;  // another loop was asked for meanwhile: this frame is not its
        if (!error.empty()) {
            mError = error;
        } else {
            mFrames[index] = std::move(airlight);
            ++mDone;
            mNext = (index + 1) % int(job->poses.size());
        }
        if (!mQuit) glfwPostEmptyEvent();  // the window may be waiting for events
    }
}

}  // namespace airlight
