// Runs CPU techniques (the reference) on a worker thread in passes of growing resolution, so the window
// never freezes while a slow technique renders.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>

#include <glm/glm.hpp>

#include "debug/technique.h"
#include "scene/scene.h"
#include "techniques/registry.h"
#include "worker_thread.h"

namespace airlight {

struct CpuRequest {
    std::string technique;
    viz::scene::Camera camera;
    viz::Settings settings;
    int width = 0, height = 0;
};

struct CpuResult {
    std::string technique;
    std::uint64_t ticket = 0;  // submit()'s for the request it answers
    viz::FrameOutput output;
    int pass = 0, passCount = 1;
    std::string error;
};

struct CpuProgress {
    bool busy = false;  // a pass is running, or a request waits for the thread to take it
    int pass = 0, passCount = 1;
    glm::ivec2 size{0};
    double elapsed = 0.0;   // seconds in this pass
    double estimate = 0.0;  // expected seconds for this pass, 0 = unknown
};

// "starting" while a request waits for its first pass, else "pass 2/3".
inline std::string passText(const CpuProgress& p) {
    return p.pass == 0 ? std::string("starting") : "pass " + std::to_string(p.pass) + "/" + std::to_string(p.passCount);
}

// Runs one CPU technique at a time in passes of growing resolution. A new request supersedes the
// pending one and stops the running one after its current pass (Technique::run cannot be
// interrupted): that pass's result still arrives, with the ticket of the request it answers, so a
// consumer compares it with its latest submit() and drops what a later request superseded. The state
// lives in a shared_ptr so that a pass still running at exit can finish on a detached thread without
// touching freed memory.
class CpuWorker {
public:
    // `make`: what makes the technique a request names (null: the registry; tests pass their own).
    explicit CpuWorker(const viz::scene::Scene& scene, viz::TechniqueMaker make = nullptr)
        : mState(std::make_shared<State>()) {
        mState->scene = scene;
        mState->make = std::move(make);
        mThread = std::thread([state = mState] { loop(*state); });
    }
    ~CpuWorker() {
        endWorker(mThread, mState->mutex, mState->wake, mState->quit, mState->progress.busy, "a reference pass");
    }
    CpuWorker(const CpuWorker&) = delete;
    CpuWorker& operator=(const CpuWorker&) = delete;

    // Replaces the worker's copy of the scene (medium, lights) for the requests that follow; a pass
    // already running finishes with the scene it started with. Cheaper and safer than a new worker per
    // edit: a busy worker cannot be stopped mid-pass, so replacing it would leave its pass running on.
    void setScene(const viz::scene::Scene& scene) {
        std::lock_guard lock(mState->mutex);
        mState->nextScene = scene;
    }

    // Returns the request's ticket: increasing, never 0; the results of its passes carry it.
    std::uint64_t submit(CpuRequest request) {
        std::uint64_t ticket = 0;
        {
            std::lock_guard lock(mState->mutex);
            ticket = ++mState->lastTicket;
            mState->request = Pending{std::move(request), ticket};
        }
        mState->wake.notify_all();
        return ticket;
    }
    std::optional<CpuResult> take() {
        std::lock_guard lock(mState->mutex);
        return std::exchange(mState->result, std::nullopt);
    }
    CpuProgress progress() const {
        std::lock_guard lock(mState->mutex);
        CpuProgress p = mState->progress;
        if (!p.busy && mState->request) return CpuProgress{.busy = true};  // taken by the thread soon
        if (p.busy) p.elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - mState->passStart).count();
        return p;
    }

private:
    struct Pending {
        CpuRequest request;
        std::uint64_t ticket = 0;
    };
    struct State {
        viz::scene::Scene scene;  // the worker's own copy; the camera comes with each request
        std::optional<viz::scene::Scene> nextScene;  // setScene's, taken with the next request
        std::map<std::string, std::unique_ptr<viz::Technique>> techniques;
        mutable std::mutex mutex;
        std::condition_variable wake;
        viz::TechniqueMaker make;
        std::optional<Pending> request;
        std::uint64_t lastTicket = 0;
        std::optional<CpuResult> result;
        CpuProgress progress;
        std::chrono::steady_clock::time_point passStart;
        double secondsPerPixel = 0.0;  // from the last finished pass, for the estimate
        bool quit = false;
    };

    static void loop(State& s);
    static void runPasses(State& s, const Pending& pending);

    std::shared_ptr<State> mState;
    std::thread mThread;
};

}  // namespace airlight
