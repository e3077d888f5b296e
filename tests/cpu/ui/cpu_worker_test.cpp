// The window's CPU worker (app/cpu_worker.h): a scene set with setScene is the one the next request
// renders, and the result equals a direct run of the technique on that scene.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "cpu_worker.h"
#include "scene/builtin_scenes.h"
#include "techniques/registry.h"

namespace airlight {
namespace {

// Submits and waits for the full-size pass.
CpuResult renderAll(CpuWorker& worker, const viz::scene::Scene& scene, int w, int h) {
    const auto reference = viz::makeTechnique("reference");
    worker.submit({"reference", scene.camera, viz::completeSettings(*reference, {}), w, h});
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(5);
    while (std::chrono::steady_clock::now() < deadline) {
        if (auto r = worker.take(); r && (!r->error.empty() || r->pass == r->passCount)) return std::move(*r);
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    ADD_FAILURE() << "the worker did not finish";
    return {};
}

viz::Image direct(const viz::scene::Scene& scene, int w, int h) {
    auto t = viz::makeTechnique("reference");
    viz::FrameInput in = viz::frameInput(&scene, w, h, viz::completeSettings(*t, {}));
    return t->run(in).airlight;
}

TEST(CpuWorker, SetSceneChangesWhatTheNextRequestRenders) {
    const int w = 16, h = 12;
    viz::scene::Scene a = viz::scene::makeBuiltinScene("grate");
    viz::scene::Scene b = a;
    b.medium.sigma_s *= 2.0;
    b.lights[0].direction = glm::normalize(b.lights[0].direction + glm::dvec3(0.3, 0.0, 0.0));
    CpuWorker worker(a);
    const CpuResult first = renderAll(worker, a, w, h);
    ASSERT_EQ(first.error, "");
    worker.setScene(b);
    const CpuResult second = renderAll(worker, b, w, h);
    ASSERT_EQ(second.error, "");
    const viz::Image expectA = direct(a, w, h), expectB = direct(b, w, h);
    ASSERT_EQ(second.output.airlight.pixels.size(), expectB.pixels.size());
    double differs = 0.0;
    for (std::size_t i = 0; i < expectB.pixels.size(); ++i) {
        EXPECT_EQ(first.output.airlight.pixels[i], expectA.pixels[i]) << i;
        EXPECT_EQ(second.output.airlight.pixels[i], expectB.pixels[i]) << i;
        differs += std::abs(double(expectB.pixels[i]) - double(expectA.pixels[i]));
    }
    EXPECT_GT(differs, 0.0) << "the two scenes give different images";
}

}  // namespace
}  // namespace airlight
