#include "cpu_worker.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdio>
#include <exception>
#include <utility>
#include <vector>


namespace airlight {

using Clock = std::chrono::steady_clock;


void CpuWorker::loop(State& s) {
    for (;;) {
        Pending pending;
        {
            std::unique_lock lock(s.mutex);
            s.wake.wait(lock, [&] { return s.quit || s.request.has_value(); });
            if (s.quit) return;
            pending = std::move(*s.request);
            s.request.reset();
            // Busy from the moment the request is taken, under the same lock: progress() never sees a
            // moment with neither a request waiting nor a pass running while one is about to start.
            s.progress = CpuProgress{.busy = true};
            s.passStart = Clock::now();
            // Only this thread reads s.scene: it changes between requests, never under a running pass.
            if (s.nextScene) s.scene = std::move(*std::exchange(s.nextScene, std::nullopt));
        }
        runPasses(s, pending);
    }
}

void CpuWorker::runPasses(State& s, const Pending& pending) {
    const CpuRequest& request = pending.request;
    // Passes at 1/4, 1/2 and full resolution, skipping ones too small to be worth showing.
    std::vector<glm::ivec2> sizes;
    for (int div : {4, 2}) {
        if (request.width / div >= 32 && request.height / div >= 24) sizes.push_back({request.width / div, request.height / div});
    }
    sizes.push_back({request.width, request.height});
    s.scene.camera = request.camera;
    auto& technique = s.techniques[request.technique];
    for (std::size_t i = 0; i < sizes.size(); ++i) {
        {
            std::lock_guard lock(s.mutex);
            if (s.quit || s.request.has_value()) break;  // superseded
            s.progress = {true, int(i) + 1, int(sizes.size()), sizes[i], 0.0,
                          s.secondsPerPixel * double(sizes[i].x) * double(sizes[i].y)};
            s.passStart = Clock::now();
        }
        CpuResult result;
        result.technique = request.technique;
        result.ticket = pending.ticket;
        result.pass = int(i) + 1;
        result.passCount = int(sizes.size());
        try {
            if (!technique) technique = s.make ? s.make(request.technique) : viz::makeTechnique(request.technique);
            viz::FrameInput input;
            input.scene = &s.scene;
            input.width = sizes[i].x;
            input.height = sizes[i].y;
            viz::setRunSettings(input, request.settings);
            result.output = technique->run(input);
        } catch (const std::exception& e) {
            result.error = e.what();
        }
        std::lock_guard lock(s.mutex);
        const double seconds = std::chrono::duration<double>(Clock::now() - s.passStart).count();
        // A frame served from the reference's disk cache says nothing about the cost of the next.
        if (result.error.empty() && result.output.timing.clock != "cache") {
            s.secondsPerPixel = seconds / (double(sizes[i].x) * double(sizes[i].y));
        }
        // Still busy until the last pass has been stored (the loop's end says otherwise).
        const bool failed = !result.error.empty();
        s.result = std::move(result);
        // Wake the main thread out of glfwWaitEventsTimeout (thread-safe in GLFW). After quit the
        // window may be gone; holding the mutex keeps the two in order.
        if (!s.quit) glfwPostEmptyEvent();
        if (failed) break;
    }
    std::lock_guard lock(s.mutex);
    s.progress.busy = false;
}

}  // namespace airlight
