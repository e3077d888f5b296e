// The scene and parameter panel (app/parameter_panel.h) driven by synthetic input, no window: every
// declared parameter of every technique has its widget except the sub-steps the stages declare; a
// widget's change comes back as an edit and leaves the settings passed in alone; picking a stiff case
// asks for its scene; Enter in the path field asks to open what was typed; the medium edits the scene.
#include <gtest/gtest.h>

#include <set>

#include "parameter_panel.h"
#include "synthetic_panel.h"
#include "scene/builtin_scenes.h"
#include "techniques/registry.h"

namespace airlight {
namespace {

using viz::ui::Context;
using viz::ui::Input;
using viz::ui::Key;
using viz::ui::testing::testFont;

// The panel in a display tall enough that every section is in view.
struct ParameterPanelTest : ::testing::Test {
    Context ui{testFont()};
    ParameterPanel panel;
    viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    int selectedLight = 0;
    viz::Plan plan;

    // One frame; the edits it made.
    ParameterPanelEdits frame(const Input& in, const viz::Technique& technique, const viz::Settings& settings,
                              const std::string& source = "grate", bool enter = false) {
        ui.beginFrame(in, {420.0f, 4000.0f});
        ui.beginPanel("Scene and parameters", {{0.0f, 0.0f}, {420.0f, 4000.0f}});
        const ParameterPanelEdits edits = panel.draw(ui, scene, selectedLight, {source, &technique, &settings, &plan, false, enter});
        ui.endPanel();
        ui.endFrame();
        return edits;
    }
    static Input at(glm::vec2 p, bool down = false) { return viz::ui::testing::SyntheticPanel::at(p, down); }
    glm::vec2 centreOf(const std::string& name) const { return viz::ui::testing::SyntheticPanel::widgetCentre(ui, name); }
};

TEST_F(ParameterPanelTest, EveryParameterHasItsWidgetButTheSubStepsTheStagesDeclare) {
    int substeps = 0;
    for (const std::string& id : viz::techniqueIds()) {
        SCOPED_TRACE(id);
        const auto technique = viz::makeTechnique(id);
        std::set<std::string> declaredSubsteps;
        for (const viz::StageInfo& s : technique->stages())
            if (!s.substepParam.empty()) declaredSubsteps.insert(s.substepParam);
        substeps += int(declaredSubsteps.size());
        frame({}, *technique, {});
        for (const viz::ParamInfo& p : technique->params())
            EXPECT_EQ(ui.widgetRects().count(p.name), declaredSubsteps.count(p.name) ? 0u : 1u) << p.name;
    }
    EXPECT_GE(substeps, 4) << "the techniques declare sub-steps (slices' planes, minmax's walk, vsv's scan, ...)";
}

TEST_F(ParameterPanelTest, AWidgetsChangeIsAnEditAndTheSettingsPassedInAreLeftAlone) {
    const auto raymarch = viz::makeTechnique("raymarch");
    const viz::Settings settings{{"samples", 64.0}};
    frame({}, *raymarch, settings);
    const auto it = ui.widgetRects().find("samples");
    ASSERT_NE(it, ui.widgetRects().end());
    // A press at the slider's left end and a release: the declared minimum.
    const glm::vec2 left{it->second.min.x + 1.0f, 0.5f * (it->second.min.y + it->second.max.y)};
    std::vector<std::pair<std::string, double>> edits;
    for (const Input& in : {at(left), at(left, true), at(left, false)}) {
        const ParameterPanelEdits e = frame(in, *raymarch, settings);
        edits.insert(edits.end(), e.settings.begin(), e.settings.end());
        EXPECT_FALSE(e.sceneEdited);
        EXPECT_FALSE(e.pickScene);
    }
    ASSERT_FALSE(edits.empty());
    EXPECT_EQ(edits.back().first, "samples");
    EXPECT_EQ(edits.back().second, 1.0);
    EXPECT_EQ(settings.at("samples"), 64.0);
}

TEST_F(ParameterPanelTest, PickingAStiffCaseAsksForItsScene) {
    const auto raymarch = viz::makeTechnique("raymarch");
    frame({}, *raymarch, {});
    const glm::vec2 combo = centreOf("stiff case");
    std::optional<std::string> picked;
    for (const Input& in : {at(combo), at(combo, true), at(combo, false), at(combo + glm::vec2(0.0f, 40.0f), true),
                            at(combo + glm::vec2(0.0f, 40.0f), false)})
        if (const ParameterPanelEdits e = frame(in, *raymarch, {}); e.pickScene) picked = e.pickScene;
    ASSERT_TRUE(picked);
    EXPECT_EQ(picked->rfind("stiff/", 0), 0u) << *picked;
}

TEST_F(ParameterPanelTest, EnterInThePathFieldAsksToOpenWhatWasTyped) {
    const auto raymarch = viz::makeTechnique("raymarch");
    frame({}, *raymarch, {});
    const glm::vec2 field = centreOf("open glTF##path");
    frame(at(field, true), *raymarch, {});
    frame(at(field, false), *raymarch, {});
    Input typed = at(field);
    typed.text = "no/such/model.gltf";
    EXPECT_FALSE(frame(typed, *raymarch, {}).openFile);
    Input enter = at(field);
    enter.keys = {Key::Enter};
    const ParameterPanelEdits e = frame(enter, *raymarch, {}, "grate", true);
    ASSERT_TRUE(e.openFile);
    EXPECT_EQ(*e.openFile, "no/such/model.gltf");  // the window says whether it exists
}

TEST_F(ParameterPanelTest, TheMediumsSliderEditsTheScene) {
    const auto raymarch = viz::makeTechnique("raymarch");
    frame({}, *raymarch, {});
    const double before = scene.medium.g;
    const auto it = ui.widgetRects().find("g (Henyey-Greenstein)");
    ASSERT_NE(it, ui.widgetRects().end());
    const glm::vec2 right{it->second.max.x - 1.0f, 0.5f * (it->second.min.y + it->second.max.y)};
    bool edited = false;
    for (const Input& in : {at(right), at(right, true), at(right, false)}) edited = frame(in, *raymarch, {}).sceneEdited || edited;
    EXPECT_TRUE(edited);
    EXPECT_NE(scene.medium.g, before);
    EXPECT_GT(scene.medium.g, 0.9);
}

}  // namespace
}  // namespace airlight
