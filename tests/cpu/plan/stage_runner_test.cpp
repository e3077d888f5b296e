// The stage runner (debug/stage_runner.h) on a made-up list of four stages: each stage's work runs once
// and is timed by the run's clock, the run stops where it is asked to, a resumed run carries over the
// stages that keep their outputs (republishing what they published) and runs again those that do not,
// and stage indices come from the declared order.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "debug/stage_runner.h"

namespace viz {
namespace {

constexpr std::array<std::string_view, 4> kOrder = {"t.a", "t.b", "t.c", "t.d"};
static_assert(stageIndexOf(kOrder, "t.a") == 0 && stageIndexOf(kOrder, "t.c") == 2 && stageIndexOf(kOrder, "t.d") == 3);

// A clock that counts: begin() and end() calls, and which stage each end() named.
class CountingClock final : public StageTimer {
public:
    void begin() override { ++begun; }
    StageTiming end(const std::string& stage) override {
        ended.push_back(stage);
        return {stage, 1.5};
    }
    std::string name() const override { return "counting"; }
    int begun = 0;
    std::vector<std::string> ended;
};

// Stages a and b keep their outputs; c and d do not (like a stage whose results live in run()'s locals).
std::vector<StageInfo> declared() {
    std::vector<StageInfo> stages;
    for (std::string_view id : kOrder) stages.push_back({std::string(id), "", "", {}, {std::string(id) + ".out"}, 1});
    stages[0].keepsOutputs = stages[1].keepsOutputs = true;
    return stages;
}

struct Recorded {
    FrameOutput out;
    std::vector<int> worked;  // stages whose work ran, in order
    CountingClock clock;
};

// One run of the four stages through `reuse`: each stage's work notes itself, its publish step adds one
// intermediate named after the stage and the run (`tag`).
void runAll(const std::vector<StageInfo>& stages, const FrameInput& input, StageReuse& reuse, Recorded& r,
            const std::string& tag) {
    StageRunner runner(stages, input, r.out, reuse, r.clock);
    for (int k = 0; k < int(stages.size()); ++k) {
        const bool more = runner.run(
            k, [&] { r.worked.push_back(k); },
            [&] {
                Intermediate i;
                i.id = stages[std::size_t(k)].id + ".out";
                i.label = tag;
                r.out.intermediates.push_back(i);
            });
        if (!more) return;
    }
}

TEST(StageRunner, RunsEveryStageOnceTimedByTheRunsClock) {
    const std::vector<StageInfo> stages = declared();
    StageReuse reuse;
    Recorded r;
    runAll(stages, FrameInput{}, reuse, r, "first");
    EXPECT_EQ(r.worked, (std::vector<int>{0, 1, 2, 3}));
    EXPECT_EQ(r.clock.begun, 4);
    EXPECT_EQ(r.clock.ended, (std::vector<std::string>{"t.a", "t.b", "t.c", "t.d"}));
    EXPECT_EQ(r.out.timing.clock, "counting");
    ASSERT_EQ(r.out.timing.stages.size(), 4u);
    EXPECT_DOUBLE_EQ(r.out.timing.totalMilliseconds(), 6.0);
    EXPECT_EQ(r.out.lastStageRun, 3);
    EXPECT_EQ(r.out.firstStageRun, 0);
    ASSERT_EQ(r.out.intermediates.size(), 4u);
}

TEST(StageRunner, StopsAfterTheAskedStageAndRunsEverythingPastTheLast) {
    const std::vector<StageInfo> stages = declared();
    for (int stop : {0, 1, 2}) {
        StageReuse reuse;
        Recorded r;
        FrameInput input;
        input.stopAfterStage = stop;
        runAll(stages, input, reuse, r, "stop");
        EXPECT_EQ(int(r.worked.size()), stop + 1) << "stop " << stop;
        EXPECT_EQ(r.out.lastStageRun, stop);
        EXPECT_EQ(int(r.out.timing.stages.size()), stop + 1);
    }
    StageReuse reuse;
    Recorded r;
    FrameInput input;
    input.stopAfterStage = 99;
    runAll(stages, input, reuse, r, "past");
    EXPECT_EQ(r.worked.size(), 4u);
    EXPECT_EQ(r.out.lastStageRun, 3);
}

TEST(StageRunner, AResumedRunCarriesTheStagesThatKeepTheirOutputs) {
    const std::vector<StageInfo> stages = declared();
    StageReuse reuse;
    Recorded first;
    runAll(stages, FrameInput{}, reuse, first, "first");

    FrameInput input;
    input.resumeAtStage = 2;
    Recorded second;
    runAll(stages, input, reuse, second, "second");
    EXPECT_EQ(second.worked, (std::vector<int>{2, 3})) << "a and b carried over";
    EXPECT_EQ(second.out.firstStageRun, 2);
    EXPECT_EQ(second.clock.ended, (std::vector<std::string>{"t.c", "t.d"})) << "timing lists the stages that ran";
    ASSERT_EQ(second.out.intermediates.size(), 4u);
    // Carried stages republish what they published when they ran, in stage order.
    EXPECT_EQ(second.out.intermediates[0].id, "t.a.out");
    EXPECT_EQ(second.out.intermediates[0].label, "first");
    EXPECT_EQ(second.out.intermediates[1].label, "first");
    EXPECT_EQ(second.out.intermediates[2].label, "second");
    EXPECT_EQ(second.out.lastStageRun, 3);
}

TEST(StageRunner, AStageThatKeepsNothingRunsAgainEvenPastTheResumePoint) {
    const std::vector<StageInfo> stages = declared();
    StageReuse reuse;
    Recorded first;
    runAll(stages, FrameInput{}, reuse, first, "first");
    // Resuming at d: c keeps nothing, so the run resumes at c.
    FrameInput input;
    input.resumeAtStage = 3;
    Recorded second;
    runAll(stages, input, reuse, second, "second");
    EXPECT_EQ(second.worked, (std::vector<int>{2, 3}));
    EXPECT_EQ(second.out.firstStageRun, 2);
}

TEST(StageRunner, ARunThatStoppedShortLeavesNothingToCarryPastIt) {
    const std::vector<StageInfo> stages = declared();
    StageReuse reuse;
    Recorded first;
    FrameInput stopped;
    stopped.stopAfterStage = 0;
    runAll(stages, stopped, reuse, first, "first");
    // Stage b never ran, so a resume at c must run b first.
    FrameInput input;
    input.resumeAtStage = 2;
    Recorded second;
    runAll(stages, input, reuse, second, "second");
    EXPECT_EQ(second.worked, (std::vector<int>{1, 2, 3}));
    EXPECT_EQ(second.out.firstStageRun, 1);
}

// A technique whose declared list drifts from its stage order stops at construction (a programmer error).
TEST(StageRunnerDeathTest, TheDeclaredListMustFollowTheStageOrder) {
    std::vector<StageInfo> stages = declared();
    checkStageOrder(stages, kOrder);
    std::vector<StageInfo> swapped = stages;
    std::swap(swapped[1], swapped[2]);
    EXPECT_DEATH(checkStageOrder(swapped, kOrder), "stage 1 is declared as t.c but the stage order says t.b");
    stages.pop_back();
    EXPECT_DEATH(checkStageOrder(stages, kOrder), "declares 3 stages but its stage order lists 4");
}

}  // namespace
}  // namespace viz
