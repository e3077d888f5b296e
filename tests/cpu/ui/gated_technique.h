// A fake CPU technique for the window's run tests: each pass waits at a gate until the test lets it go,
// so a test can hold a pass while it submits the next request; its image is the camera's x, so every
// image names the request it was rendered for.
#pragma once

#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "cpu_worker.h"
#include "cpu/ui/fake_technique.h"

namespace airlight::testing {

using namespace std::chrono_literals;

// Passes wait here until the test lets them go, one by one.
struct Gate {
    std::mutex mutex;
    std::condition_variable changed;
    int entered = 0, released = 0;

    void pass() {
        std::unique_lock lock(mutex);
        const int me = ++entered;
        changed.notify_all();
        changed.wait(lock, [&] { return released >= me; });
    }
    // Waits (up to 20 s) until `n` passes have entered.
    bool waitEntered(int n) {
        std::unique_lock lock(mutex);
        return changed.wait_for(lock, 20s, [&] { return entered >= n; });
    }
    void release() {
        std::lock_guard lock(mutex);
        ++released;
        changed.notify_all();
    }
};

class GatedTechnique : public FakeTechnique {
public:
    explicit GatedTechnique(std::shared_ptr<Gate> gate) : FakeTechnique("gated", "waits for the test"), mGate(std::move(gate)) {
        mStages = {{"gated.all", "All", "", {}, {}, 1}};
    }
    viz::FrameOutput run(const viz::FrameInput& in) override {
        mGate->pass();
        viz::FrameOutput out;
        out.airlight = viz::Image(in.width, in.height, 3);
        for (float& v : out.airlight.pixels) v = float(in.scene->camera.position.x);
        out.final = out.airlight;
        return out;
    }

private:
    std::shared_ptr<Gate> mGate;
};

inline viz::scene::Camera cameraAt(double x) {
    viz::scene::Camera c;
    c.position = {x, 0.0, 0.0};
    return c;
}

// Takes the worker's next result (up to 20 s).
inline std::optional<CpuResult> nextResult(CpuWorker& worker) {
    for (auto start = std::chrono::steady_clock::now(); std::chrono::steady_clock::now() - start < 20s;) {
        if (auto r = worker.take()) return r;
        std::this_thread::sleep_for(1ms);
    }
    return std::nullopt;
}

// Makes gated techniques (for a worker or a pool).
inline viz::TechniqueMaker gatedMaker(std::shared_ptr<Gate> gate) {
    return [gate](const std::string&) { return std::make_unique<GatedTechnique>(gate); };
}

}  // namespace airlight::testing
