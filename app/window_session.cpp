// The window's session file and its side of the lesson player (LessonHost): what is saved, loaded and
// applied.
#include "gui_app.h"

namespace airlight {

AppState GuiApp::appState() const {
    AppState a;
    static_cast<HeldState&>(a) = mState;
    a.selectedLight = selectedLightIndex();  // kept in range of the scene's lights
    a.defaults = viz::completeSettings(technique(), {});
    a.stageShown = stageShown();
    a.steppedSettings = mState.settings;
    if (mState.cursor.substep > 0) (void)viz::setSubstep(technique(), a.stageShown, a.steppedSettings, mState.cursor.substep);
    a.camera = mController.camera();
    a.orbitTarget = mController.target();
    a.flyCamera = mController.mode() == CameraController::Mode::Fly;
    a.medium = mScene.medium;
    a.lights = mScene.lights;
    a.layout = mGrid.layout.toText();
    a.maximisedView = mGrid.layout.maximised();
    for (int id : mGrid.layout.views()) {
        const ViewState& v = mGrid.views.at(id);
        a.views.push_back({id, v.content, v.layer, v.transform.zoom, v.transform.center, v.display});
    }
    a.inspected = mPendingInspect;
    if (mInspector.active()) a.inspected = mInspector.pixel();
    return a;
}

SessionState GuiApp::currentSession() const {
    SessionState base = mSession;
    base.lesson.clear();
    if (mLesson) mLesson->saveTo(base);
    return sessionOf(appState(), std::move(base));
}

void GuiApp::saveSessionNow() {
    try {
        saveSession(mOptions.statePath, currentSession());
        mNotice = "session saved to " + mOptions.statePath;
    } catch (const viz::InputError& e) {
        mNotice = e.what();
        std::fprintf(stderr, "airlight: %s\n", e.what());
    }
}

void GuiApp::loadSessionNow() {
    std::string problem;
    SessionState loaded = loadSession(mOptions.statePath, problem);
    if (!problem.empty()) {
        mNotice = problem + "; the current session stays";
        return;
    }
    if (!loaded.lesson.empty()) {
        // A lesson position: the step is applied (loading its scene), try-it changes go on top.
        mSession = std::move(loaded);
        mLesson = std::make_unique<LessonPlayer>(mSession.lesson, mLessonSize);
        mLesson->restore(mSession.lessonStep, mSession.lessonTryIt);
        mNotice = "session loaded from " + mOptions.statePath;
        return;
    }
    if (!loaded.scene.empty() && loaded.scene != mState.scene) {
        // The session's own scene, as opening a file would switch to it; one that no longer loads leaves
        // the window as it was.
        try {
            loadLessonScene(loaded.scene);
        } catch (const std::exception& e) {
            mNotice = "the saved session's scene '" + loaded.scene + "' does not load (" + firstLine(e.what()) +
                      "); the current session stays";
            return;
        }
    }
    mLesson.reset();  // a session without a lesson closes the one open
    mSession = std::move(loaded);
    mState.size = {mSession.width, mSession.height};
    restoreSessionOverStep();
    replan();
    mNotice = "session loaded from " + mOptions.statePath;
}

void GuiApp::restoreSessionOverStep() {
    const bool lights = applyLightPlacements(mSession.lights, mScene);
    if (mSession.medium) mScene.medium = *mSession.medium;
    if (mSession.medium || lights) cpuWorker().setScene(mScene);  // the CPU worker keeps its own copy of the scene
    const auto it = std::find(mIds.begin(), mIds.end(), mSession.technique);
    selectTechnique(it == mIds.end() ? currentIndex() : int(it - mIds.begin()));
    applySessionView();
}

void GuiApp::loadLessonScene(const std::string& name) {
    viz::scene::Scene scene = viz::scene::loadScene(name, mOptions.load);  // InputError: the window keeps its scene
    mScene = std::move(scene);
    mFileLighting = lightingOf(mScene);
    mState.scene = name;
    mSceneWatch.watch(name);
    viz::scene::stampGeometry(mScene);
    mState.selectedLight = 0;
    mController = CameraController(mScene.camera, orbitDistance(mScene));
    mGizmoArm = kGizmoArm * mController.targetDistance();
    cpuWorker().setScene(mScene);
    mPanel.forgetValues();
    mNotice = sceneNotesLine(mScene);
    mComparison.close();
    mInspector.clear();
    mDirty = true;
}

LessonWindowState GuiApp::lessonWindowState() const { return lessonStateOf(appState()); }

void GuiApp::applyLessonWindowState(const LessonWindowState& s) {
    bool lighting = s.medium.sigma_s != mScene.medium.sigma_s || s.medium.sigma_a != mScene.medium.sigma_a ||
                    s.medium.g != mScene.medium.g || s.lights.size() != mScene.lights.size();
    for (std::size_t i = 0; !lighting && i < s.lights.size(); ++i) {
        const auto& a = s.lights[i];
        const auto& b = mScene.lights[i];
        lighting = a.position != b.position || a.direction != b.direction || a.intensity != b.intensity || a.colour != b.colour;
    }
    mScene.medium = s.medium;
    mScene.lights = s.lights;
    if (lighting) cpuWorker().setScene(mScene);  // it keeps its own copy of the scene
    mController.place(s.camera, s.orbitTarget);
    mState.size = s.size;
    const auto it = std::find(mIds.begin(), mIds.end(), s.technique);
    if (it == mIds.end()) throw viz::InputError("unknown technique '" + s.technique + "'");
    selectTechnique(int(it - mIds.begin()));  // also drops the last frame: the step's pixel waits for its own
    mState.settings = s.settings;
    mSettingsError.clear();
    const int last = int(technique().stages().size()) - 1;
    mState.cursor = {s.stage >= 0 && s.stage < last ? s.stage : -1, 0};
    // The step's sub-step of the stage it stops in becomes the cursor; a sub-step parameter of an
    // earlier stage stays a setting of the step (the title says the frame is cut short).
    if (auto c = takeSubsteps(technique(), mState.settings, stageShown()); c && c->stage == stageShown())
        mState.cursor.substep = c->substep;
    replan();
    layOutLessonViews(s.views.empty() ? std::vector<std::string>{s.view} : s.views);
    mInspector.clear();
    mPendingInspect = s.inspect;
    mState.exposureSet = false;
    mComparison.close();
}

void GuiApp::layOutLessonViews(const std::vector<std::string>& views) {
    if (views.size() < 2) {
        if (mGrid.lessonGrid) resetLayout(views.empty() ? std::string() : views.front());
        mGrid.lessonGrid = false;
        if (!views.empty()) showInFocusedView(views.front());
        return;
    }
    mState.focusedView = mGrid.lesson(views);
    for (auto& [id, v] : mGrid.views) refreshView(v);
}

// A view of the step already in the grid takes the focus; otherwise the focused view shows it.
void GuiApp::showLessonView(const std::string& id) {
    for (auto& [view, state] : mGrid.views)
        if (state.content == id) {
            mState.focusedView = view;
            return;
        }
    showInFocusedView(id);
}

void GuiApp::showInFocusedView(const std::string& id) {
    ViewState& v = focusedView();
    v.content = id;
    v.layer = 0;
    v.transform.fit();
    refreshView(v);
}

void GuiApp::setLessonSetting(const std::string& name, double value) {
    // A lesson's animation of the shown stage's sub-steps moves the cursor.
    if (substepStageOf(technique(), name) == stageShown()) {
        viz::Settings probe = mState.settings;
        probe[name] = value;
        const viz::SubstepPosition pos = viz::substepPosition(technique(), stageShown(), probe);
        moveCursor({stageShown(), pos.at < pos.count ? pos.at : 0});
        return;
    }
    if (mState.settings.count(name) && mState.settings.at(name) == value) return;
    mState.settings[name] = value;
    mDirty = true;
}

int GuiApp::lessonSubstepCount(int stage) const {
    return substepCountOf(technique(), stage, mState.settings, mOutput.substepCounts);
}

void GuiApp::setLessonLight(const viz::scene::Light& light) {
    // GPU techniques read the scene at every run; the reference (its worker holds a copy of the scene,
    // seconds per frame) keeps the light where it is.
    if (mScene.lights.empty() || !technique().needsGl()) return;
    mScene.lights[0] = light;
    mDirty = true;
}

void GuiApp::applySessionView() {
    if (mSession.camera) mController.place(*mSession.camera, mSession.orbitTarget);
    applySessionGrid();
    mState.exposure = mSession.exposure;
    mState.exposureSet = mSession.exposureSet;
    mDirty = true;
}

void GuiApp::clearPanes() {
    mMarkerCache.clear();
    for (auto& [id, v] : mGrid.views) {
        v.pane = {};
        v.values = {};
        updateStatistics(v);
    }
}

void GuiApp::resetLayout(const std::string& content) { mState.focusedView = mGrid.reset(content); }

void GuiApp::applySessionGrid() {
    try {
        mState.focusedView = mGrid.restore(mSession);
    } catch (const std::exception& e) {
        SessionState pair = mSession;  // the default pair around the session's view
        pair.layout.clear();
        mState.focusedView = mGrid.restore(pair);
        mNotice = std::string("session view grid: ") + e.what() + "; using the default grid";
    }
}

}  // namespace airlight
