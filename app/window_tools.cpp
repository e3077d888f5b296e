// The comparison grid (G) and exporting a view (E) or the window (F12).
#include "gui_app.h"

namespace airlight {

void GuiApp::toggleComparison() {
    if (mComparison.isOpen()) {
        mComparison.close();
        return;
    }
    openComparison(mIds);
}

void GuiApp::openComparison(const std::vector<std::string>& ids) {
    viz::scene::Scene scene = mScene;
    scene.camera = mController.camera();
    try {
        mComparison.open(scene, mState.size, ids);
    } catch (const std::exception& e) {
        mError = std::string("comparison: ") + e.what();
        mComparison.close();
    }
}

void GuiApp::showLessonComparison(const std::vector<std::string>& techniques) {
    mComparison.close();
    if (techniques.empty()) return;
    std::vector<std::string> ids = {"reference"};
    ids.insert(ids.end(), techniques.begin(), techniques.end());
    openComparison(ids);
}

ComparisonGrid::RunTechnique GuiApp::comparisonRunner() {
    return [this](const std::string& id, const viz::scene::Scene& scene, glm::ivec2 size, int frame) {
        RunScheduler& runner = mRuns.runner(Consumer::Others, id);
        runner.invalidate();  // the grid times whole runs: nothing carried over from the last one
        viz::FrameOutput out = runner.run(scene, size.x, size.y, completedOtherSettings(id), {}, {}, frame);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        return out;
    };
}

void GuiApp::runComparisonTechniques() { mComparison.runTechniques(comparisonRunner()); }

std::string GuiApp::exportStem(const std::string& what, std::initializer_list<const char*> extensions) {
    // A file's scene is named by the file (the glTF's own scene name may be another scene's).
    const std::string scene = isSceneFile(mState.scene) ? std::filesystem::path(mState.scene).stem().string() : mScene.name;
    std::string name = scene + "-" + technique().id() + "-" + what;
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
    std::error_code ec;
    std::filesystem::create_directories(mOptions.exportDir, ec);
    // A name none of whose files exist yet (name, name-2, name-3, ...): exporting again after a change
    // never writes over an earlier export.
    const std::filesystem::path base = std::filesystem::path(mOptions.exportDir) / name;
    const auto taken = [&](const std::string& stem) {
        for (const char* ext : extensions)
            if (std::filesystem::exists(std::filesystem::symlink_status(stem + ext, ec))) return true;
        return false;
    };
    std::string stem = base.string();
    for (int n = 2; taken(stem) && n <= kMaxExportsOfOneName; ++n) stem = base.string() + "-" + std::to_string(n);
    if (taken(stem))
        throw viz::InputError("not exported: '" + base.string() + "' to '-" + std::to_string(kMaxExportsOfOneName) +
                              "' all exist in " + mOptions.exportDir);
    return stem;
}

bool GuiApp::focusedViewImage(viz::Image& image, float& exposure) {
    ViewState& v = focusedView();
    if (!mHaveOutput || v.pane.texture == 0) return false;
    // The view's CPU copy, read back after each run (not during a drag's reduced runs: then read now).
    if (v.values.empty()) readBackValues(v);
    if (v.values.empty()) return false;
    const viz::Image& values = v.values;
    const DisplayMapping m = resolveMapping(v.pane, v.display, mState.exposure, v.measured);
    const bool colour = m.mode == DisplayMode::HdrColour || m.mode == DisplayMode::RangeColour;
    image = colour ? values : viz::toDisplay(values, m.lo, m.hi);
    exposure = colour ? std::exp2(m.exposure) : 1.0f;
    return true;
}

void GuiApp::exportView() {
    if (mAnimation.playing) {
        toggleRecording();
        return;
    }
    const PaneImage& pane = focusedView().pane;
    viz::Image shown;
    float exposure = 1.0f;
    if (!focusedViewImage(shown, exposure)) {
        mNotice = "nothing to export: the view holds no image";
        return;
    }
    try {
        const std::string stem = exportStem(pane.id.empty() ? "view" : pane.id, {".exr", ".png"});
        viz::writeImage(focusedView().values, stem + ".exr");
        viz::writeImage(shown, stem + ".png", exposure);
        mNotice = "exported " + stem + ".exr and .png";
    } catch (const viz::InputError& e) {
        mNotice = e.what();
    }
}

void GuiApp::toggleRecording() {
    if (mAnimation.recorder.recording()) {
        stopRecording();
        return;
    }
    const PaneImage& pane = focusedView().pane;
    try {
        mAnimation.recorder.start(exportStem(pane.id.empty() ? "view" : pane.id, {".gif"}) + ".gif");
    } catch (const viz::InputError& e) {
        mNotice = e.what();
        return;
    }
    mAnimation.recordStart = mAnimation.clock;
    mNotice = "recording the focused view: E or P stops and writes the GIF";
}

void GuiApp::stopRecording() {
    if (!mAnimation.recorder.recording()) return;
    // The animation's own clock: frames over the seconds it played (1/30 s a frame under automation).
    const double seconds = mAnimation.clock - mAnimation.recordStart;
    const int fps = seconds > 0.0 ? int(std::lround(double(mAnimation.recorder.frames()) / seconds)) : 25;
    mNotice = mAnimation.recorder.finish(fps);
}

void GuiApp::exportWindow() {
    try {
        const std::string path = exportStem("window", {".png", ".json"}) + ".png";
        writeScreenshot(path);
        mNotice = "wrote " + path;
    } catch (const viz::InputError& e) {
        mNotice = e.what();
    }
}

}  // namespace airlight
