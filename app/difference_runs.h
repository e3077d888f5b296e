// The other side of the window's difference views: one technique's L_air and final image for the window's
// scene, camera and size, kept until any of those or the technique's settings change. CPU techniques (the
// reference, from its on-disk cache when it has the frame) run on a worker thread of their own, so that
// the window stays responsive: nothing until their full-size pass arrives (poll). GPU techniques need the
// window's GL context: they are queued and run by runDue at the start of the next frame, after a frame
// that says so, as the window does for a slow run of its own technique.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "cpu_worker.h"
#include "run_pool.h"
#include "run_scheduler.h"
#include "scene/scene.h"

namespace airlight {

// What a run of one technique depends on, as the window sees it now.
struct DifferenceRequest {
    const viz::scene::Scene* scene = nullptr;  // medium, lights, geometry (the camera is `camera`)
    viz::scene::Camera camera;
    glm::ivec2 size{0};
    viz::Settings settings;  // complete: the technique's defaults under the session's and the command line's
    // The window's animation plays: a CPU technique is not asked again for every played frame (each
    // request would supersede the last before any pass finished); its last image stands, as Run::held.
    bool hold = false;
};

// The medium, lights and geometry (geometryKeyOf: the window's scene is stamped, a reloaded file with
// moved geometry has another key): what a CPU worker's scene copy depends on besides the camera.
std::string sceneKey(const viz::scene::Scene& scene);

// Everything a run depends on: technique, size, camera, scene and settings.
std::string runKey(const std::string& id, const DifferenceRequest& request);

class DifferenceRuns {
public:
    struct Run {
        std::string key{};  // the request it was run for
        viz::Image airlight{}, final{};
        std::string failure{};
        std::string pending{};  // the key of the run being computed (worker or queue)
        std::uint64_t ticket = 0;  // the worker's for `pending` (CPU runs): a superseded request's pass is not it
        bool held = false;  // get() returned it for a different request (DifferenceRequest::hold)
    };
    // Runs with the pool's instances for Consumer::Others (shared with the comparison grid) and its
    // Worker::Differences thread.
    explicit DifferenceRuns(RunPool& pool) : mPool(pool) {}

    // `id`'s images for `request`: kept ones when the request is the same, a failure when the technique
    // cannot be made, otherwise null while they are computed (started here, or queued for runDue). With
    // `request.hold`, a CPU technique's last images (held) once it has some.
    const Run* get(const std::string& id, const DifferenceRequest& request);

    // GPU runs are queued: the window runs them on its next frame.
    bool due() const { return mDue; }
    // Runs the queued GPU techniques whose request still holds (`current(id)`: the request now; a stale
    // one is dropped and asked again by the next get). Binds framebuffer 0 after each. Returns the ids
    // that have new images (or a failure).
    std::vector<std::string> runDue(const std::function<DifferenceRequest(const std::string&)>& current);
    // The worker's finished full-size pass, if one arrived: the id it belongs to.
    std::optional<std::string> poll();
    // Whether any run is being computed or queued.
    bool pending() const;

private:
    RunScheduler& runnerFor(const std::string& id) { return mPool.runner(Consumer::Others, id); }

    RunPool& mPool;
    std::map<std::string, Run> mRuns;  // by technique id
    CpuWorker* mWorker = nullptr;  // the pool's, once a CPU technique was asked for
    std::string mWorkerSceneKey;
    bool mDue = false;
};

}  // namespace airlight
