// The scene and parameter panel: scene and stiff-case pickers, medium, lights, preset, the technique's
// declared parameters and its plan.
#include "gui_app.h"
#include "parameter_widgets.h"
#include "plan_panel.h"

namespace airlight {

void GuiApp::drawParameters(glm::ivec2 fb) {
    (void)fb;
    if (mParamsRect.size().y > 0.0f) {
        mUi->beginPanel("Scene and parameters", mParamsRect);
        scenePicker();
        bool sceneChanged = false;
        if (mUi->collapsingHeader("Medium", true))
            sceneChanged = mediumWidgets(*mUi, mScene.medium, mSigmaSSlider, mSigmaASlider);
        if (mScene.lights.size() > 1) {
            // Every light is editable: the panel and the gizmo work on the one picked here.
            std::vector<std::string> names;
            for (std::size_t i = 0; i < mScene.lights.size(); ++i)
                names.push_back(std::to_string(i + 1) + ": " + (mScene.lights[i].name.empty() ? "light" : mScene.lights[i].name) +
                                " (" + lightTypeName(mScene.lights[i].type) + ")");
            int picked = selectedLightIndex();
            if (mUi->combo("light", picked, names)) {
                mState.selectedLight = picked;
                mIntensitySlider.forget();
            }
        }
        if (!mScene.lights.empty() && mUi->collapsingHeader("Light: " + selectedLight().name, true)) {
            sceneChanged = mIntensitySlider.draw(*mUi, "on", "intensity", selectedLight().intensity) || sceneChanged;
        }
        // Folded by default: the technique's parameters stay in view on small windows.
        if (!mScene.lights.empty() && mUi->collapsingHeader("Light placement", false)) {
            sceneChanged = lightPlacementWidgets(*mUi, selectedLight(), orbitDistance(mScene)) || sceneChanged;
        }
        if (mUi->collapsingHeader(technique().id() + " parameters", true)) parameterWidgets();
        drawPlanSection(*mUi, shownPlan());
        mUi->endPanel();
        if (sceneChanged) sceneEdited();
    }
    if (mLesson) mLesson->draw(*this, *mUi, *mDrawList, *mBackground, mScale);
    mUi->endFrame();
}

void GuiApp::scenePicker() {
    if (mSceneChoices.empty()) {
        mSceneChoices = viz::scene::builtinSceneNames();
        mStiffChoices = {"(none)"};
        for (const auto& c : viz::scene::stiffCases()) mStiffChoices.push_back("stiff/" + c.id);
    }
    const bool stiff = mState.scene.rfind("stiff/", 0) == 0;
    std::vector<std::string> scenes = mSceneChoices;
    if (!stiff && std::find(scenes.begin(), scenes.end(), mState.scene) == scenes.end())
        scenes.push_back(mState.scene);
    int sceneIndex = stiff ? -1 : int(std::find(scenes.begin(), scenes.end(), mState.scene) - scenes.begin());
    std::string picked;
    if (mUi->combo("scene", sceneIndex, scenes)) picked = scenes[std::size_t(sceneIndex)];
    mUi->tooltip("the built-in scenes (and a glTF file given with --scene)");
    int stiffIndex = 0;
    if (stiff) {
        const auto at = std::find(mStiffChoices.begin(), mStiffChoices.end(), mState.scene);
        stiffIndex = at == mStiffChoices.end() ? 0 : int(at - mStiffChoices.begin());
    }
    if (mUi->combo("stiff case", stiffIndex, mStiffChoices) && stiffIndex > 0)
        picked = mStiffChoices[std::size_t(stiffIndex)];
    mUi->tooltip("the stiff and extreme cases (README: Stiff and extreme cases)");
    openFileWidgets();
    // Loaded at the start of the next frame: this frame's views (and the comparison grid's tiles) are
    // queued for drawing with the textures the scene change would release.
    if (!picked.empty() && picked != mState.scene) mPendingScene = picked;
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
        viz::scene::Scene scene = viz::scene::loadScene(mState.scene, mOptions.load);
        mScene = std::move(scene);
        mGeometryHash = viz::scene::geometryContentHash(mScene);
    } catch (const std::exception& e) {
        mError = "reloading " + sceneTitle() + " failed, the scene is kept as it was: " + firstLine(e.what());
        return;
    }
    cpuWorker().setScene(mScene);
    mComparison.close();  // its tiles show the old scene (this runs before the frame is laid out)
    mNotice = "reloaded " + sceneTitle() + " (changed on disk)";
    if (const std::string notes = sceneNotesLine(mScene); !notes.empty()) mNotice += "; " + notes;
    replan();
    mDirty = true;
}

std::string GuiApp::sceneTitle() const {
    if (!isSceneFile(mState.scene)) return mScene.name;
    const std::filesystem::path file(mState.scene);
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

void GuiApp::parameterWidgets() {
    const std::string id = mState.technique;
    // The user's change wins over the command line, and is kept across technique switches and saved.
    const auto set = [&](const std::string& name, double value) {
        mState.settings[name] = value;
        mSession.settings[id][name] = value;
        mOptions.settings.erase(name);
    };
    std::string ignored;  // mState.settings were validated when they were set
    if (const auto preset = presetWidget(*mUi, technique(), settingsFor(technique(), mState.settings, ignored))) {
        for (const auto& [name, value] : *preset) set(name, value);
        replan();
    }
    for (const viz::ParamInfo& p : technique().params()) {
        // Sub-steps are the stepping cursor's (S, D, the timeline), not settings.
        if (substepStageOf(technique(), p.name) >= 0) continue;
        double value = mState.settings.count(p.name) ? mState.settings.at(p.name) : p.defaultValue;
        if (parameterWidget(*mUi, p, value)) {
            set(p.name, value);
            replan();
        }
    }
}

}  // namespace airlight
