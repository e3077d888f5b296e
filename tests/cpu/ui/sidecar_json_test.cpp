// The sidecar's plain parts (app/sidecar_json.h): what each says for a value built here by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sidecar_json.h"

namespace airlight {
namespace {

TEST(SidecarJson, ThePlanListsOnlyTheSkippedStagesAndEveryFeature) {
    viz::Plan plan;
    plan.stages = {{"t.a", true, "detail"}, {"t.b", false, "no spot light"}, {"t.c", true, ""}};
    plan.features = {{"SPOT", false, "no spot"}, {"SUN", true, "a sun"}};
    const nlohmann::json j = planJson(plan);
    ASSERT_EQ(j.at("skipped").size(), 1u);
    EXPECT_EQ(j.at("skipped")[0].at("stage"), "t.b");
    EXPECT_EQ(j.at("skipped")[0].at("why"), "no spot light");
    ASSERT_EQ(j.at("features").size(), 2u);
    EXPECT_EQ(j.at("features")[0].at("on"), false);
    EXPECT_EQ(j.at("features")[1].at("feature"), "SUN");
}

TEST(SidecarJson, StageTimesThatAreNotKnownAreLeftOut) {
    viz::Timing t;
    t.clock = "glFinish+steady_clock";
    t.stages.push_back({"t.a", 1.5});
    t.stages.push_back({"t.b", std::numeric_limits<double>::quiet_NaN()});
    t.stages.push_back({"t.c", 2.5});
    const nlohmann::json j = timingJson(t);
    EXPECT_EQ(j.at("clock"), "glFinish+steady_clock");
    ASSERT_EQ(j.at("stages").size(), 2u);
    EXPECT_EQ(j.at("stages")[1].at("stage"), "t.c");
    EXPECT_EQ(j.at("stages")[1].at("ms"), 2.5);
}

TEST(SidecarJson, AColourBarKeepsNonFiniteNumbersAsNullAndNamesNanAndInfSwatches) {
    ColourBar b;
    b.kind = ColourBar::Kind::Ramp;
    b.lo = 0.0;
    b.hi = std::numeric_limits<double>::infinity();
    b.ticks = {0.0, 0.5};
    b.tickLabels = {"0", "0.5"};
    b.tickAt = {0.0f, 0.5f};
    b.units = "radiance";
    b.legend = {{"NaN", std::numeric_limits<float>::quiet_NaN(), 3, false},
                {"-Inf", -std::numeric_limits<float>::infinity(), 1, false},
                {"-1: outside", -1.0f, 7, true}};
    const nlohmann::json j = colourBarJson(b, {{1, 2}, {3, 4}}, {{5, 6}, {7, 8}});
    EXPECT_EQ(j.at("kind"), "ramp");
    EXPECT_TRUE(j.at("hi").is_null());
    EXPECT_EQ(j.at("ticks").size(), 2u);
    EXPECT_EQ(j.at("rect"), nlohmann::json({1, 2, 3, 4}));
    EXPECT_EQ(j.at("ramp_rect"), nlohmann::json({5, 6, 7, 8}));
    ASSERT_EQ(j.at("legend").size(), 3u);
    EXPECT_EQ(j.at("legend")[0].at("value"), "NaN");
    EXPECT_EQ(j.at("legend")[1].at("value"), "-Inf");
    EXPECT_EQ(j.at("legend")[2].at("value"), -1.0);
    EXPECT_EQ(j.at("legend")[2].at("sentinel"), true);
    EXPECT_FALSE(j.contains("classes")) << "a ramp has no classes";
}

}  // namespace
}  // namespace airlight
