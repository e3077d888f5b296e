// The scene and parameter panel (parameter_panel.h).
#include "parameter_panel.h"

#include <algorithm>
#include <filesystem>

#include "parameter_widgets.h"
#include "plan_panel.h"
#include "scene_file.h"
#include "window_common.h"
#include "scene/builtin_scenes.h"
#include "scene/stiff_scenes.h"

namespace airlight {

void ParameterPanel::forgetValues() {
    mIntensity.forget();
    mSigmaS.forget();
    mSigmaA.forget();
}

ParameterPanelEdits ParameterPanel::draw(viz::ui::Context& ui, viz::scene::Scene& scene, int& selectedLight,
                                         const ParameterPanelFacts& facts) {
    ParameterPanelEdits edits;
    scenePickers(ui, facts.sceneSource, edits);
    openFileField(ui, facts.tab, facts.enter, edits);
    if (ui.collapsingHeader("Medium", true)) edits.sceneEdited = mediumWidgets(ui, scene.medium, mSigmaS, mSigmaA);
    const int lights = int(scene.lights.size());
    int picked = std::clamp(selectedLight, 0, std::max(0, lights - 1));  // the state keeps what was chosen
    if (lights > 1) {
        // Every light is editable: the panel and the gizmo work on the one picked here.
        std::vector<std::string> names;
        for (int i = 0; i < lights; ++i) {
            const viz::scene::Light& l = scene.lights[std::size_t(i)];
            names.push_back(std::to_string(i + 1) + ": " + (l.name.empty() ? "light" : l.name) + " (" + lightTypeName(l.type) + ")");
        }
        if (ui.combo("light", picked, names)) {
            selectedLight = picked;
            mIntensity.forget();
        }
    }
    if (lights > 0) {
        viz::scene::Light& light = scene.lights[std::size_t(picked)];
        if (ui.collapsingHeader("Light: " + light.name, true))
            edits.sceneEdited = mIntensity.draw(ui, "on", "intensity", light.intensity) || edits.sceneEdited;
        // Folded by default: the technique's parameters stay in view on small windows.
        if (ui.collapsingHeader("Light placement", false))
            edits.sceneEdited = lightPlacementWidgets(ui, light, orbitDistance(scene)) || edits.sceneEdited;
    }
    const viz::Technique& technique = *facts.technique;
    if (ui.collapsingHeader(technique.id() + " parameters", true)) {
        // A preset's values are shown by the widgets below in the same frame.
        std::string ignored;  // the settings were validated when they were set
        viz::Settings shown = *facts.settings;
        if (const auto preset = presetWidget(ui, technique, settingsFor(technique, shown, ignored)))
            for (const auto& [name, value] : *preset) {
                shown[name] = value;
                edits.settings.emplace_back(name, value);
            }
        for (const viz::ParamInfo& p : technique.params()) {
            // Sub-steps are the stepping cursor's (S, D, the timeline), not settings.
            if (substepStageOf(technique, p.name) >= 0) continue;
            double value = shown.count(p.name) ? shown.at(p.name) : p.defaultValue;
            if (parameterWidget(ui, p, value)) edits.settings.emplace_back(p.name, value);
        }
    }
    drawPlanSection(ui, *facts.plan);
    return edits;
}

void ParameterPanel::scenePickers(viz::ui::Context& ui, const std::string& source, ParameterPanelEdits& edits) {
    // The built-in scenes (and the file given on the command line, if any) in one list, the stiff cases of
    // `airlight report --suite stiff` in another (one long list would not fit the window).
    if (mSceneChoices.empty()) {
        mSceneChoices = viz::scene::builtinSceneNames();
        mStiffChoices = {"(none)"};
        for (const auto& c : viz::scene::stiffCases()) mStiffChoices.push_back("stiff/" + c.id);
    }
    const bool stiff = source.rfind("stiff/", 0) == 0;
    std::vector<std::string> scenes = mSceneChoices;
    if (!stiff && std::find(scenes.begin(), scenes.end(), source) == scenes.end()) scenes.push_back(source);
    int sceneIndex = stiff ? -1 : int(std::find(scenes.begin(), scenes.end(), source) - scenes.begin());
    std::string picked;
    if (ui.combo("scene", sceneIndex, scenes)) picked = scenes[std::size_t(sceneIndex)];
    ui.tooltip("the built-in scenes (and a glTF file given with --scene)");
    int stiffIndex = 0;
    if (stiff) {
        const auto at = std::find(mStiffChoices.begin(), mStiffChoices.end(), source);
        stiffIndex = at == mStiffChoices.end() ? 0 : int(at - mStiffChoices.begin());
    }
    if (ui.combo("stiff case", stiffIndex, mStiffChoices) && stiffIndex > 0) picked = mStiffChoices[std::size_t(stiffIndex)];
    ui.tooltip("the stiff and extreme cases (README: Stiff and extreme cases)");
    if (!picked.empty() && picked != source) edits.pickScene = picked;
}

void ParameterPanel::openFileField(viz::ui::Context& ui, bool tab, bool enter, ParameterPanelEdits& edits) {
    const bool wasFocused = ui.textFocused();
    ui.textInput("open glTF##path", mOpenPath);
    ui.tooltip("a .gltf or .glb file: Tab completes the path, Enter opens (or drop the file on the window)");
    const bool editing = ui.focused() == ui.lastId();
    const std::vector<std::string> completions = mOpenPath.empty() ? std::vector<std::string>{} : completePath(mOpenPath, 6);
    if (editing && tab) mOpenPath = commonCompletion(mOpenPath, completions);
    if (wasFocused && !editing && enter && !mOpenPath.empty()) edits.openFile = mOpenPath;
    // The completions, while the typed path names no file: a click takes one (a file opens).
    std::error_code ec;
    if (!mOpenPath.empty() && !std::filesystem::is_regular_file(mOpenPath, ec))
        for (const std::string& c : completions)
            if (ui.button(c + "##complete")) {
                mOpenPath = c;
                if (isSceneFile(c)) edits.openFile = c;
            }
    if (!mOpenPath.empty() && ui.button("Open##path")) edits.openFile = mOpenPath;
}

}  // namespace airlight
