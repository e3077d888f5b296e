// The scene and parameter panel: scene and stiff-case pickers, medium, lights, preset, the technique's
// declared parameters and its plan.
#include "gui_app.h"
#include "plan_panel.h"

namespace airlight {

void GuiApp::drawParameters(glm::ivec2 fb) {
    (void)fb;
    if (mParamsRect.size().y > 0.0f) {
        mUi->beginPanel("Scene and parameters", mParamsRect);
        scenePicker();
        bool sceneChanged = false;
        if (mUi->collapsingHeader("Medium", true)) {
            // Values change only when a widget reports a change, so the scene keeps its exact doubles.
            // 0 is a box unticked ("scatters", "absorbs"): sigma_s = 0 makes L_air 0, sigma_a = 0 leaves
            // extinction to scattering.
            viz::scene::Medium& m = mScene.medium;
            sceneChanged = mSigmaSSlider.draw(*mUi, "scatters", "sigma_s (scattering)", m.sigma_s) || sceneChanged;
            mUi->tooltip("per scene unit; untick 'scatters' for sigma_s = 0 (no airlight)");
            sceneChanged = mSigmaASlider.draw(*mUi, "absorbs", "sigma_a (absorption)", m.sigma_a) || sceneChanged;
            mUi->tooltip("per scene unit; untick 'absorbs' for sigma_a = 0");
            float g = float(mScene.medium.g);
            if (mUi->sliderFloat("g (Henyey-Greenstein)", g, -0.99f, 0.99f)) mScene.medium.g = g, sceneChanged = true;
            mUi->tooltip("phase function asymmetry: > 0 scatters forward, < 0 back");
        }
        if (mScene.lights.size() > 1) {
            // Every light is editable: the panel and the gizmo work on the one picked here.
            std::vector<std::string> names;
            for (std::size_t i = 0; i < mScene.lights.size(); ++i)
                names.push_back(std::to_string(i + 1) + ": " + (mScene.lights[i].name.empty() ? "light" : mScene.lights[i].name) +
                                " (" + lightTypeName(mScene.lights[i].type) + ")");
            int picked = selectedLightIndex();
            if (mUi->combo("light", picked, names)) {
                mLight = picked;
                mIntensitySlider.forget();
            }
        }
        if (!mScene.lights.empty() && mUi->collapsingHeader("Light: " + selectedLight().name, true)) {
            sceneChanged = mIntensitySlider.draw(*mUi, "on", "intensity", selectedLight().intensity) || sceneChanged;
        }
        // Folded by default: the technique's parameters stay in view on small windows.
        if (!mScene.lights.empty() && mUi->collapsingHeader("Light placement", false)) {
            sceneChanged = lightPlacementWidgets(selectedLight()) || sceneChanged;
        }
        if (mUi->collapsingHeader(technique().id() + " parameters", true)) parameterWidgets();
        drawPlanSection(*mUi, shownPlan());
        mUi->endPanel();
        if (sceneChanged) sceneEdited();
    }
    if (mLesson) mLesson->draw(*this, *mUi, *mDrawList, *mBackground, mScale);
    mUi->endFrame();
}

void GuiApp::presetWidget(const std::string& id) {
    const viz::Settings paper = technique().paperSettings();
    if (paper.empty()) return;
    std::string ignored;  // mSettings were validated when they were set
    const viz::Settings current = settingsFor(technique(), mSettings, ignored);
    const viz::Settings defaults = viz::completeSettings(technique(), {});
    bool isPaper = true, isOurs = true;
    std::string names;
    for (const auto& [name, value] : paper) {
        isPaper = isPaper && current.at(name) == value;
        isOurs = isOurs && current.at(name) == defaults.at(name);
        names += (names.empty() ? "" : ", ") + name;
    }
    int index = isPaper ? 1 : isOurs ? 0 : 2;
    const std::vector<std::string> choices = {"ours (defaults)", "paper", "(mixed)"};
    const bool changed = mUi->combo("preset", index, choices);
    mUi->tooltip("the paper's own configuration or Airlight's defaults, for " + names +
                 " (airlight render --preset paper)");
    if (!changed || index == 2) return;
    for (const auto& [name, value] : paper) {
        const double v = index == 1 ? value : defaults.at(name);
        mSettings[name] = v;
        mSession.settings[id][name] = v;
        mOptions.settings.erase(name);
    }
    replan();
}

void GuiApp::scenePicker() {
    if (mSceneChoices.empty()) {
        mSceneChoices = viz::scene::builtinSceneNames();
        mStiffChoices = {"(none)"};
        for (const auto& c : viz::scene::stiffCases()) mStiffChoices.push_back("stiff/" + c.id);
    }
    const bool stiff = mOptions.scene.rfind("stiff/", 0) == 0;
    std::vector<std::string> scenes = mSceneChoices;
    if (!stiff && std::find(scenes.begin(), scenes.end(), mOptions.scene) == scenes.end())
        scenes.push_back(mOptions.scene);
    int sceneIndex = stiff ? -1 : int(std::find(scenes.begin(), scenes.end(), mOptions.scene) - scenes.begin());
    std::string picked;
    if (mUi->combo("scene", sceneIndex, scenes)) picked = scenes[std::size_t(sceneIndex)];
    mUi->tooltip("the built-in scenes (and a glTF file given with --scene)");
    int stiffIndex = 0;
    if (stiff) {
        const auto at = std::find(mStiffChoices.begin(), mStiffChoices.end(), mOptions.scene);
        stiffIndex = at == mStiffChoices.end() ? 0 : int(at - mStiffChoices.begin());
    }
    if (mUi->combo("stiff case", stiffIndex, mStiffChoices) && stiffIndex > 0)
        picked = mStiffChoices[std::size_t(stiffIndex)];
    mUi->tooltip("the stiff and extreme cases (README: Stiff and extreme cases)");
    openFileWidgets();
    // Loaded at the start of the next frame: this frame's views (and the comparison grid's tiles) are
    // queued for drawing with the textures the scene change would release.
    if (!picked.empty() && picked != mOptions.scene) mPendingScene = picked;
}

void GuiApp::openFileWidgets() {
    const bool wasFocused = mUi->textFocused();
    mUi->textInput("open glTF##path", mOpenPath);
    mUi->tooltip("a .gltf or .glb file: Tab completes the path, Enter opens (or drop the file on the window)");
    const bool editing = mUi->focused() == mUi->lastId();
    const std::vector<std::string> completions = mOpenPath.empty() ? std::vector<std::string>{} : completePath(mOpenPath, 6);
    if (editing && mTextTab) mOpenPath = commonCompletion(mOpenPath, completions);
    const bool entered = wasFocused && !editing && mTextEnter;
    mTextTab = mTextEnter = false;
    if (entered && !mOpenPath.empty()) openSceneFile(mOpenPath);
    // The completions, while the typed path names no file: a click takes one (a file opens).
    std::error_code ec;
    if (!mOpenPath.empty() && !std::filesystem::is_regular_file(mOpenPath, ec))
        for (const std::string& c : completions)
            if (mUi->button(c + "##complete")) {
                mOpenPath = c;
                if (isSceneFile(c)) openSceneFile(c);
            }
    if (!mOpenPath.empty() && mUi->button("Open##path")) openSceneFile(mOpenPath);
}

void GuiApp::openSceneFile(const std::string& path) {
    std::error_code ec;
    if (!isSceneFile(path)) mError = "cannot open '" + path + "': not a .gltf or .glb file";
    else if (!std::filesystem::is_regular_file(path, ec)) mError = "cannot open '" + path + "': no such file";
    else mPendingScene = path;
}

void GuiApp::reloadScene() {
    try {
        viz::scene::Scene scene = viz::scene::loadScene(mOptions.scene, mOptions.load);
        mScene = std::move(scene);
        mGeometryHash = viz::scene::geometryContentHash(mScene);
    } catch (const std::exception& e) {
        mError = "reloading " + sceneTitle() + " failed, the scene is kept as it was: " + firstLine(e.what());
        return;
    }
    mWorker->setScene(mScene);
    mComparison.close();  // its tiles show the old scene (this runs before the frame is laid out)
    mNotice = "reloaded " + sceneTitle() + " (changed on disk)";
    if (const std::string notes = sceneNotesLine(mScene); !notes.empty()) mNotice += "; " + notes;
    replan();
    mDirty = true;
}

std::string GuiApp::sceneTitle() const {
    if (!isSceneFile(mOptions.scene)) return mScene.name;
    const std::filesystem::path file(mOptions.scene);
    const std::string title = file.filename().string();
    return mScene.name.empty() || mScene.name == file.stem().string() ? title : title + " (glTF scene " + mScene.name + ")";
}

void GuiApp::loadPendingScene() {
    if (!mPendingScene) return;
    const std::string name = std::move(*mPendingScene);
    mPendingScene.reset();
    try {
        loadLessonScene(name);
        replan();
    } catch (const std::exception& e) {
        mError = e.what();
    }
}

bool GuiApp::lightPlacementWidgets(viz::scene::Light& light) {
    using viz::scene::LightType;
    bool changed = false;
    if (light.type == LightType::Spot || light.type == LightType::Directional) {
        const glm::dvec3 d = glm::normalize(light.direction);
        float azimuth = float(glm::degrees(std::atan2(d.x, -d.z)));
        float elevation = float(glm::degrees(std::asin(std::clamp(d.y, -1.0, 1.0))));
        const bool turned = mUi->sliderFloat("direction azimuth (deg)", azimuth, -180.0f, 180.0f);
        mUi->tooltip("about the vertical axis; 0 travels along -z");
        const bool tilted = mUi->sliderFloat("direction elevation (deg)", elevation, -90.0f, 90.0f);
        if (turned || tilted) {
            const double a = glm::radians(double(azimuth)), e = glm::radians(double(elevation));
            light.direction = {std::cos(e) * std::sin(a), std::sin(e), -std::cos(e) * std::cos(a)};
            changed = true;
        }
    }
    if (light.type == LightType::Point || light.type == LightType::Spot) {
        const float speed = float(0.004 * std::max(orbitDistance(mScene), 1e-3));
        const char* names[3] = {"position x", "position y", "position z"};
        for (int axis = 0; axis < 3; ++axis) {
            float v = float(light.position[axis]);
            if (mUi->dragFloat(names[axis], v, speed, -1e6f, 1e6f)) {
                light.position[axis] = v;
                changed = true;
            }
        }
    }
    return changed;
}

void GuiApp::parameterWidgets() {
    const std::string id = mIds[std::size_t(mCurrent)];
    presetWidget(id);
    for (const viz::ParamInfo& p : technique().params()) {
        // Sub-steps are the stepping cursor's (S, D, the timeline), not settings.
        if (substepStageOf(technique(), p.name) >= 0) continue;
        double value = mSettings.count(p.name) ? mSettings.at(p.name) : p.defaultValue;
        bool changed = false;
        if (!p.choices.empty()) {
            int index = int(value);
            changed = mUi->combo(p.name, index, p.choices);
            value = index;
        } else if (p.integer && p.minValue == 0.0 && p.maxValue == 1.0) {
            bool on = value != 0.0;
            changed = mUi->checkbox(p.name, on);
            value = on ? 1.0 : 0.0;
        } else if (p.maxValue - p.minValue > 1e4 && !(p.minValue > 0.0)) {
            float v = float(value);
            changed = mUi->dragFloat(p.name, v, float(std::max(1.0, std::abs(value)) * 0.01), float(p.minValue),
                                     float(p.maxValue));
            value = p.integer ? std::round(v) : v;
        } else if (p.minValue > 0.0 && p.maxValue / p.minValue >= 100.0) {
            float v = float(value);
            changed = mUi->sliderFloat(p.name, v, float(p.minValue), float(p.maxValue), true);
            value = p.integer ? std::round(v) : v;
        } else if (p.integer) {
            int v = int(value);
            changed = mUi->sliderInt(p.name, v, int(p.minValue), int(p.maxValue));
            value = v;
        } else {
            float v = float(value);
            changed = mUi->sliderFloat(p.name, v, float(p.minValue), float(p.maxValue));
            value = v;
        }
        mUi->tooltip(p.help);
        if (changed && value != mSettings[p.name]) {
            mSettings[p.name] = value;
            mSession.settings[id][p.name] = value;  // kept across technique switches and saved
            mOptions.settings.erase(p.name);         // the user's change wins over the command line
            replan();
        }
    }
}

}  // namespace airlight
