// The scene and parameter panel (parameter_panel.h) in the window: its edits carried out (a scene to
// load, a file to open, settings to keep, the scene edited), and the scene file's loading and reloading
// (which keeps the user's edits of the medium and the lights: reload_merge.h).
#include "gui_app.h"

namespace airlight {

void GuiApp::drawParameters(glm::ivec2 fb) {
    (void)fb;
    if (mParamsRect.size().y > 0.0f) {
        mUi->beginPanel("Scene and parameters", mParamsRect);
        const viz::Plan& plan = shownPlan();
        const ParameterPanelEdits edits = mPanel.draw(*mUi, mScene, mState.selectedLight,
                                                      {mState.scene, &technique(), &mState.settings, &plan, mTextTab, mTextEnter});
        mUi->endPanel();
        // Loaded at the start of the next frame: this frame's views (and the comparison grid's tiles) are
        // queued for drawing with the textures the scene change would release.
        if (edits.pickScene) mPendingScene = edits.pickScene;
        if (edits.openFile) openSceneFile(*edits.openFile);
        // The user's change wins over the command line, and is kept across technique switches and saved.
        for (const auto& [name, value] : edits.settings) {
            mState.settings[name] = value;
            mSession.settings[mState.technique][name] = value;
            for (auto& [id, given] : mOptions.settings) given.erase(name);
            for (auto& [id, refused] : mOptions.settingErrors) refused.erase(name);
        }
        if (!edits.settings.empty()) replan();
        if (edits.sceneEdited) sceneEdited();
    }
    mTextTab = mTextEnter = false;
    if (mLesson) mLesson->draw(*this, *mUi, *mDrawList, *mBackground, mScale);
    mUi->endFrame();
}

void GuiApp::openSceneFile(const std::string& path) {
    std::error_code ec;
    if (!isSceneFile(path)) mError = "cannot open '" + path + "': not a .gltf or .glb file";
    else if (!std::filesystem::is_regular_file(path, ec)) mError = "cannot open '" + path + "': no such file";
    else mPendingScene = path;
}

void GuiApp::reloadScene() {
    ReloadMerge merge;
    try {
        viz::scene::Scene scene = viz::scene::loadScene(mState.scene, mOptions.load);
        // The user's edits of the medium and the lights stay where the file left those values alone.
        SceneLighting fresh = lightingOf(scene);
        merge = keepUserEdits(mFileLighting, mScene, scene);
        mFileLighting = std::move(fresh);
        mScene = std::move(scene);
        viz::scene::stampGeometry(mScene);
    } catch (const std::exception& e) {
        mError = "reloading " + sceneTitle() + " failed, the scene is kept as it was: " + firstLine(e.what());
        return;
    }
    cpuWorker().setScene(mScene);
    mComparison.close();  // its tiles show the old scene (this runs before the frame is laid out)
    mNotice = "reloaded " + sceneTitle() + " (changed on disk)" + merge.summary;
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

}  // namespace airlight
