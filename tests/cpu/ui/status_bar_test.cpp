// The window's status lines (app/status_bar.h): what each line says for a frame, which message wins the
// third line (error, then the session's notice, then the run's note, over the skipped stages), that
// facts about a run are left out until there is one, and that the description comes after the cursor. Expected texts are written out by hand.
#include <gtest/gtest.h>

#include "status_bar.h"

namespace airlight {
namespace {

StatusFacts frameFacts() {
    StatusFacts f;
    f.scene = "grate";
    f.technique = "minmax";
    f.description = "1D min-max mipmaps";
    f.renderSize = {320, 240};
    f.stage = 5;
    f.stageCount = 6;
    f.stageId = "minmax.compose";
    f.plan.stages = {{"minmax.shadow_maps", true, ""}, {"minmax.rectify", false, "no spot light"},
                     {"minmax.mipmap", false, ""}};
    return f;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(StatusBar, BeforeAnyRunTheLinesSayWhereTheCursorIsAndNothingAboutARun) {
    StatusFacts f = frameFacts();
    f.reduced = true;
    f.passCount = 3;
    f.firstStageRun = 2;
    const auto lines = statusLines(f);
    EXPECT_EQ(lines[0].text,
              "scene: grate   technique: minmax   render 320x240   stage 6/6 minmax.compose (S, D, Home, End)   "
              "(minmax: 1D min-max mipmaps)");
    EXPECT_EQ(lines[0].tone, StatusTone::Text);
    EXPECT_EQ(lines[1].text, "timings: (no run yet)");
    EXPECT_EQ(lines[2].text, "skipped: minmax.rectify (no spot light);  minmax.mipmap");
    EXPECT_EQ(lines[2].tone, StatusTone::Dim);
}

TEST(StatusBar, InFlyModeTheStepHintOffersOnlyTheKeysThatStillStep) {
    StatusFacts f = frameFacts();
    f.fly = true;
    EXPECT_TRUE(contains(statusLines(f)[0].text, "stage 6/6 minmax.compose (Home, End)   "))
        << statusLines(f)[0].text;
}

TEST(StatusBar, ARunAddsItsSizeItsPassItsResumeAndItsStageTimes) {
    StatusFacts f = frameFacts();
    f.haveOutput = true;
    f.reduced = true;
    f.outputSize = {160, 120};
    f.pass = 1;
    f.passCount = 2;
    f.stage = 4;
    f.stageId = "minmax.traverse";
    f.substep = 3;
    f.substepCount = 28;
    f.firstStageRun = 4;
    f.timing.clock = "glFinish+steady_clock";
    f.timing.stages = {{"minmax.traverse", 12.25}, {"minmax.compose", 0.5}};
    const auto lines = statusLines(f);
    EXPECT_EQ(lines[0].text,
              "scene: grate   technique: minmax   render 320x240   (interactive: 160x120)   (showing pass 1/2: "
              "160x120)   stage 5/6 minmax.traverse sub-step 3/28 (S, D, Home, End)   re-ran from stage 5 (earlier "
              "ones kept)   (minmax: 1D min-max mipmaps)");
    EXPECT_EQ(lines[1].text,
              "timings: total 12.8 ms (clock: glFinish+steady_clock)   |  minmax.traverse 12.2 ms  "
              "minmax.compose 0.5 ms");
}

TEST(StatusBar, AnErrorWinsTheThirdLineThenTheNoticeThenTheRunsNote) {
    StatusFacts f = frameFacts();
    f.haveOutput = true;
    f.note = "sun: no cone to clip";
    auto lines = statusLines(f);
    EXPECT_EQ(lines[2].text, "note: sun: no cone to clip   |   skipped: minmax.rectify (no spot light);  minmax.mipmap");
    EXPECT_EQ(lines[2].tone, StatusTone::Accent);

    f.notice = "session saved";
    lines = statusLines(f);
    EXPECT_EQ(lines[2].text, "session saved   |   skipped: minmax.rectify (no spot light);  minmax.mipmap");
    EXPECT_EQ(lines[2].tone, StatusTone::Dim);

    f.settingsError = "rank: 40 is above 16";
    lines = statusLines(f);
    EXPECT_EQ(lines[2].text, "error: rank: 40 is above 16 (using defaults)");
    EXPECT_EQ(lines[2].tone, StatusTone::Error);

    // A run's error beats the settings' and shows its first line only, marked as cut.
    f.error = "shader minmax/traverse.comp failed\n0:12: syntax error";
    lines = statusLines(f);
    EXPECT_TRUE(contains(lines[2].text, "error: shader minmax/traverse.comp failed")) << lines[2].text;
    EXPECT_TRUE(contains(lines[2].text, "(...)")) << lines[2].text;
    EXPECT_FALSE(contains(lines[2].text, "syntax error")) << lines[2].text;
    EXPECT_EQ(lines[2].tone, StatusTone::Error);
}

TEST(StatusBar, ANoteIsLeftOutUntilThereIsARun) {
    StatusFacts f = frameFacts();
    f.note = "left over from another scene";
    EXPECT_EQ(statusLines(f)[2].tone, StatusTone::Dim);
    EXPECT_FALSE(contains(statusLines(f)[2].text, "left over"));
}

TEST(StatusBar, APlanThatRunsEveryStageSaysNoneSkipped) {
    viz::Plan plan;
    plan.stages = {{"a", true, "detail"}, {"b", true, ""}};
    EXPECT_EQ(skippedLine(plan), "skipped: none");
    EXPECT_EQ(timingLine({}), "timings: (none yet)");
}

// A run whose stages compiled shaders says how many, and marks those stages: its times are no warm figures.
TEST(StatusBar, ARunThatCompiledShadersSaysSo) {
    viz::Timing t;
    t.clock = "glFinish+steady_clock";
    t.stages = {{"minmax.rectify", 60.0}, {"minmax.traverse", 700.0}, {"minmax.compose", 1.0}};
    t.stages[0].programsCompiled = 2;
    t.stages[1].programsCompiled = 1;
    EXPECT_EQ(timingLine(t), "timings: total 761.0 ms (clock: glFinish+steady_clock, * includes compiling 3 shader "
                             "programs (first use))   |  minmax.rectify 60.0 ms*  minmax.traverse 700.0 ms*  "
                             "minmax.compose 1.0 ms");
    t.stages[0].programsCompiled = 0;
    EXPECT_NE(timingLine(t).find("compiling 1 shader program (first use)"), std::string::npos) << timingLine(t);
}

}  // namespace
}  // namespace airlight
