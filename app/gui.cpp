// The window: one GLFW window with a grid of views the user arranges (the final frame, L_air and any
// intermediate; split, close, swap, maximise; linked cursors; per-view display strips and difference
// views; app/view_layout.h, view_state.h) or the comparison grid, a clickable technique list, a views
// list (what the focused view shows), a status line with the stage shown, per-stage timings and the
// plan's skipped stages, the ray inspector or timing bars under the grid, the scene and parameter panel
// (immediate-mode widgets) beside them, and an orbit/fly camera. GPU techniques run on the main thread
// whenever the camera, the settings or the technique change; CPU techniques (the reference) run on a
// worker thread in progressive passes (1/4, 1/2, then full resolution) so the window never freezes.
#include "gui_app.h"

#include <cstdlib>

#include "gl/gpu_timer.h"

namespace airlight {

GuiApp::GuiApp(const GuiOptions& options, viz::scene::Scene scene, SceneLighting fileLighting, viz::Window& window,
               SessionState session, std::string notice)
    : mOptions(options)
    , mScript(options.script, options.scriptPath)
    , mSession(std::move(session))
    , mNotice(std::move(notice))
    , mScene(std::move(scene))
    , mWindow(window)
    , mFileLighting(std::move(fileLighting))
    , mController(mScene.camera, orbitDistance(mScene))
    , mGizmoArm(kGizmoArm * mController.targetDistance())
    , mIds(viz::techniqueIds()) {
    if (mNotice.empty()) mNotice = sceneNotesLine(mScene);
    float sx = 1.0f, sy = 1.0f;
    glfwGetWindowContentScale(mWindow.handle(), &sx, &sy);
    mContentScale = std::max(1.0f, std::max(sx, sy));
    mUiScale = std::clamp(options.uiScale, kMinUiScale, kMaxUiScale);
    mScale = mContentScale * mUiScale;
    mFont = std::make_unique<viz::ui::FontAtlas>(
        viz::ui::FontAtlas::bake(viz::ui::FontAtlas::defaultFontPath(), kFontSize * mScale));
    mTextRenderer = std::make_unique<viz::ui::TextRenderer>(*mFont);
    mUi = std::make_unique<viz::ui::Context>(*mFont);
    mDrawList = std::make_unique<DrawList>(*mFont);
    mBackground = std::make_unique<DrawList>(*mFont);
    mCanvas.overlay = mDrawList.get();
    mCanvas.background = mBackground.get();
    mCanvas.font = mFont.get();
    mImageDisplay = std::make_unique<ImageDisplay>();
    (void)cpuWorker();  // the main views' CPU worker starts with the window
    std::string wanted = options.technique.empty() ? mIds.front() : options.technique;
    if (!options.techniqueGiven && !mSession.technique.empty() &&
        std::find(mIds.begin(), mIds.end(), mSession.technique) != mIds.end())
        wanted = mSession.technique;
    mState.technique = std::find(mIds.begin(), mIds.end(), wanted) == mIds.end() ? mIds.front() : wanted;
    mState.scene = options.scene;
    mState.size = {options.width, options.height};
    mClockName = viz::gl::StageClock::method();
    // Where GL timer queries measure the work, the main views' stages are timed without waiting for the
    // GPU (the times shown are a frame or a few old); AIRLIGHT_GPU_TIMER=1 forces it (tests on llvmpipe,
    // where its times mean nothing).
    const char* forced = std::getenv("AIRLIGHT_GPU_TIMER");
    if (mClockName == viz::gl::StageClock::methodName(viz::gl::ClockMethod::TimestampQuery) ||
        (forced && std::string(forced) == "1"))
        mGpuTimer = std::make_unique<viz::gl::GpuTimer>();
    mRuns.setViewsTimer(mGpuTimer.get());

    glfwSetWindowUserPointer(mWindow.handle(), this);
    glfwSetKeyCallback(mWindow.handle(), [](GLFWwindow* w, int key, int, int action, int mods) {
        static_cast<GuiApp*>(glfwGetWindowUserPointer(w))->onKey(key, action, mods);
    });
    glfwSetCharCallback(mWindow.handle(), [](GLFWwindow* w, unsigned codepoint) {
        static_cast<GuiApp*>(glfwGetWindowUserPointer(w))->onChar(codepoint);
    });
    glfwSetMouseButtonCallback(mWindow.handle(), [](GLFWwindow* w, int button, int action, int) {
        static_cast<GuiApp*>(glfwGetWindowUserPointer(w))->onMouseButton(button, action);
    });
    glfwSetCursorPosCallback(mWindow.handle(), [](GLFWwindow* w, double x, double y) {
        static_cast<GuiApp*>(glfwGetWindowUserPointer(w))->onCursor(x, y);
    });
    glfwSetScrollCallback(mWindow.handle(), [](GLFWwindow* w, double, double dy) {
        static_cast<GuiApp*>(glfwGetWindowUserPointer(w))->onScroll(dy);
    });
    glfwSetDropCallback(mWindow.handle(), [](GLFWwindow* w, int count, const char** paths) {
        std::vector<std::string> dropped;
        for (int i = 0; i < count; ++i) dropped.emplace_back(paths[i]);
        static_cast<GuiApp*>(glfwGetWindowUserPointer(w))->onDrop(dropped);
    });
    if (!options.path.empty()) {
        mAnimation.path = viz::scene::parseMotionPath(options.path);
        mAnimation.pathFrames = options.pathFrames;
    }
    mSceneWatch.watch(mState.scene);
    viz::scene::stampGeometry(mScene);
    selectTechnique(currentIndex());
    applySessionView();
    const std::string lesson = !options.lesson.empty() ? options.lesson : mSession.lesson;
    if (options.sizeGiven) mLessonSize = {options.width, options.height};
    if (!lesson.empty()) {
        mLesson = std::make_unique<LessonPlayer>(lesson, mLessonSize);
        if (lesson == mSession.lesson) mLesson->restore(mSession.lessonStep, mSession.lessonTryIt);
    }
}

GuiApp::~GuiApp() {
    glfwSetWindowUserPointer(mWindow.handle(), nullptr);
    glfwSetKeyCallback(mWindow.handle(), nullptr);
    glfwSetCharCallback(mWindow.handle(), nullptr);
    glfwSetMouseButtonCallback(mWindow.handle(), nullptr);
    glfwSetCursorPosCallback(mWindow.handle(), nullptr);
    glfwSetScrollCallback(mWindow.handle(), nullptr);
    glfwSetDropCallback(mWindow.handle(), nullptr);
    glfwSetCursor(mWindow.handle(), nullptr);
    for (GLFWcursor* cursor : {mColumnCursor, mRowCursor})
        if (cursor) glfwDestroyCursor(cursor);
    // Panes may borrow the techniques' textures: drop them first.
    mGrid.views.clear();
    mComparison.close();
    mOutput = {};
    mRuns.clear();
}

int GuiApp::run() {
    auto last = Clock::now();
    while (!mWindow.shouldClose()) {
        const bool flying = mController.mode() == CameraController::Mode::Fly && anyFlyKeyDown();
        const bool busy = cpuWorker().progress().busy || mDifferenceRuns.pending() || mComparison.pending();
        const bool automated = !mOptions.screenshot.empty() || !mOptions.script.empty();
        if (flying || mDirty || automated || mAnimation.playing || mDifferenceRuns.due() || mComparison.due() ||
            (mLesson && mLesson->animating())) {
            glfwPollEvents();
        } else {
            // Nothing animates: sleep until input arrives, waking a few times a second while the
            // worker computes so that its progress stays current.
            glfwWaitEventsTimeout(busy ? 0.1 : 0.5);
        }
        const auto now = Clock::now();
        const double dt = std::min(0.1, std::chrono::duration<double>(now - last).count());
        last = now;
        loadPendingScene();
        if (mSceneWatch.changed(now)) reloadScene();
        if (mDifferenceRuns.due()) runDueGpuOthers();  // after a frame that said "computing it..."
        if (mComparison.due()) runComparisonTechniques();
        if (mController.mode() == CameraController::Mode::Fly) fly(dt);
        // Automation advances animations by a fixed 1/30 s per frame, so runs repeat exactly.
        if (mLesson) mLesson->update(*this, automated ? 1.0 / 30.0 : dt);
        if (mAnimation.playing) advanceAnimation(automated ? 1.0 / 30.0 : dt);
        if (mReduced && mDragButton < 0 && !mGizmoDrag && !anyFlyKeyDown()) mDirty = true;
        // A view now shows (or no longer shows) something the technique draws only on demand.
        if (!mDirty && mHaveOutput && technique().needsGl()) {
            const RunScheduler& runner = mRuns.at(Consumer::Views, technique().id());
            if (runner.onDemandAmong(shownContents()) != runner.lastViews()) mDirty = true;
        }
        if (mDirty) {
            // A slow GPU run blocks this thread: first show a frame that says so.
            if (technique().needsGl() && (!mHaveOutput || mLastRunSeconds > 0.3)) {
                mRendering = true;
                draw();
                mWindow.swapBuffers();
                mRendering = false;
            }
            render();
        }
        if (auto result = cpuWorker().take()) acceptCpuResult(std::move(*result));
        // A lesson step's pixel: inspected once its full-size result is in (the value beside the truth).
        if (mPendingInspect && mHaveOutput && mPass == mPassCount && !cpuWorker().progress().busy) {
            inspectPixel(mPendingInspect->x, mPendingInspect->y);
            mPendingInspect.reset();
        }
        pollOtherWorker();
        mComparison.poll();
        draw();
        ++mFramesDrawn;
        if (!mOptions.script.empty()) {
            // Each frame runs the script's next actions; the window closes when it is done.
            // Each action waits for the runs it caused, but a held key counts window frames as a user's
            // would: flying with a CPU technique shown asks for a new frame every frame.
            const bool settled = mHaveOutput && !cpuWorker().progress().busy && !mDifferenceRuns.pending() &&
                                 !mComparison.pending() && !mAnimation.reference.busy();
            if ((settled || mScript.heldKey() >= 0) && !mScript.step(*this)) {
                if (!mOptions.screenshot.empty()) writeScreenshot(mOptions.screenshot);
                return 0;
            }
        } else if (automated && mFramesDrawn >= mOptions.frames && mHaveOutput && !cpuWorker().progress().busy &&
                   !mDifferenceRuns.pending()) {
            writeScreenshot(mOptions.screenshot);
            return 0;
        }
        mWindow.swapBuffers();
    }
    if (mOptions.screenshot.empty() && mOptions.script.empty()) saveSessionNow();
    return 0;
}

int GuiApp::currentIndex() const {
    const auto it = std::find(mIds.begin(), mIds.end(), mState.technique);
    return it == mIds.end() ? 0 : int(it - mIds.begin());
}

void GuiApp::selectTechnique(int index) {
    const int n = int(mIds.size());
    index = ((index % n) + n) % n;
    const std::string& id = mIds[std::size_t(index)];
    try {
        (void)mRuns.runner(Consumer::Views, id);
    } catch (const std::exception& e) {
        mError = e.what();
        return;
    }
    mState.technique = id;
    mState.cursor = {};  // a new technique starts on its complete frame
    mError.clear();
    mSettingsError.clear();
    mState.settings = settingsFor(technique(), givenSettings(id), mSettingsError);
    if (const std::string* refused = firstRefusal(mOptions.settingErrors, id); refused && mSettingsError.empty())
        mSettingsError = *refused;
    if (auto c = takeSubsteps(technique(), mState.settings)) mState.cursor = *c;
    try {
        mPlan = technique().plan(mScene, mState.settings);
    } catch (const std::exception& e) {
        mPlan = {};
        mError = e.what();
    }
    // The previous technique's frame does not belong to this one.
    clearPanes();
    mOutput = {};
    mHaveOutput = false;
    mPass = 0;
    mWindow.setTitle("Airlight - " + sceneTitle() + " - " + id);
    mDirty = true;
}

void GuiApp::render() {
    mDirty = false;
    mScene.camera = mController.camera();
    viz::Technique& t = technique();
    if (!t.needsGl()) {
        mReduced = false;  // the worker's progressive passes play that role
        // While the animation plays a CPU technique keeps its still frame (seconds a pass: a request per
        // played frame would supersede every pass before it finished); play stopping asks again.
        if (mAnimation.playing && (mHaveOutput || cpuWorker().progress().busy)) return;
        cpuWorker().submit({t.id(), mScene.camera, mState.settings, mState.size.x, mState.size.y});
        return;
    }
    glm::ivec2 size = mState.size;
    // While the camera is being dragged or flown, render at half size to keep up; the full size
    // follows when the interaction stops.
    mReduced = (mDragButton >= 0 || mGizmoDrag || anyFlyKeyDown()) && size.x >= 64 && size.y >= 48;
    if (mReduced) size /= 2;
    // What the views show, stand-ins included, before the panes that say so are cleared.
    const std::vector<std::string> shownViews = shownContents();
    // Panes borrow textures the run is about to replace.
    clearPanes();
    const auto start = Clock::now();
    try {
        // The scheduler re-runs only the stages whose inputs changed (a sub-step: its stage alone).
        mOutput = mRuns.runner(Consumer::Views, t.id()).run(mScene, size.x, size.y, mState.settings, mState.cursor, shownViews, mAnimation.frame);
        // While playing, the temporal views: this frame's L_air against the previous one's, and its error
        // against the reference's frames when they are known (--path).
        if (mAnimation.playing && mAnimation.temporal.add(mOutput.airlight, pathReferenceFrame())) {
            mOutput.intermediates.push_back(mAnimation.temporal.view());
            if (mAnimation.temporal.errorPairs() > 0) mOutput.intermediates.push_back(mAnimation.temporal.errorView());
        }
        mError.clear();
        mHaveOutput = true;
        mPass = 1;
        mPassCount = 1;
        mOutputSize = size;
    } catch (const std::exception& e) {
        mError = e.what();
        mOutput = {};
        mHaveOutput = false;
    }
    mLastRunSeconds = std::chrono::duration<double>(Clock::now() - start).count();
    // The technique leaves its own framebuffer and state behind.
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    refreshPanes();
    if (mAnimation.recorder.recording()) {
        viz::Image shown;
        float exposure = 1.0f;
        if (focusedViewImage(shown, exposure) && !mAnimation.recorder.add(shown, exposure)) stopRecording();  // full
    }
}

void GuiApp::acceptCpuResult(CpuResult result) {
    // From a technique no longer shown, or older than the pass shown. A pass of a request that a later
    // one superseded (the camera moved while it ran) is shown until the later one's passes replace it:
    // while the camera flies, the latest pass finished is the view's preview.
    if (result.technique != mState.technique || result.ticket < mCpuShownTicket) return;
    mCpuShownTicket = result.ticket;
    if (!result.error.empty()) {
        mError = result.error;
        return;
    }
    mError.clear();
    mOutput = std::move(result.output);
    mOutputSize = {mOutput.final.width, mOutput.final.height};
    mHaveOutput = true;
    mPass = result.pass;
    mPassCount = result.passCount;
    refreshPanes();
}

void GuiApp::sceneEdited() {
    cpuWorker().setScene(mScene);
    replan();
}

void GuiApp::replan() {
    try {
        mPlan = technique().plan(mScene, mState.settings);
    } catch (const std::exception& e) {
        mError = e.what();
    }
    mDirty = true;
}

int runGui(const GuiOptions& options) {
    if (options.width < 1 || options.height < 1) throw viz::InputError("render size must be at least 1x1");
    // The session named with --state: one that does not exist yet starts there; a file that is not a
    // session stops here, untouched (session_state.h).
    SessionState session;
    std::string notice;
    GuiOptions effective = options;
    if (options.loadStateAtStart) {
        SessionRead read = loadNamedSession(options.statePath);
        session = std::move(read.state);
        notice = std::move(read.problem);
        if (!notice.empty()) std::fprintf(stderr, "airlight: note: %s\n", notice.c_str());
        if (!options.sceneGiven && !session.scene.empty()) effective.scene = session.scene;
        if (notice.empty()) {
            if (!options.sizeGiven) effective.width = session.width, effective.height = session.height;
            notice = "session loaded from " + options.statePath;
        }
        // A session whose scene cannot be loaded any more falls back to the default scene.
        if (effective.scene != options.scene) {
            try {
                (void)viz::scene::loadScene(effective.scene, options.load);
            } catch (const viz::InputError& e) {
                notice = "session scene: " + std::string(e.what()) + "; using '" + options.scene + "'";
                std::fprintf(stderr, "airlight: note: %s\n", notice.c_str());
                effective.scene = options.scene;
                session = SessionState{};
            }
        }
    }
    // Everything that can fail on user input fails before the window opens.
    viz::scene::Scene scene = viz::scene::loadScene(effective.scene, options.load);
    SceneLighting fileLighting = lightingOf(scene);  // before the session's edits: a reload keeps those
    if (session.medium && effective.scene == session.scene) scene.medium = *session.medium;
    if (effective.scene == session.scene) applyLightPlacements(session.lights, scene);
    // A path that cannot move this scene (a light motion without a movable light) fails here.
    if (!options.path.empty()) (void)viz::scene::poseAt(viz::scene::parseMotionPath(options.path), scene, 1, options.pathFrames);
    // Every --set names a parameter of some technique (checked when read); its values must suit the
    // technique the window opens with.
    const std::string firstId = options.technique.empty() ? viz::techniqueIds().front() : options.technique;
    if (const std::string* refused = firstRefusal(options.settingErrors, firstId)) throw viz::InputError(*refused);
    const auto given = options.settings.find(firstId);
    (void)viz::completeSettings(*viz::makeTechnique(firstId), given == options.settings.end() ? viz::Settings{} : given->second);
#ifdef NDEBUG
    constexpr bool kDebugContext = false;
#else
    constexpr bool kDebugContext = true;
#endif
    // AIRLIGHT_GL_DEBUG=1: a debug context whose messages are printed, in optimised builds too.
    const char* glDebug = std::getenv("AIRLIGHT_GL_DEBUG");
    const bool debugContext = kDebugContext || (glDebug && std::string(glDebug) == "1");
    std::unique_ptr<viz::Window> window = viz::Window::create(1280, 720, "Airlight", debugContext);
    if (debugContext) viz::gl::installDebugOutput();
    int code = 0;
    {
        GuiApp app(effective, std::move(scene), std::move(fileLighting), *window, std::move(session), std::move(notice));
        code = app.run();
    }
    return code;
}

}  // namespace airlight
