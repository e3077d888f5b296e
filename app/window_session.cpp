// The window's session file and its side of the lesson player (LessonHost): what is saved, loaded and
// applied.
#include "gui_app.h"

namespace airlight {

SessionState GuiApp::currentSession() const {
    SessionState s = mSession;
    s.scene = mOptions.scene;
    s.technique = mIds[std::size_t(mCurrent)];
    s.width = mOptions.width;
    s.height = mOptions.height;
    s.camera = mController.camera();
    s.orbitTarget = mController.target();
    s.medium = mScene.medium;
    s.lights = lightPlacements(mScene);
    // Only what differs from the technique's defaults is kept, per technique.
    const auto defaults = viz::completeSettings(technique(), {});
    viz::Settings changed;
    for (const auto& [name, value] : mSettings)
        if (!defaults.count(name) || defaults.at(name) != value) changed[name] = value;
    s.settings[s.technique] = changed;
    // The first view in reading order that is not the final frame, for files read by older builds.
    s.view = "airlight";
    for (int id : mLayout.views())
        if (mViews.at(id).content != "final") {
            s.view = mViews.at(id).content;
            s.viewZoom = mViews.at(id).transform.zoom;
            s.viewCenter = mViews.at(id).transform.center;
            break;
        }
    s.layout = mLayout.toText();
    s.focusedView = mFocused;
    s.maximisedView = mLayout.maximised();
    s.gridViews.clear();
    for (int id : mLayout.views()) {
        const ViewState& v = mViews.at(id);
        const DisplaySettings& d = v.display;
        s.gridViews.push_back({id, v.content, v.layer, v.transform.zoom, v.transform.center, int(d.channel),
                               int(d.range), int(d.colourMap), int(d.difference), d.manualMin, d.manualMax,
                               d.markNegative, d.logScale, d.stripOpen, d.against});
    }
    s.exposure = mExposure;
    s.exposureSet = mExposureSet;
    s.lesson.clear();
    if (mLesson) mLesson->saveTo(s);
    return s;
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
        mNotice = problem;  // the current session stays as it is
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
    if (!loaded.scene.empty() && loaded.scene != mOptions.scene) {
        mNotice = "the saved session is for scene '" + loaded.scene + "': restart with --state to switch scenes";
        return;
    }
    mLesson.reset();  // a session without a lesson closes the one open
    mSession = std::move(loaded);
    restoreSessionOverStep();
    mNotice = "session loaded from " + mOptions.statePath;
}

void GuiApp::restoreSessionOverStep() {
    const bool lights = applyLightPlacements(mSession.lights, mScene);
    if (mSession.medium) mScene.medium = *mSession.medium;
    if (mSession.medium || lights) mWorker->setScene(mScene);  // the CPU worker keeps its own copy of the scene
    const auto it = std::find(mIds.begin(), mIds.end(), mSession.technique);
    selectTechnique(it == mIds.end() ? mCurrent : int(it - mIds.begin()));
    applySessionView();
}

void GuiApp::loadLessonScene(const std::string& name) {
    viz::scene::Scene scene = viz::scene::loadScene(name, mOptions.load);  // InputError: the window keeps its scene
    mScene = std::move(scene);
    mOptions.scene = name;
    mSceneWatch.watch(name);
    mLight = 0;
    mController = CameraController(mScene.camera, orbitDistance(mScene));
    mGizmoArm = kGizmoArm * mController.targetDistance();
    mWorker->setScene(mScene);
    mLightIntensityOff = 0.0;
    mNotice = sceneNotesLine(mScene);
    mComparison.close();
    mProbe.reset();
    mDirty = true;
}

LessonWindowState GuiApp::lessonWindowState() const {
    LessonWindowState s;
    s.scene = mOptions.scene;
    s.technique = mIds[std::size_t(mCurrent)];
    s.size = {mOptions.width, mOptions.height};
    s.settings = mSettings;
    s.stage = stageShown();
    // The lesson speaks in settings: the cursor's sub-step is its stage's parameter there.
    if (mCursor.substep > 0) (void)viz::setSubstep(technique(), s.stage, s.settings, mCursor.substep);
    s.view = mViews.count(mFocused) ? mViews.at(mFocused).content : std::string("airlight");
    s.inspect = mPendingInspect;
    if (mProbe) s.inspect = glm::ivec2(mProbe->x, mProbe->y);
    s.camera = mController.camera();
    s.orbitTarget = mController.target();
    s.medium = mScene.medium;
    s.lights = mScene.lights;
    return s;
}

void GuiApp::applyLessonWindowState(const LessonWindowState& s) {
    bool lighting = s.medium.sigma_s != mScene.medium.sigma_s || s.medium.sigma_a != mScene.medium.sigma_a ||
                    s.medium.g != mScene.medium.g || s.lights.size() != mScene.lights.size();
    for (std::size_t i = 0; !lighting && i < s.lights.size(); ++i) {
        const auto& a = s.lights[i];
        const auto& b = mScene.lights[i];
        lighting = a.position != b.position || a.direction != b.direction || a.intensity != b.intensity || a.color != b.color;
    }
    mScene.medium = s.medium;
    mScene.lights = s.lights;
    if (lighting) mWorker->setScene(mScene);  // it keeps its own copy of the scene
    mController.place(s.camera, s.orbitTarget);
    mOptions.width = s.size.x;
    mOptions.height = s.size.y;
    const auto it = std::find(mIds.begin(), mIds.end(), s.technique);
    if (it == mIds.end()) throw viz::InputError("unknown technique '" + s.technique + "'");
    selectTechnique(int(it - mIds.begin()));  // also drops the last frame: the step's pixel waits for its own
    mSettings = s.settings;
    mSettingsError.clear();
    const int last = int(technique().stages().size()) - 1;
    mCursor = {s.stage >= 0 && s.stage < last ? s.stage : -1, 0};
    // The step's sub-step of the stage it stops in becomes the cursor; a sub-step parameter of an
    // earlier stage stays a setting of the step (the title says the frame is cut short).
    if (auto c = takeSubsteps(technique(), mSettings, stageShown()); c && c->stage == stageShown())
        mCursor.substep = c->substep;
    replan();
    showInFocusedView(s.view);
    mProbe.reset();
    mPendingInspect = s.inspect;
    mExposureSet = false;
    mComparison.close();
}

void GuiApp::showLessonView(const std::string& id) { showInFocusedView(id); }

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
        viz::Settings probe = mSettings;
        probe[name] = value;
        const viz::SubstepPosition pos = viz::substepPosition(technique(), stageShown(), probe);
        moveCursor({stageShown(), pos.at < pos.count ? pos.at : 0});
        return;
    }
    if (mSettings.count(name) && mSettings.at(name) == value) return;
    mSettings[name] = value;
    mDirty = true;
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
    mExposure = mSession.exposure;
    mExposureSet = mSession.exposureSet;
    mDirty = true;
}

void GuiApp::clearPanes() {
    mMarkerCache.clear();
    for (auto& [id, v] : mViews) {
        v.pane = {};
        v.values = {};
        updateStatistics(v);
    }
}

void GuiApp::resetLayout(const std::string& content) {
    mLayout = ViewLayout(0);
    mLayout.split(0, SplitAxis::X, 1);
    mViews.clear();
    mViews[0].content = "final";
    mViews[1].content = content.empty() ? "airlight" : content;
    mFocused = 1;
    mNextView = 2;
}

void GuiApp::applySessionGrid() {
    resetLayout(mSession.view);
    mViews[1].transform.zoom = mSession.viewZoom;
    mViews[1].transform.center = mSession.viewCenter;
    mViews[1].transform.clampCenter();
    if (mSession.layout.empty()) return;
    try {
        ViewLayout layout = ViewLayout::fromText(mSession.layout);
        std::map<int, ViewState> views;
        for (int id : layout.views()) views[id];
        for (const SessionState::GridView& g : mSession.gridViews) {
            if (!views.count(g.id)) continue;
            ViewState& v = views[g.id];
            v.content = g.content;
            v.layer = std::max(0, g.layer);
            v.transform.zoom = g.zoom;
            v.transform.center = g.center;
            v.transform.clampCenter();
            DisplaySettings& d = v.display;
            d.channel = Channel(g.channel);
            d.range = RangeMode(g.range);
            d.colourMap = ColourMap(g.colourMap);
            d.difference = DifferenceMode(g.difference);
            d.manualMin = g.manualMin;
            d.manualMax = g.manualMax;
            d.logScale = g.logScale;
            d.markNegative = g.markNegative;
            d.stripOpen = g.stripOpen;
            d.against = g.against;
        }
        mLayout = std::move(layout);
        mViews = std::move(views);
        mFocused = mLayout.contains(mSession.focusedView) ? mSession.focusedView : mLayout.views().front();
        if (mSession.maximisedView >= 0 && mLayout.contains(mSession.maximisedView))
            mLayout.toggleMaximise(mSession.maximisedView);
        mNextView = 0;
        for (int id : mLayout.views()) mNextView = std::max(mNextView, id + 1);
    } catch (const std::exception& e) {
        mNotice = std::string("session view grid: ") + e.what() + "; using the default grid";
    }
}

}  // namespace airlight
