#include "difference_runs.h"

#include <cstdio>
#include <utility>

#include <epoxy/gl.h>

#include "core/text.h"
#include "scene/scene_source.h"

namespace airlight {

std::string sceneKey(const viz::scene::Scene& scene) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "%016llx %.17g %.17g %.17g",
                  static_cast<unsigned long long>(viz::scene::geometryKeyOf(scene)),
                  scene.medium.sigma_s, scene.medium.sigma_a, scene.medium.g);
    std::string key = buf;
    for (const auto& l : scene.lights)
        for (const double x : {l.position.x, l.position.y, l.position.z, l.direction.x, l.direction.y,
                               l.direction.z, l.intensity, l.colour.x, l.colour.y, l.colour.z}) {
            key += ' ';  // appended apart: GCC 12 at -O3 warns (-Wrestrict) on " " + a temporary here
            key += viz::format("%.17g", x);
        }
    return key;
}

std::string runKey(const std::string& id, const DifferenceRequest& request) {
    // The scene's key holds its geometry too, so a file reloaded with a moved mesh but the same lights does
    // not keep the old image.
    std::string key = id + " " + std::to_string(request.size.x) + "x" + std::to_string(request.size.y);
    const viz::scene::Camera& c = request.camera;
    char buf[512];
    std::snprintf(buf, sizeof buf, " %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g", c.position.x,
                  c.position.y, c.position.z, c.forward.x, c.forward.y, c.forward.z, c.up.x, c.up.y, c.up.z, c.yfov);
    key += buf;
    key += " " + sceneKey(*request.scene);
    for (const auto& [name, value] : request.settings) key += " " + name + "=" + viz::format("%.17g", value);
    return key;
}

const DifferenceRuns::Run* DifferenceRuns::get(const std::string& id, const DifferenceRequest& request) {
    const std::string key = runKey(id, request);
    Run& run = mRuns[id];
    run.held = false;
    if (run.key == key) return &run;
    RunScheduler* runner = nullptr;
    try {
        runner = &runnerFor(id);
    } catch (const std::exception& e) {
        run = Run{.key = key, .failure = e.what()};
        return &run;
    }
    if (run.pending == key) return nullptr;
    if (request.hold && !runner->technique().needsGl() && (!run.pending.empty() || !run.key.empty())) {
        // The pass under way finishes for the request it has; until then nothing, after it that.
        if (run.key.empty()) return nullptr;
        run.held = true;
        return &run;
    }
    run.pending = key;
    if (runner->technique().needsGl()) {
        mDue = true;
        return nullptr;
    }
    // The worker keeps its own copy of the scene: handed the new one when the medium, lights or geometry
    // changed.
    const std::string scene = sceneKey(*request.scene);
    if (!mWorker) mWorker = &mPool.worker(Worker::Differences, *request.scene);
    else if (mWorkerSceneKey != scene) mWorker->setScene(*request.scene);
    mWorkerSceneKey = scene;
    run.ticket = mWorker->submit({id, request.camera, request.settings, request.size.x, request.size.y});
    return nullptr;
}

std::vector<std::string> DifferenceRuns::runDue(const std::function<DifferenceRequest(const std::string&)>& current) {
    mDue = false;
    std::vector<std::string> done;
    for (auto& [id, run] : mRuns) {
        if (run.pending.empty()) continue;
        RunScheduler* runner = nullptr;
        try {
            runner = &runnerFor(id);
        } catch (const std::exception&) {
            continue;  // get() recorded the failure when it asked
        }
        if (!runner->technique().needsGl()) continue;
        const DifferenceRequest request = current(id);
        const std::string key = std::exchange(run.pending, std::string());
        if (key != runKey(id, request)) continue;  // stale: the next get asks again
        run = Run{.key = key};
        try {
            viz::scene::Scene scene = *request.scene;
            scene.camera = request.camera;
            viz::FrameOutput out = runner->run(scene, request.size.x, request.size.y, request.settings, {}, {}, 0);
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            run.airlight = std::move(out.airlight);
            run.final = std::move(out.final);
        } catch (const std::exception& e) {
            run.failure = e.what();
        }
        done.push_back(id);
    }
    return done;
}

std::optional<std::string> DifferenceRuns::poll() {
    if (!mWorker) return std::nullopt;
    std::optional<CpuResult> result = mWorker->take();
    if (!result || (result->error.empty() && result->pass < result->passCount)) return std::nullopt;
    auto it = mRuns.find(result->technique);
    // A pass of a request that a later one superseded (the camera moved while it ran) is not the pending
    // run's: its images would be kept under the new key. The superseding request's passes follow.
    if (it == mRuns.end() || it->second.pending.empty() || result->ticket != it->second.ticket) return std::nullopt;
    Run& run = it->second;
    run.key = std::exchange(run.pending, std::string());
    run.failure = result->error;
    run.airlight = std::move(result->output.airlight);
    run.final = std::move(result->output.final);
    return result->technique;
}

bool DifferenceRuns::pending() const {
    for (const auto& [id, run] : mRuns)
        if (!run.pending.empty()) return true;
    return false;
}

}  // namespace airlight
