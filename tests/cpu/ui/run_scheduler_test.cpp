// The window's run scheduler (app/run_scheduler.h) with a technique that counts how often each stage
// runs. Four stages: a reads `a`, b reads `b`, c reads `c` and steps through 5 sub-steps (`step`), d
// composes. Each stage's result is kept in the instance (as a GPU technique keeps textures) and depends on
// the scene, the earlier stage and its own parameters, so a stage wrongly carried over shows in the
// output: every run is checked against a fresh instance running all stages.
#include <gtest/gtest.h>

#include <array>
#include <memory>

#include "cpu/ui/fake_technique.h"
#include "debug/stage_reuse.h"
#include "run_scheduler.h"

namespace airlight {
namespace {

class CountingTechnique : public airlight::testing::FakeTechnique {
public:
    explicit CountingTechnique(unsigned instance) : FakeTechnique("fake", "counts stage runs"), mInstance(instance) {
        mParams = {{"a", "", 1, 0, 100, true},  {"b", "", 2, 0, 100, true},  {"c", "", 3, 0, 100, true},
                   {"step", "", 0, 0, 4, true}, {"look", "", 0, 0, 1, true}};
        mStages = {{"fake.a", "A", "", {"a"}, {"fake.a"}, 1},
                   {"fake.b", "B", "", {"b"}, {"fake.b", "fake.b_view"}, 1, "", "", {"fake.b_view"}},
                   {"fake.c", "C", "", {"c", "step"}, {"fake.c"}, 5, "step"},
                   {"fake.d", "D", "", {}, {"fake.d"}, 1}};
    }
    viz::FrameOutput run(const viz::FrameInput& in) override {
        viz::FrameOutput out;
        const int stop = in.stopAfterStage < 0 ? 3 : in.stopAfterStage;
        mReuse.begin(in, out);
        const double light = in.scene->lights.empty() ? 0.0 : in.scene->lights[0].intensity;
        const auto stage = [&](int k, double value) {
            if (mReuse.carries(k)) {
                mReuse.carry(k, out);
            } else {
                ++runs[std::size_t(k)];
                mValue[std::size_t(k)] = value;
                viz::Intermediate i;
                i.id = mStages[std::size_t(k)].id;
                i.glTexture = mInstance * 1000 + unsigned(k);  // "textures" of this instance
                out.intermediates.push_back(i);
                mReuse.ran(k, out);
            }
            out.lastStageRun = k;
            return k == stop;
        };
        if (stage(0, light + in.settings.at("a"))) return finish(out, 0);
        if (stage(1, mValue[0] * 10.0 + in.settings.at("b"))) return finish(out, 1);
        // "step" 1..4 keeps that many hundredths of c; 0: all of it.
        const double step = substepLimit(in, 2);
        if (stage(2, mValue[1] * 10.0 + in.settings.at("c") * (step == 0.0 ? 1.0 : step / 100.0))) return finish(out, 2);
        stage(3, mValue[2] + 0.5);
        return finish(out, 3);
    }

    std::array<int, 4> runs{};

private:
    viz::FrameOutput finish(viz::FrameOutput& out, int k) {
        out.final = viz::Image(1, 1, 1);
        out.final.at(0, 0, 0) = float(mValue[std::size_t(k)]);
        return std::move(out);
    }
    unsigned mInstance;
    viz::StageReuse mReuse;
    std::array<double, 4> mValue{};
};

struct Fixture {
    viz::scene::Scene scene;
    RunScheduler runner{std::make_unique<CountingTechnique>(1)};
    CountingTechnique& fake() { return static_cast<CountingTechnique&>(runner.technique()); }

    Fixture() {
        scene.name = "fake";
        scene.lights.emplace_back();
        scene.lights[0].intensity = 7.0;
    }
    viz::Settings settings(const viz::Settings& given = {}) { return viz::completeSettings(fake(), given); }
    // Runs through the runner; checks the value against a fresh instance that runs every stage.
    float run(const viz::Settings& s, StepCursor cursor) {
        const viz::FrameOutput out = runner.run(scene, 4, 3, s, cursor);
        RunScheduler fresh(std::make_unique<CountingTechnique>(9));
        const viz::FrameOutput truth = fresh.run(scene, 4, 3, s, cursor);
        EXPECT_EQ(out.final.at(0, 0, 0), truth.final.at(0, 0, 0)) << "a carried stage changed the result";
        EXPECT_EQ(out.intermediates.size(), truth.intermediates.size());
        return out.final.at(0, 0, 0);
    }
    std::array<int, 4> counted() {
        const auto r = fake().runs;
        fake().runs = {};
        return r;
    }
};

using Counts = std::array<int, 4>;

TEST(RunScheduler, ASubstepChangeRerunsItsStageOnly) {
    Fixture f;
    const viz::Settings s = f.settings();
    f.run(s, {2, 1});
    EXPECT_EQ(f.counted(), (Counts{1, 1, 1, 0}));
    f.run(s, {2, 2});
    EXPECT_EQ(f.counted(), (Counts{0, 0, 1, 0}));
    EXPECT_EQ(f.runner.lastResume().stage, 2);
    EXPECT_TRUE(f.runner.lastResume().substepOnly);
    f.run(s, {2, 5});  // the last sub-step: the stage whole
    EXPECT_EQ(f.counted(), (Counts{0, 0, 1, 0}));
}

TEST(RunScheduler, AParameterOfStageThreeRerunsFromStageThree) {
    Fixture f;
    f.run(f.settings(), {});
    EXPECT_EQ(f.counted(), (Counts{1, 1, 1, 1}));
    f.run(f.settings({{"c", 8}}), {});
    EXPECT_EQ(f.counted(), (Counts{0, 0, 1, 1}));
    EXPECT_FALSE(f.runner.lastResume().substepOnly);
    f.run(f.settings({{"c", 8}, {"b", 5}}), {});
    EXPECT_EQ(f.counted(), (Counts{0, 1, 1, 1}));
    // A parameter no stage declares: everything (nothing can be vouched for).
    f.run(f.settings({{"c", 8}, {"b", 5}, {"look", 1}}), {});
    EXPECT_EQ(f.counted(), (Counts{1, 1, 1, 1}));
}

// A view stage b draws only on demand: showing it (or no longer showing it) re-runs from stage b; other
// views shown or hidden change nothing.
TEST(RunScheduler, ShowingAnOnDemandViewRerunsFromTheStageThatDrawsIt) {
    Fixture f;
    f.runner.run(f.scene, 4, 3, f.settings(), {});
    f.counted();
    EXPECT_EQ(f.runner.onDemandAmong({"final", "fake.b_view", "fake.c", "fake.b_view"}),
              (std::vector<std::string>{"fake.b_view"}));
    f.runner.run(f.scene, 4, 3, f.settings(), {}, {"final", "fake.b_view"});
    EXPECT_EQ(f.counted(), (Counts{0, 1, 1, 1}));
    EXPECT_EQ(f.runner.lastViews(), (std::vector<std::string>{"fake.b_view"}));
    f.runner.run(f.scene, 4, 3, f.settings(), {}, {"fake.b_view", "fake.c"});
    EXPECT_EQ(f.counted(), (Counts{0, 0, 0, 1}));  // the same on-demand view: only the last stage, as always
    f.runner.run(f.scene, 4, 3, f.settings(), {}, {"fake.c"});
    EXPECT_EQ(f.counted(), (Counts{0, 1, 1, 1}));
    EXPECT_TRUE(f.runner.lastViews().empty());
}

TEST(RunScheduler, ASceneEditRerunsEverything) {
    Fixture f;
    f.run(f.settings(), {});
    f.counted();
    f.scene.lights[0].intensity = 8.0;
    f.run(f.settings(), {});
    EXPECT_EQ(f.counted(), (Counts{1, 1, 1, 1}));
    f.scene.camera.position.x += 1e-9;
    f.run(f.settings(), {});
    EXPECT_EQ(f.counted(), (Counts{1, 1, 1, 1}));
    // So does a new size.
    f.runner.run(f.scene, 5, 3, f.settings(), {});
    EXPECT_EQ(f.counted(), (Counts{1, 1, 1, 1}));
}

// Leaving a stage stopped at an early sub-step runs it whole again: nothing of the partial result leaks
// into the complete frame (the window's scan_passes leak).
TEST(RunScheduler, LeavingAPartialStageRunsItWhole) {
    Fixture f;
    const viz::Settings s = f.settings();
    const float complete = f.run(s, {});
    f.run(s, {2, 2});
    f.counted();
    EXPECT_EQ(f.run(s, {}), complete);
    EXPECT_EQ(f.counted(), (Counts{0, 0, 1, 1}));
    // Back to an earlier stage: that stage runs, nothing before it.
    f.run(s, {1, 0});
    EXPECT_EQ(f.counted(), (Counts{0, 1, 0, 0}));
    // Forward from there: the stages after it.
    EXPECT_EQ(f.run(s, {}), complete);
    EXPECT_EQ(f.counted(), (Counts{0, 0, 1, 1}));
}

TEST(RunScheduler, TwoConsumersNeverSeeEachOthersTextures) {
    Fixture one;
    RunScheduler two(std::make_unique<CountingTechnique>(2));
    const viz::Settings s1 = one.settings(), s2 = one.settings({{"a", 40}});
    for (int round = 0; round < 3; ++round) {
        one.run(s1, {2, round + 1});
        const viz::FrameOutput b = two.run(one.scene, 4, 3, s2, {2, round + 1});
        RunScheduler fresh(std::make_unique<CountingTechnique>(9));
        EXPECT_EQ(b.final.at(0, 0, 0), fresh.run(one.scene, 4, 3, s2, {2, round + 1}).final.at(0, 0, 0));
        for (const viz::Intermediate& i : b.intermediates) EXPECT_EQ(i.glTexture / 1000, 2u) << i.id;
    }
    const viz::FrameOutput a = one.runner.run(one.scene, 4, 3, s1, {});
    for (const viz::Intermediate& i : a.intermediates) EXPECT_EQ(i.glTexture / 1000, 1u) << i.id;
}

}  // namespace
}  // namespace airlight
