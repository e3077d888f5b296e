// The app state (app/app_state.h): the session file written from it reads back, through the session
// parser, as the same state; a lesson sees the cursor as its stage's parameter and the focused view.
#include <gtest/gtest.h>

#include "app_state.h"
#include "view_layout.h"

namespace airlight {
namespace {

AppState sampleState() {
    AppState a;
    a.scene = "colonnade";
    a.technique = "slices";
    a.size = {200, 150};
    a.defaults = {{"planes", 64}, {"planes_drawn", 0}, {"accum", 0}};
    a.settings = {{"planes", 96}, {"planes_drawn", 0}, {"accum", 0}};
    a.cursor = {2, 5};
    a.stageShown = 2;
    a.steppedSettings = a.settings;
    a.steppedSettings["planes_drawn"] = 5;
    a.camera.position = {1.0, 2.0, 3.0};
    a.camera.forward = {0.0, 0.0, -1.0};
    a.orbitTarget = {1.0, 2.0, -4.0};
    a.medium.sigma_s = 0.3;
    a.medium.sigma_a = 0.02;
    a.medium.g = -0.4;
    viz::scene::Light l{.type = viz::scene::LightType::Spot,
                        .position = {0.0, 5.0, 0.0},
                        .direction = {0.0, -1.0, 0.0},
                        .intensity = 250.0};
    a.lights = {l};
    a.exposure = -1.5f;
    a.exposureSet = true;
    ViewLayout layout(1);
    layout.split(1, SplitAxis::X, 2);
    a.layout = layout.toText();
    a.focusedView = 2;
    AppState::View final;
    final.id = 1;
    final.content = "final";
    AppState::View planes;
    planes.id = 2;
    planes.content = "slices.planes";
    planes.layer = 3;
    planes.zoom = 4.0;
    planes.center = {0.25, 0.75};
    planes.display.logScale = true;
    planes.display.colourMap = ColourMap::Sequential;
    a.views = {final, planes};
    a.inspected = glm::ivec2(10, 20);
    return a;
}

TEST(AppState, TheSessionWrittenFromTheStateReadsBackAsTheState) {
    const AppState a = sampleState();
    SessionState base;
    base.settings["minmax"] = {{"mip_levels", 3}};  // another technique's: kept as it was
    std::string problem;
    const SessionState s = sessionFromJson(sessionToJson(sessionOf(a, base)), problem);
    ASSERT_TRUE(problem.empty()) << problem;
    EXPECT_EQ(s.scene, "colonnade");
    EXPECT_EQ(s.technique, "slices");
    EXPECT_EQ(s.width, 200);
    EXPECT_EQ(s.height, 150);
    ASSERT_TRUE(s.camera.has_value());
    EXPECT_EQ(s.camera->position, a.camera.position);
    EXPECT_EQ(s.orbitTarget, a.orbitTarget);
    ASSERT_TRUE(s.medium.has_value());
    EXPECT_EQ(s.medium->sigma_s, 0.3);
    EXPECT_EQ(s.medium->g, -0.4);
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].intensity, 250.0);
    EXPECT_EQ(s.settings.at("slices"), (viz::Settings{{"planes", 96}})) << "only what differs from the defaults";
    EXPECT_EQ(s.settings.at("minmax").at("mip_levels"), 3);
    EXPECT_EQ(s.settings.at("slices").count("planes_drawn"), 0u) << "the cursor is not a setting";
    EXPECT_EQ(s.exposure, -1.5f);
    EXPECT_TRUE(s.exposureSet);
    EXPECT_EQ(s.layout, a.layout);
    EXPECT_EQ(s.focusedView, 2);
    ASSERT_EQ(s.gridViews.size(), 2u);
    EXPECT_EQ(s.gridViews[1].content, "slices.planes");
    EXPECT_EQ(s.gridViews[1].layer, 3);
    EXPECT_EQ(s.gridViews[1].zoom, 4.0);
    EXPECT_TRUE(s.gridViews[1].logScale);
    EXPECT_EQ(s.gridViews[1].colourMap, int(ColourMap::Sequential));
    EXPECT_EQ(s.view, "slices.planes") << "the first view that is not the final frame, for older readers";
}

TEST(AppState, ALessonSeesTheCursorAsItsStagesParameterAndTheFocusedView) {
    const LessonWindowState l = lessonStateOf(sampleState());
    EXPECT_EQ(l.stage, 2);
    EXPECT_EQ(l.settings.at("planes_drawn"), 5);
    EXPECT_EQ(l.settings.at("planes"), 96);
    EXPECT_EQ(l.view, "slices.planes");
    ASSERT_TRUE(l.inspect.has_value());
    EXPECT_EQ(*l.inspect, glm::ivec2(10, 20));
    EXPECT_EQ(l.size, glm::ivec2(200, 150));
}

TEST(AppState, TheSidecarStateNamesTheCursorCameraAndSelection) {
    const nlohmann::json j = sidecarStateOf(sampleState());
    EXPECT_EQ(j.at("cursor").at("stage"), 2);
    EXPECT_EQ(j.at("cursor").at("substep"), 5);
    EXPECT_EQ(j.at("settings").at("planes_drawn"), 0) << "the settings, not the stepped ones";
    EXPECT_EQ(j.at("camera").at("position")[2], 3.0);
    EXPECT_EQ(j.at("inspected")[1], 20);
    EXPECT_EQ(j.at("exposure"), -1.5);
}

}  // namespace
}  // namespace airlight
