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

// A 2x1 view's values: texel (1, 0) holds 0.25, NaN, 4.
ViewState twoTexelView() {
    ViewState v;
    v.content = "airlight";
    v.values = viz::Image(2, 1, 3);
    v.values.at(1, 0, 0) = 0.25f;
    v.values.at(1, 0, 1) = std::numeric_limits<float>::quiet_NaN();
    v.values.at(1, 0, 2) = 4.0f;
    v.meaningful = 3;
    v.counts.nan = 1;
    return v;
}

TEST(SidecarJson, AScreenSpaceViewGivesTheLinkedPixelAndItsValuesWithNaNAsNull) {
    ViewState v = twoTexelView();
    v.cell = {{10.0f, 20.0f}, {110.0f, 95.0f}};
    ViewSidecarFacts f;
    f.id = 3;
    f.focused = true;
    f.screenSpace = true;
    f.linkedPixel = glm::ivec2(1, 0);
    const nlohmann::json j = viewSidecar(v, f);
    EXPECT_EQ(j.at("cell"), 3);
    EXPECT_EQ(j.at("cell_rect"), nlohmann::json::parse("[10, 20, 110, 95]"));
    EXPECT_EQ(j.at("focused"), true);
    EXPECT_EQ(j.at("content"), "airlight");
    EXPECT_EQ(j.at("nan_pixels"), 1);
    EXPECT_EQ(j.at("cursor"), nlohmann::json::array({1, 0}));
    EXPECT_EQ(j.at("cursor_value"), nlohmann::json::parse("[0.25, null, 4.0]"));
    EXPECT_FALSE(j.contains("markers"));
    EXPECT_FALSE(j.contains("difference")) << "no difference shown";
    // Outside the values: the cursor, no values.
    f.linkedPixel = glm::ivec2(5, 0);
    EXPECT_FALSE(viewSidecar(v, f).contains("cursor_value"));
}

TEST(SidecarJson, ADataViewListsItsMarkersAndNoCursor) {
    const ViewState v = twoTexelView();
    ViewSidecarFacts f;
    f.linkedPixel = glm::ivec2(1, 0);
    f.markers = std::vector<viz::ViewMarker>{{{0.5f, 0.5f}, {1.5f, 0.5f}, "ray", 2}};
    const nlohmann::json j = viewSidecar(v, f);
    EXPECT_TRUE(j.at("cursor").is_null());
    ASSERT_EQ(j.at("markers").size(), 1u);
    EXPECT_EQ(j.at("markers")[0].at("label"), "ray");
    EXPECT_EQ(j.at("markers")[0].at("layer"), 2);
    EXPECT_EQ(j.at("markers")[0].at("to"), nlohmann::json::array({1.5, 0.5}));
}

TEST(SidecarJson, ADifferenceGivesOnlyTheFiguresThatAreDefined) {
    ViewState v = twoTexelView();
    v.display.difference = DifferenceMode::Relative;
    v.display.against = "raymarch";
    v.differenceNote = "the reference is black";
    v.error = viz::report::ErrorMetrics{};
    v.error->relativeL2 = std::numeric_limits<double>::quiet_NaN();
    v.error->maxAbsolute = 0.5;
    const nlohmann::json d = viewSidecar(v, ViewSidecarFacts{}).at("difference");
    EXPECT_EQ(d.at("mode"), differenceModeNames()[std::size_t(DifferenceMode::Relative)]);
    EXPECT_EQ(d.at("against"), "raymarch");
    EXPECT_EQ(d.at("note"), "the reference is black");
    EXPECT_FALSE(d.contains("relative_l2"));
    EXPECT_EQ(d.at("max_abs"), 0.5);
}

}  // namespace
}  // namespace airlight

namespace airlight {
namespace {

// A 2x1 RGB L_air with every channel of pixel i equal to values[i].
viz::Image sidecarFrame(float a, float b) {
    viz::Image image(2, 1, 3);
    for (int c = 0; c < 3; ++c) {
        image.at(0, 0, c) = a;
        image.at(1, 0, c) = b;
    }
    return image;
}

TEST(SidecarJson, TheAnimationGivesItsScoresOnlyOnceTheyExistAndThePathOnlyAlongOne) {
    WindowAnimation a;
    nlohmann::json j = animationJson(a);
    EXPECT_EQ(j.at("playing"), false);
    EXPECT_EQ(j.at("temporal_pairs"), 0);
    EXPECT_FALSE(j.contains("temporal_change_rms"));  // NaN before two frames: absent, never null or NaN
    EXPECT_FALSE(j.contains("temporal_error_rms"));
    EXPECT_FALSE(j.contains("path"));
    EXPECT_EQ(j.at("reference_frames").at("total"), 0);

    a.playing = true;
    a.frame = 2;
    a.temporal.add(sidecarFrame(1.0f, 1.0f));
    a.temporal.add(sidecarFrame(1.0f, 3.0f));  // one pixel changed: a positive score
    a.path = viz::scene::parseMotionPath("camera-orbit:30deg");
    a.pathFrames = 24;
    a.pathFrame = 5;
    j = animationJson(a);
    EXPECT_EQ(j.at("playing"), true);
    EXPECT_EQ(j.at("frame"), 2);
    EXPECT_EQ(j.at("temporal_pairs"), 1);
    ASSERT_TRUE(j.contains("temporal_change_rms"));
    EXPECT_DOUBLE_EQ(j.at("temporal_change_rms").get<double>(), a.temporal.score());
    EXPECT_GT(j.at("temporal_change_rms").get<double>(), 0.0);
    EXPECT_FALSE(j.contains("temporal_error_rms"));  // no reference frames were given
    EXPECT_EQ(j.at("path").at("text"), "camera-orbit:30deg");
    EXPECT_EQ(j.at("path").at("frames"), 24);
    EXPECT_EQ(j.at("path").at("frame"), 5);
}

}  // namespace
}  // namespace airlight
