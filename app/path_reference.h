// The reference's L_air on every frame of the motion path the window plays (gui --path), for the
// temporal view against the reference (issue 19). A thread of its own renders the frames one at a time,
// from the frame shown when the loop was asked for onwards, wrapping; each is the reference technique's
// full run, so a frame already in the reference's disk cache (left by `animate` or `report --temporal` at
// the same size, or by an earlier play) costs a file read. The window asks only while a temporal view is
// shown: the reference is seconds a frame, and costs nothing when nobody looks.
//
// A loop is identified by its key (what every frame's scene depends on: geometry, medium, the path, its
// frame count, the pose where play started, the size and the reference's settings); asking for another
// key drops the frames of the last one and stops after the frame being rendered (a run cannot be
// interrupted).
#pragma once

#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "core/image.h"
#include "debug/technique.h"
#include "scene/motion_path.h"
#include "scene/scene.h"

namespace airlight {

struct PathLoop {
    std::string key;
    viz::scene::Scene scene;                 // as shown; each frame sets its pose's camera and lights
    std::vector<viz::scene::Pose> poses;     // one per frame of the loop
    int width = 0, height = 0;
    viz::Settings settings;                  // the window's for the reference (filtered on the worker)
};

// The loop of `path` over `frames` from `start` on `scene` (its camera and lights replaced by each pose).
PathLoop makePathLoop(const viz::scene::Scene& scene, const viz::scene::MotionPath& path, const viz::scene::Pose& start,
                      int frames, int width, int height, const viz::Settings& settings);

// What identifies a loop's frames: geometry (geometryKeyOf), medium, path, frames, start pose, size and
// settings.
std::string pathLoopKey(const viz::scene::Scene& scene, const viz::scene::MotionPath& path,
                        const viz::scene::Pose& start, int frames, int width, int height, const viz::Settings& settings);

class PathReference {
public:
    PathReference();
    ~PathReference();
    PathReference(const PathReference&) = delete;
    PathReference& operator=(const PathReference&) = delete;

    // The frames of this loop, rendered from `firstFrame` on. Nothing happens when it is the loop already
    // asked for (so the window may ask every frame); `loop` is only built when it is not (make()).
    template <typename Make>
    void follow(const std::string& key, int firstFrame, Make make) {
        if (key == currentKey()) return;
        PathLoop loop = make();
        loop.key = key;
        start(std::move(loop), firstFrame);
    }
    // Forgets the loop (play stopped, or no temporal view is shown); a frame being rendered is dropped.
    void stop();

    // The reference's L_air for frame `frame` of the loop `key`; null until it is rendered.
    std::shared_ptr<const viz::Image> frame(const std::string& key, int frame) const;
    // Frames of the current loop rendered, and in all (0 without a loop).
    int ready() const;
    int total() const;
    bool busy() const;          // a loop has frames left to render
    // Seconds the last frame computed (not read from the disk cache) took; 0 before one.
    double secondsPerFrame() const;
    std::string error() const;  // the reference's failure on the current loop ("" when none)
    std::string currentKey() const;

private:
    // Shared with the thread, so that a frame still rendering when the window closes (tv-room's area light
    // takes minutes) finishes on a detached thread without touching freed memory, as CpuWorker does.
    struct State {
        mutable std::mutex mutex;
        std::condition_variable wake;
        std::shared_ptr<const PathLoop> loop;  // the loop asked for (null: none)
        int next = 0;                          // the next frame to render
        int done = 0;                          // frames of the loop rendered
        std::map<int, std::shared_ptr<const viz::Image>> frames;
        std::string error;
        double secondsPerFrame = 0.0;
        bool quit = false, rendering = false;
        // The thread's own: the reference instance and the scene of the loop it renders.
        std::unique_ptr<viz::Technique> reference;
        std::shared_ptr<const PathLoop> sceneOf;
        viz::scene::Scene scene;
    };
    void start(PathLoop loop, int firstFrame);
    static void work(State& s);

    std::shared_ptr<State> mState;
    std::thread mThread;
};

}  // namespace airlight
