#include "path_reference.h"

#include <chrono>
#include <exception>
#include <sstream>
#include <utility>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "scene/scene_source.h"
#include "techniques/registry.h"
#include "window_common.h"
#include "worker_thread.h"

namespace airlight {

std::string pathLoopKey(const viz::scene::Scene& scene, const viz::scene::MotionPath& path,
                        const viz::scene::Pose& start, int frames, int width, int height, const viz::Settings& settings) {
    // The start pose, the medium and every light's properties through the scene hash of a scene without
    // geometry (the geometry's own hash stands for it).
    viz::scene::Scene posed;
    posed.medium = scene.medium;
    viz::scene::applyPose(start, posed);
    std::ostringstream key;
    key.precision(17);
    key << "geometry " << viz::scene::geometryKeyOf(scene) << " pose " << viz::scene::sceneContentHash(posed) << " path "
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

PathReference::PathReference() : mState(std::make_shared<State>()) {
    mThread = std::thread([state = mState] { work(*state); });
}

PathReference::~PathReference() {
    endWorker(mThread, mState->mutex, mState->wake, mState->quit, mState->rendering, "a reference frame of the path");
}

void PathReference::start(PathLoop loop, int firstFrame) {
    {
        std::lock_guard lock(mState->mutex);
        const int n = int(loop.poses.size());
        mState->loop = std::make_shared<const PathLoop>(std::move(loop));
        mState->next = n > 0 ? ((firstFrame % n) + n) % n : 0;
        mState->done = 0;
        mState->frames.clear();
        mState->error.clear();
    }
    mState->wake.notify_all();
}

void PathReference::stop() {
    std::lock_guard lock(mState->mutex);
    mState->loop.reset();
    mState->frames.clear();
    mState->done = 0;
    mState->error.clear();
}

std::shared_ptr<const viz::Image> PathReference::frame(const std::string& key, int frame) const {
    std::lock_guard lock(mState->mutex);
    if (!mState->loop || mState->loop->key != key) return nullptr;
    const auto it = mState->frames.find(frame);
    return it == mState->frames.end() ? nullptr : it->second;
}

int PathReference::ready() const {
    std::lock_guard lock(mState->mutex);
    return mState->loop ? mState->done : 0;
}

int PathReference::total() const {
    std::lock_guard lock(mState->mutex);
    return mState->loop ? int(mState->loop->poses.size()) : 0;
}

bool PathReference::busy() const {
    std::lock_guard lock(mState->mutex);
    return mState->loop && mState->error.empty() && mState->done < int(mState->loop->poses.size());
}

double PathReference::secondsPerFrame() const {
    std::lock_guard lock(mState->mutex);
    return mState->secondsPerFrame;
}

std::string PathReference::error() const {
    std::lock_guard lock(mState->mutex);
    return mState->error;
}

std::string PathReference::currentKey() const {
    std::lock_guard lock(mState->mutex);
    return mState->loop ? mState->loop->key : std::string();
}

void PathReference::work(State& s) {
    for (;;) {
        std::shared_ptr<const PathLoop> job;
        int index = 0;
        {
            std::unique_lock lock(s.mutex);
            s.wake.wait(lock, [&] { return s.quit || (s.loop && s.error.empty() && s.done < int(s.loop->poses.size())); });
            if (s.quit) return;
            job = s.loop;
            index = s.next;
            s.rendering = true;
        }
        std::shared_ptr<viz::Image> airlight;
        std::string error;
        bool computed = false;
        const auto started = std::chrono::steady_clock::now();
        try {
            if (!s.reference) s.reference = viz::makeTechnique("reference");
            // One copy of the scene per loop; each frame only sets the camera and lights.
            if (s.sceneOf != job) {
                s.scene = job->scene;
                s.sceneOf = job;
            }
            viz::scene::applyPose(job->poses[std::size_t(index)], s.scene);
            // The window's settings for the reference, less the names only other techniques have (the
            // difference views read them the same way); a value out of range is the frame's error.
            std::string invalid;
            const viz::Settings settings = settingsFor(*s.reference, job->settings, invalid);
            if (!invalid.empty()) throw viz::InputError(invalid);
            const viz::FrameInput input = viz::frameInput(&s.scene, job->width, job->height, settings);
            viz::FrameOutput out = s.reference->run(input);
            computed = out.timing.clock != "cache";
            airlight = std::make_shared<viz::Image>(std::move(out.airlight));
        } catch (const std::exception& e) {
            error = e.what();
        }
        std::lock_guard lock(s.mutex);
        s.rendering = false;
        // A frame read from the cache says nothing about the cost of the next one to compute.
        if (computed) s.secondsPerFrame = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        if (s.loop != job) continue;  // another loop was asked for meanwhile: this frame is not its
        if (!error.empty()) {
            s.error = error;
        } else {
            s.frames[index] = std::move(airlight);
            ++s.done;
            s.next = (index + 1) % int(job->poses.size());
        }
        // Wake the window out of glfwWaitEventsTimeout; after quit it may be gone (the mutex orders the two).
        if (!s.quit) glfwPostEmptyEvent();
    }
}

}  // namespace airlight
