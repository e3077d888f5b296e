// gl::GpuTimer's mechanics (its times mean nothing on llvmpipe, where timer queries do not measure the
// work): a run timed by it records the same stages as one timed by the technique's own clock, each with
// the latest time known for it (the first run waits for its own); runs after it wait for nothing beyond
// the ring's bound; once the GPU is done every waiting result is read; nested stages are both timed.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "gl/gl_test_fixture.h"
#include "gl/gpu_timer.h"
#include "scene/builtin_scenes.h"
#include "techniques/registry.h"

namespace viz::testing {
namespace {

class GpuTimerTest : public gl::GlTest {};

std::vector<std::string> stageNames(const FrameOutput& out) {
    std::vector<std::string> names;
    for (const StageTiming& s : out.timing.stages) names.push_back(s.stage);
    return names;
}

TEST_F(GpuTimerTest, ARunRecordsEveryStageWithTheLatestTimeKnownAndWaitsForNoMoreThanTheRing) {
    const scene::Scene scene = scene::makeBuiltinScene("grate");
    auto technique = makeTechnique("raymarch");
    const Settings settings = completeSettings(*technique, {{"samples", 8.0}});
    const FrameOutput own = technique->run(frameInput(&scene, 40, 30, settings));

    constexpr std::size_t kRing = 6;
    gl::GpuTimer timer(kRing);
    FrameInput input = frameInput(&scene, 40, 30, settings);
    input.timer = &timer;
    const FrameOutput first = technique->run(input);
    EXPECT_EQ(first.timing.clock, timer.name());
    EXPECT_EQ(stageNames(first), stageNames(own));
    for (const StageTiming& s : first.timing.stages) {
        EXPECT_TRUE(std::isfinite(s.milliseconds) && s.milliseconds >= 0.0) << s.stage;
        EXPECT_EQ(s.milliseconds, timer.latest(s.stage)) << s.stage;
    }
    // The image is the technique's, whatever times it.
    ASSERT_EQ(first.airlight.pixels, own.airlight.pixels);

    for (int k = 0; k < 12; ++k) {
        const FrameOutput later = technique->run(input);
        EXPECT_EQ(stageNames(later), stageNames(own));
        EXPECT_LE(timer.waiting(), kRing);
        for (const StageTiming& s : later.timing.stages)
            EXPECT_TRUE(std::isfinite(s.milliseconds) && s.milliseconds >= 0.0) << s.stage;
    }
    glFinish();
    timer.poll();
    EXPECT_EQ(timer.waiting(), 0u);
}

TEST_F(GpuTimerTest, NestedStagesAreBothTimedTheInnerWithinTheOuter) {
    gl::GpuTimer timer;
    timer.begin();
    timer.begin();
    const StageTiming inner = timer.end("inner");
    const StageTiming outer = timer.end("outer");
    glFinish();
    timer.poll();
    EXPECT_EQ(inner.stage, "inner");
    EXPECT_EQ(outer.stage, "outer");
    EXPECT_GE(timer.latest("inner"), 0.0);
    EXPECT_GE(timer.latest("outer"), timer.latest("inner"));
}

}  // namespace
}  // namespace viz::testing
