// The window: one GLFW window with a grid of views the user arranges (the final frame, L_air and any
// intermediate; split, close, swap, maximise; linked cursors; per-view display strips and difference
// views; app/view_layout.h, view_state.h) or the comparison grid, a clickable technique list, a views
// list (what the focused view shows), a status line with the stage shown, per-stage timings and the
// plan's skipped stages, the ray inspector or timing bars under the grid, the scene and parameter panel
// (immediate-mode widgets) beside them, and an orbit/fly camera. GPU techniques run on the main thread
// whenever the camera, the settings or the technique change; CPU techniques (the reference) run on a
// worker thread in progressive passes (1/4, 1/2, then full resolution) so the window never freezes.
#include "gui.h"

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "camera_controller.h"
#include "comparison_grid.h"
#include "cpu_worker.h"
#include "lesson_player.h"
#include "pane_image.h"
#include "process_stats.h"
#include "ray_inspection.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/image_io.h"
#include "gl/debug_output.h"
#include "gl/program.h"
#include "gl/readback.h"
#include "gl/stage_clock.h"
#include "gl/texture.h"
#include "gl/vertex_array.h"
#include "platform/window_glfw.h"
#include "render_job.h"
#include "run_scheduler.h"
#include "step_timeline.h"
#include "scene/orbit_target.h"
#include "scene/scene_source.h"
#include "scene/stiff_scenes.h"
#include "scene/builtin_scenes.h"
#include "session_state.h"
#include "light_gizmo.h"
#include "view_layout.h"
#include "view_state.h"
#include "view_stats.h"
#include "techniques/registry.h"
#include "plot/plot.h"
#include "report/error_metrics.h"
#include "techniques/reference/ray_probe.h"
#include "ui/font.h"
#include "ui/immediate.h"
#include "ui/text_renderer.h"

namespace airlight {

namespace {

using viz::ui::DrawList;
using viz::ui::Rect;
using Clock = std::chrono::steady_clock;

// ---- colours (display values) and sizes (logical pixels, times the content scale) ----
constexpr glm::vec4 kBackground{0.11f, 0.11f, 0.12f, 1.0f};
constexpr glm::vec4 kPanel{0.16f, 0.16f, 0.18f, 1.0f};
constexpr glm::vec4 kText{0.90f, 0.90f, 0.90f, 1.0f};
constexpr glm::vec4 kDim{0.60f, 0.62f, 0.66f, 1.0f};
constexpr glm::vec4 kAccent{0.98f, 0.78f, 0.35f, 1.0f};
constexpr glm::vec4 kHighlight{0.25f, 0.36f, 0.55f, 1.0f};
constexpr glm::vec4 kHover{0.22f, 0.22f, 0.26f, 1.0f};
constexpr glm::vec4 kError{1.0f, 0.45f, 0.40f, 1.0f};
constexpr float kFontSize = 15.0f;
constexpr float kPad = 8.0f;
constexpr double kGizmoArm = 0.25;  // the light gizmo's direction arm, in orbit distances of the scene camera
constexpr float kSidebarMin = 170.0f;
constexpr float kExposureStep = 0.5f;  // stops per +/- key press
constexpr double kOrbitRadiansPerPixel = 0.008;
constexpr double kLookRadiansPerPixel = 0.004;
constexpr double kFlySpeed = 0.6;  // target distances per second
constexpr float kStripSideBySide = 460.0f;  // a view at least this wide has its histogram beside the widgets
constexpr float kHistogramHeight = 110.0f;

// ---- settings ----

// The given settings that this technique has a parameter for, completed with its defaults. A value
// the technique rejects is reported in `error` and the defaults are used instead.
viz::Settings settingsFor(const viz::Technique& technique, const viz::Settings& given, std::string& error) {
    viz::Settings mine;
    for (const auto& [name, value] : given) {
        for (const viz::ParamInfo& p : technique.params())
            if (p.name == name) mine[name] = value;
    }
    try {
        return viz::completeSettings(technique, mine);
    } catch (const viz::InputError& e) {
        error = e.what();
        return viz::completeSettings(technique, {});
    }
}

// The stage whose sub-step parameter `name` is (StageInfo::substepParam), or -1.
int substepStageOf(const viz::Technique& technique, const std::string& name) {
    const auto& stages = technique.stages();
    for (int k = 0; k < int(stages.size()); ++k)
        if (stages[std::size_t(k)].substepParam == name) return k;
    return -1;
}

// The window steps with its cursor, never with settings: takes the sub-step parameters out of `settings`
// (back to their defaults) and returns the cursor that the first one set away from its default stands
// for (the command line's `gui --set planes_drawn=7`, a session file), if any. `onlyStage` >= 0: only
// that stage's parameter (a lesson step stopping there); the others stay as the lesson set them.
std::optional<StepCursor> takeSubsteps(const viz::Technique& technique, viz::Settings& settings, int onlyStage = -1) {
    std::optional<StepCursor> cursor;
    const viz::Settings defaults = viz::completeSettings(technique, {});
    const auto& stages = technique.stages();
    for (int k = 0; k < int(stages.size()); ++k) {
        const std::string& name = stages[std::size_t(k)].substepParam;
        if (name.empty() || !settings.count(name) || (onlyStage >= 0 && k != onlyStage)) continue;
        const viz::SubstepPosition pos = viz::substepPosition(technique, k, settings);
        settings[name] = defaults.at(name);
        if (!cursor && pos.at < pos.count) cursor = StepCursor{k, pos.at};
    }
    return cursor;
}

// ---- formatting ----

// Error messages (shader logs) can span lines; the status line shows the first.
std::string firstLine(const std::string& text) {
    const std::size_t end = text.find('\n');
    return end == std::string::npos ? text : text.substr(0, end) + "  (...)";
}

std::string format(const char* fmt, double a) {
    char buf[64];
    std::snprintf(buf, sizeof buf, fmt, a);
    return buf;
}

std::string timingLine(const viz::Timing& timing) {
    if (timing.stages.empty()) return "timings: (none yet)";
    std::string line = "timings:";
    for (const auto& st : timing.stages) line += "  " + st.stage + " " + format("%.1f ms", st.milliseconds);
    line += "  | total " + format("%.1f ms", timing.totalMilliseconds()) + "  (clock: " + timing.clock + ")";
    return line;
}

std::string skippedLine(const viz::Plan& plan) {
    std::string line;
    for (const auto& st : plan.stages) {
        if (st.runs) continue;
        line += (line.empty() ? "skipped: " : ";  ") + st.stage + (st.why.empty() ? "" : " (" + st.why + ")");
    }
    return line.empty() ? "skipped: none" : line;
}

// The orbit target's distance from the scene camera (scene/orbit_target.h).
using viz::scene::orbitDistance;

// ---- the app ----

// The keys the widgets use, from GLFW's; others stay with the window's own shortcuts.
std::optional<viz::ui::Key> uiKey(int key) {
    switch (key) {
        case GLFW_KEY_ENTER: case GLFW_KEY_KP_ENTER: return viz::ui::Key::Enter;
        case GLFW_KEY_SPACE: return viz::ui::Key::Space;
        case GLFW_KEY_LEFT: return viz::ui::Key::Left;
        case GLFW_KEY_RIGHT: return viz::ui::Key::Right;
        case GLFW_KEY_UP: return viz::ui::Key::Up;
        case GLFW_KEY_DOWN: return viz::ui::Key::Down;
        case GLFW_KEY_BACKSPACE: return viz::ui::Key::Backspace;
        case GLFW_KEY_DELETE: return viz::ui::Key::Delete;
        case GLFW_KEY_HOME: return viz::ui::Key::Home;
        case GLFW_KEY_END: return viz::ui::Key::End;
        default: return std::nullopt;
    }
}

// A light gizmo handle being dragged (GuiApp::mGizmoDrag).
struct GizmoDrag {
    int view = -1;
    bool direction = false;  // the direction handle (else the position handle)
    glm::dvec2 offset{0.0};  // from the cursor to the handle at the press, in frame uv (drags render at
                             // half size): the handle keeps it
};

// What the loader decided on its own about a scene (a default light, a medium typo, repaired normals),
// for the status line: "scene notes: A; B".
std::string sceneNotesLine(const viz::scene::Scene& scene) {
    std::string line;
    for (const std::string& n : scene.notes) line += (line.empty() ? "scene notes: " : "; ") + n;
    return line;
}

class GuiApp : public LessonHost {
public:
    GuiApp(const GuiOptions& options, viz::scene::Scene scene, viz::Window& window, SessionState session,
           std::string notice)
        : mOptions(options)
        , mSession(std::move(session))
        , mNotice(std::move(notice))
        , mScene(std::move(scene))
        , mWindow(window)
        , mController(mScene.camera, orbitDistance(mScene))
        , mGizmoArm(kGizmoArm * mController.targetDistance())
        , mIds(viz::techniqueIds()) {
        if (mNotice.empty()) mNotice = sceneNotesLine(mScene);
        float sx = 1.0f, sy = 1.0f;
        glfwGetWindowContentScale(mWindow.handle(), &sx, &sy);
        mScale = std::max(1.0f, std::max(sx, sy));
        mFont = std::make_unique<viz::ui::FontAtlas>(
            viz::ui::FontAtlas::bake(viz::ui::FontAtlas::kDefaultFontPath, kFontSize * mScale));
        mTextRenderer = std::make_unique<viz::ui::TextRenderer>(*mFont);
        mUi = std::make_unique<viz::ui::Context>(*mFont);
        mDrawList = std::make_unique<DrawList>(*mFont);
        mBackground = std::make_unique<DrawList>(*mFont);
        mImageDisplay = std::make_unique<ImageDisplay>();
        mWorker = std::make_unique<CpuWorker>(mScene);
        std::string wanted = options.technique.empty() ? mIds.front() : options.technique;
        if (!options.techniqueGiven && !mSession.technique.empty() &&
            std::find(mIds.begin(), mIds.end(), mSession.technique) != mIds.end())
            wanted = mSession.technique;
        const auto it = std::find(mIds.begin(), mIds.end(), wanted);
        mCurrent = it == mIds.end() ? 0 : int(it - mIds.begin());
        mClockName = viz::gl::StageClock::method();

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
        selectTechnique(mCurrent);
        applySessionView();
        const std::string lesson = !options.lesson.empty() ? options.lesson : mSession.lesson;
        if (options.sizeGiven) mLessonSize = {options.width, options.height};
        if (!lesson.empty()) {
            mLesson = std::make_unique<LessonPlayer>(lesson, mLessonSize);
            if (lesson == mSession.lesson) mLesson->restore(mSession.lessonStep, mSession.lessonTryIt);
        }
    }

    ~GuiApp() {
        glfwSetWindowUserPointer(mWindow.handle(), nullptr);
        glfwSetKeyCallback(mWindow.handle(), nullptr);
        glfwSetCharCallback(mWindow.handle(), nullptr);
        glfwSetMouseButtonCallback(mWindow.handle(), nullptr);
        glfwSetCursorPosCallback(mWindow.handle(), nullptr);
        glfwSetScrollCallback(mWindow.handle(), nullptr);
        glfwSetCursor(mWindow.handle(), nullptr);
        for (GLFWcursor* cursor : {mColumnCursor, mRowCursor})
            if (cursor) glfwDestroyCursor(cursor);
        // Panes may borrow the techniques' textures: drop them first.
        mViews.clear();
        mComparison.close();
        mOutput = {};
        mTechniques.clear();
        mRunners.clear();
    }

    int run() {
        auto last = Clock::now();
        while (!mWindow.shouldClose()) {
            const bool flying = mController.mode() == CameraController::Mode::Fly && anyFlyKeyDown();
            const bool busy = mWorker->progress().busy || otherPending() || mComparison.pending();
            const bool automated = !mOptions.screenshot.empty() || !mOptions.script.empty();
            if (flying || mDirty || automated || mPlaying || mGpuOthersDue || mComparison.due() ||
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
            if (mGpuOthersDue) runDueGpuOthers();  // after a frame that said "computing it..."
            if (mComparison.due()) runComparisonTechniques();
            if (mController.mode() == CameraController::Mode::Fly) fly(dt);
            // Automation advances animations by a fixed 1/30 s per frame, so runs repeat exactly.
            if (mLesson) mLesson->update(*this, automated ? 1.0 / 30.0 : dt);
            if (mPlaying) advanceAnimation(automated ? 1.0 / 30.0 : dt);
            if (mReduced && mDragButton < 0 && !mGizmoDrag && !anyFlyKeyDown()) mDirty = true;
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
            if (auto result = mWorker->take()) acceptCpuResult(std::move(*result));
            // A lesson step's pixel: inspected once its full-size result is in (the value beside the truth).
            if (mPendingInspect && mHaveOutput && mPass == mPassCount && !mWorker->progress().busy) {
                inspectPixel(mPendingInspect->x, mPendingInspect->y);
                mPendingInspect.reset();
            }
            pollOtherWorker();
            mComparison.poll();
            draw();
            ++mFramesDrawn;
            if (!mOptions.script.empty()) {
                // Each frame runs the script's next actions; the window closes when it is done.
                if (mHaveOutput && !mWorker->progress().busy && !otherPending() && !mComparison.pending() && !stepScript()) {
                    if (!mOptions.screenshot.empty()) writeScreenshot(mOptions.screenshot);
                    return 0;
                }
            } else if (automated && mFramesDrawn >= mOptions.frames && mHaveOutput && !mWorker->progress().busy &&
                       !otherPending()) {
                writeScreenshot(mOptions.screenshot);
                return 0;
            }
            mWindow.swapBuffers();
        }
        if (mOptions.screenshot.empty() && mOptions.script.empty()) saveSessionNow();
        return 0;
    }

    // ---- scripted actions (ui_script.h) ----

    // The rectangle of a widget, view or sidebar item drawn last frame.
    Rect scriptTarget(const ScriptAction& a) const {
        if (const auto it = mUi->widgetRects().find(a.target); it != mUi->widgetRects().end()) return it->second;
        for (const auto& v : mViewRects)
            if (v.name == a.target) return v.rect;
        if (const auto it = mNamedRects.find(a.target); it != mNamedRects.end()) return it->second;
        std::string known;
        for (const auto& [name, r] : mNamedRects) known += (known.empty() ? "" : ", ") + name;
        for (const auto& v : mViewRects) known += ", " + v.name;
        for (const auto& [name, r] : mUi->widgetRects()) known += ", " + name;
        throw viz::InputError(mOptions.scriptPath + ":" + std::to_string(a.line) + ": nothing named '" + a.target +
                              "' is on screen (on screen: " + known + ")");
    }

    // Runs actions until one needs frames to pass; false when the script is done.
    // A widget named by a script action is scrolled into view first, as a user would: the request is
    // served on the next frame and the new rectangle known the frame after. Returns true while waiting.
    bool revealScriptTarget(const ScriptAction& a) {
        if (mScriptRevealFrames > 0) return --mScriptRevealFrames > 0;  // 0: revealed, go on
        if (!mUi->widgetRects().count(a.target)) return false;
        mUi->reveal(a.target);
        mScriptRevealFrames = 2;
        return true;
    }

    bool stepScript() {
        while (mScriptIndex < mOptions.script.size()) {
            const ScriptAction& a = mOptions.script[mScriptIndex];
            switch (a.kind) {
                case ScriptAction::Kind::Frames:
                    if (mScriptWait == 0) mScriptWait = a.frames;
                    if (--mScriptWait > 0) return true;
                    ++mScriptIndex;
                    return true;
                case ScriptAction::Kind::Key:
                    onKey(scriptKeyCode(a.target), GLFW_PRESS, a.modifiers);
                    ++mScriptIndex;
                    return true;
                case ScriptAction::Kind::Hover: {
                    if (revealScriptTarget(a)) return true;
                    const Rect r = scriptTarget(a);
                    mHover = r.min + a.fraction * r.size();
                    ++mScriptIndex;
                    return true;
                }
                case ScriptAction::Kind::Wheel: {
                    if (revealScriptTarget(a)) return true;
                    const Rect r = scriptTarget(a);
                    mHover = r.min + 0.5f * r.size();
                    onScroll(double(a.notches));
                    ++mScriptIndex;
                    return true;
                }
                case ScriptAction::Kind::Screenshot:
                    writeScreenshot(a.target);
                    ++mScriptIndex;
                    break;
                case ScriptAction::Kind::Stats: {
                    while (glGetError() != GL_NO_ERROR) ++mGlErrors;
                    std::ofstream out(a.target, std::ios::app);
                    out << statsJsonLine(currentProcessStats(), long(mFramesDrawn), mGlErrors) << "\n";
                    if (!out) throw viz::InputError(mOptions.scriptPath + ":" + std::to_string(a.line) + ": cannot append to '" + a.target + "'");
                    ++mScriptIndex;
                    break;
                }
                case ScriptAction::Kind::Drag: {
                    // Frame 1: press at the start; frames 2-5: move a quarter of the way each; then release.
                    // Both ends are fixed at the press: what is dragged (a divider, a handle) moves.
                    if (mScriptDragStep == 0) {
                        const Rect r = scriptTarget(a);
                        Rect onto = r;
                        if (!a.onto.empty()) {
                            ScriptAction other = a;
                            other.target = a.onto;
                            onto = scriptTarget(other);
                        }
                        mScriptDragFrom = r.min + a.fraction * r.size();
                        mScriptDragTo = onto.min + a.to * onto.size();
                        mHover = mScriptDragFrom;
                        mSyntheticDown = true;  // widgets (a splitter, a slider) see the button held
                        onMouseButtonAt(GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, mScriptDragFrom);
                        mScriptDragStep = 1;
                    } else if (mScriptDragStep <= 4) {
                        const glm::vec2 p = mScriptDragFrom + (mScriptDragTo - mScriptDragFrom) * (float(mScriptDragStep) / 4.0f);
                        onCursorPixels(p);
                        ++mScriptDragStep;
                    } else {
                        mSyntheticDown.reset();
                        onMouseButtonAt(GLFW_MOUSE_BUTTON_LEFT, GLFW_RELEASE, mScriptDragTo);
                        mScriptDragStep = 0;
                        ++mScriptIndex;
                    }
                    return true;
                }
                case ScriptAction::Kind::Click: {
                    // Frame 1: move there and press; frame 2: release (widgets click on release).
                    if (!mSyntheticDown) {
                        if (revealScriptTarget(a)) return true;
                        const Rect r = scriptTarget(a);
                        mScriptPoint = r.min + a.fraction * r.size();
                        mHover = mScriptPoint;
                        mSyntheticDown = true;
                        onMouseButtonAt(GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, mScriptPoint);
                    } else {
                        mHover = mScriptPoint;
                        mSyntheticDown = false;
                        onMouseButtonAt(GLFW_MOUSE_BUTTON_LEFT, GLFW_RELEASE, mScriptPoint);
                        mSyntheticDown.reset();
                        ++mScriptIndex;
                    }
                    return true;
                }
            }
        }
        return false;
    }

    // The back buffer as drawn (before the swap) to the PNG, and the views' rectangles beside it.
    void writeScreenshot(const std::string& path) {
        const glm::ivec2 fb = mWindow.framebufferSize();
        std::vector<std::uint8_t> bytes(std::size_t(fb.x) * std::size_t(fb.y) * 4);
        glReadBuffer(GL_BACK);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, fb.x, fb.y, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
        // Display bytes, GL row 0 at the bottom -> linear floats, row 0 at the top (writeImage encodes).
        viz::Image image(fb.x, fb.y, 3);
        for (int y = 0; y < fb.y; ++y)
            for (int x = 0; x < fb.x; ++x)
                for (int c = 0; c < 3; ++c) {
                    const float v = float(bytes[(std::size_t(fb.y - 1 - y) * std::size_t(fb.x) + std::size_t(x)) * 4 +
                                                std::size_t(c)]) / 255.0f;
                    image.at(x, y, c) = v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
                }
        viz::writeImage(image, path);
        nlohmann::json views = nlohmann::json::array();
        for (const auto& v : mViewRects) {
            nlohmann::json entry = {{"name", v.name}, {"title", v.title},
                                    {"rect", {v.rect.min.x, v.rect.min.y, v.rect.max.x, v.rect.max.y}}};
            if (v.cell >= 0 && mViews.count(v.cell)) entry.update(viewSidecar(v.cell, mViews.at(v.cell)));
            views.push_back(entry);
        }
        nlohmann::json sidecar = {{"window", {fb.x, fb.y}},
                                        {"scale", mScale},
                                        {"scene", mScene.name},
                                        {"technique", technique().id()},
                                        {"frames", mFramesDrawn},
                                        {"medium", {{"sigma_s", mScene.medium.sigma_s}, {"sigma_a", mScene.medium.sigma_a},
                                                    {"g", mScene.medium.g}}},
                                        {"settings", mSettings},
                                        {"stage", technique().stages()[std::size_t(stageShown())].id},
                                        {"last_stage_run", mHaveOutput ? mOutput.lastStageRun : -1},
                                        {"first_stage_run", mHaveOutput ? mOutput.firstStageRun : -1},
                                        {"substep", substepState().first},
                                        {"substep_count", substepState().second},
                                        {"stopped_early", stoppedEarly()},
                                        {"notice", mNotice},
                                        {"views", views}};
        {
            nlohmann::json lights = nlohmann::json::array();
            for (const auto& l : mScene.lights)
                lights.push_back({{"name", l.name},
                                  {"position", {l.position.x, l.position.y, l.position.z}},
                                  {"direction", {l.direction.x, l.direction.y, l.direction.z}},
                                  {"intensity", l.intensity}});
            sidecar["lights"] = lights;
        }
        // The light gizmo in the first view that shows it: its handles in that view's frame pixels.
        sidecar["gizmo"] = nullptr;
        for (const ViewCellRect& c : mCells) {
            const auto gizmo = gizmoFor(mViews.at(c.view));
            if (!gizmo) continue;
            const GizmoHandles h = gizmo->handles(mScene.lights[0]);
            const auto point = [](const std::optional<glm::dvec2>& p) {
                return p ? nlohmann::json::array({p->x, p->y}) : nlohmann::json(nullptr);
            };
            // Where each handle is grabbed in the window (off the view: at its edge).
            const auto grab = [&](const std::optional<glm::dvec2>& p) {
                bool inside = true;
                if (!p) return nlohmann::json(nullptr);
                const glm::vec2 w = handlePoint(mViews.at(c.view), *p, inside);
                return nlohmann::json::array({w.x, w.y});
            };
            sidecar["gizmo"] = {{"cell", c.view},           {"position", point(h.position)}, {"tip", point(h.tip)},
                                {"root", point(h.root)},    {"arm", mGizmoArm},
                                {"position_grab", grab(h.position)}, {"tip_grab", grab(h.tip)}};
            break;
        }
        sidecar["animation"] = {{"playing", mPlaying}, {"seconds", mPlayClock}, {"light_turn", mPlayTurn}};
        sidecar["view_grid"] = {{"layout", mLayout.toText()}, {"focused", mFocused},
                                {"maximised", mLayout.maximised()},
                                {"cpu_ms_last_frame", mGridMilliseconds},
                                {"ui_cpu_ms_last_frame", mUiMilliseconds},
                                {"linked_pixel", mLinkedPixel ? nlohmann::json::array({mLinkedPixel->x, mLinkedPixel->y})
                                                              : nlohmann::json(nullptr)}};
        if (mComparison.isOpen()) sidecar["comparison"] = mComparison.toJson();
        if (mProbe) {
            const auto rgb = [](glm::dvec3 v) { return nlohmann::json::array({v.x, v.y, v.z}); };
            nlohmann::json lights = nlohmann::json::array();
            for (const auto& l : mProbe->lights) {
                nlohmann::json spans = nlohmann::json::array();
                for (const auto& iv : l.lit) spans.push_back({iv.a, iv.b});
                lights.push_back({{"name", l.name}, {"lit", spans}, {"airlight", rgb(l.airlight)}});
            }
            sidecar["inspector"] = {{"pixel", {mProbe->x, mProbe->y}},
                                    {"d", mProbe->d},
                                    {"reference", rgb(mProbe->airlight)},
                                    {"technique", mProbeTechnique},
                                    {"technique_value", mProbeHasValue ? rgb(mProbeValue) : nlohmann::json(nullptr)},
                                    {"lights", lights}};
            if (mHaveOutput && mProbeTechnique == technique().id()) {
                nlohmann::json readings = nlohmann::json::object();
                for (const PixelReading& r : probeInspection().readings) {
                    std::vector<double> values;
                    for (int c = 0; c < r.channels; ++c) values.push_back(r.value[c]);
                    readings[r.id] = values;
                }
                sidecar["inspector"]["readings"] = readings;
                sidecar["inspector"]["ray_views"] = probeInspection().rayViews;
                nlohmann::json series = nlohmann::json::object();
                for (const viz::plot::Series& s : probeInspection().series) {
                    nlohmann::json points = nlohmann::json::array();
                    for (const glm::dvec2& q : s.points) points.push_back({q.x, q.y});
                    series[s.name] = points;
                }
                sidecar["inspector"]["ray_series"] = series;
            }
        }
        if (mLesson) sidecar["lesson"] = mLesson->sidecar(*this);
        std::filesystem::path json(path);
        json.replace_extension(".json");
        const std::string error = viz::writeFileAtomically(json, sidecar.dump(2) + "\n");
        if (!error.empty()) throw viz::InputError("cannot write '" + json.string() + "': " + error);
    }

private:
    // ---- the session file ----

    SessionState currentSession() const {
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

    void saveSessionNow() {
        try {
            saveSession(mOptions.statePath, currentSession());
            mNotice = "session saved to " + mOptions.statePath;
        } catch (const viz::InputError& e) {
            mNotice = e.what();
            std::fprintf(stderr, "airlight: %s\n", e.what());
        }
    }

    void loadSessionNow() {
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

    // The session's medium, technique (with its settings), camera, view and exposure over the scene.
    void restoreSessionOverStep() override {
        const bool lights = applyLightPlacements(mSession.lights, mScene);
        if (mSession.medium) mScene.medium = *mSession.medium;
        if (mSession.medium || lights) mWorker->setScene(mScene);  // the CPU worker keeps its own copy of the scene
        const auto it = std::find(mIds.begin(), mIds.end(), mSession.technique);
        selectTechnique(it == mIds.end() ? mCurrent : int(it - mIds.begin()));
        applySessionView();
    }

    // ---- the lesson player's hooks (lesson_player.h): the window's own state changes ----

    void loadLessonScene(const std::string& name) override {
        viz::scene::Scene scene = viz::scene::loadScene(name, mOptions.load);  // InputError: the window keeps its scene
        mScene = std::move(scene);
        mOptions.scene = name;
        mController = CameraController(mScene.camera, orbitDistance(mScene));
        mGizmoArm = kGizmoArm * mController.targetDistance();
        mWorker->setScene(mScene);
        mLightIntensityOff = 0.0;
        mNotice = sceneNotesLine(mScene);
        mComparison.close();
        mProbe.reset();
        mDirty = true;
    }

    LessonWindowState lessonWindowState() const override {
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

    void applyLessonWindowState(const LessonWindowState& s) override {
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

    void showLessonView(const std::string& id) override { showInFocusedView(id); }

    // A lesson's view goes to the focused view of the grid (the right-hand one by default).
    void showInFocusedView(const std::string& id) {
        ViewState& v = focusedView();
        v.content = id;
        v.layer = 0;
        v.transform.fit();
        refreshView(v);
    }

    void setLessonSetting(const std::string& name, double value) override {
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

    // ---- animation (P): the first light circles its aim point, and a technique with a `time`
    // parameter (slices' scrolling noise) follows the clock. GPU techniques run every frame while it plays;
    // the reference (seconds per frame on its worker) keeps the light where it is. Pausing keeps the
    // state where it is; playing again continues from there.
    static constexpr double kLightTurnSeconds = 8.0;

    void togglePlaying() {
        mPlaying = !mPlaying;
        if (!mPlaying) return;
        mPlayLight.reset();
        if (!mScene.lights.empty() && mScene.lights[0].type != viz::scene::LightType::Area) {
            mPlayLight = mScene.lights[0];
            mPlayCentre = mController.target();
            mPlayTurn = 0.0;
        }
    }

    void advanceAnimation(double dt) {
        mPlayClock += dt;
        if (mSettings.count("time")) {
            mSettings["time"] = mPlayClock;
            mDirty = true;
        }
        if (mPlayLight && technique().needsGl() && !mScene.lights.empty()) {
            mPlayTurn = std::fmod(mPlayTurn + dt / kLightTurnSeconds, 1.0);
            mScene.lights[0] = orbitLight(*mPlayLight, mPlayCentre, mPlayTurn);
            mDirty = true;
        }
    }

    void setLessonLight(const viz::scene::Light& light) override {
        // GPU techniques read the scene at every run; the reference (its worker holds a copy of the scene,
        // seconds per frame) keeps the light where it is.
        if (mScene.lights.empty() || !technique().needsGl()) return;
        mScene.lights[0] = light;
        mDirty = true;
    }

    // Camera, view and exposure of the session (the scene, medium and technique are applied before).
    void applySessionView() {
        if (mSession.camera) mController.place(*mSession.camera, mSession.orbitTarget);
        applySessionGrid();
        mExposure = mSession.exposure;
        mExposureSet = mSession.exposureSet;
        mDirty = true;
    }

    // ---- comparison grid ----

    // G: the comparison grid (comparison_grid.h) for the current view; G again closes it.
    void toggleComparison() {
        if (mComparison.isOpen()) {
            mComparison.close();
            return;
        }
        viz::scene::Scene scene = mScene;
        scene.camera = mController.camera();
        try {
            mComparison.open(scene, {mOptions.width, mOptions.height}, mIds);
        } catch (const std::exception& e) {
            mError = std::string("comparison: ") + e.what();
            mComparison.close();
        }
    }

    // The grid's techniques with the window's instances and settings (this thread holds the GL context).
    void runComparisonTechniques() {
        mComparison.runTechniques([this](const std::string& id, const viz::scene::Scene& scene, glm::ivec2 size) {
            if (!mTechniques.count(id)) mTechniques[id] = viz::makeTechnique(id);
            viz::Technique& t = *mTechniques.at(id);
            viz::Settings given = mSession.settings.count(id) ? mSession.settings.at(id) : viz::Settings{};
            for (const auto& [name, value] : mOptions.settings) given[name] = value;
            std::string ignored;
            viz::FrameOutput out = t.run({&scene, size.x, size.y, settingsFor(t, given, ignored), -1});
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            return out;
        });
    }

    void drawComparison(DrawList& dl, const Rect& area) {
        const float line = mFont->lineHeight(), pad = 4.0f * mScale;
        const int n = int(mComparison.tiles().size());
        // One more cell for the plot of error against time.
        const int cells = n + 1;
        const int cols = int(std::ceil(std::sqrt(double(cells)))), rows = (cells + cols - 1) / cols;
        const glm::vec2 cell{area.size().x / float(cols), area.size().y / float(rows)};
        dl.textClipped({area.min.x, area.min.y - line}, "comparison (G): L_air at the reference's exposure, time of a "
                       "warm run and relative L2 against the reference", kAccent, area.max.x);
        {
            // The plot takes the rest of the last row.
            const glm::vec2 at = area.min + glm::vec2(float(n % cols), float(n / cols)) * cell;
            const Rect box{at + pad, at + glm::vec2(float(cols - n % cols), 1.0f) * cell - pad};
            viz::plot::drawPlot(dl, box, mComparison.errorAgainstTime());
            mViewRects.push_back({"comparison.error_vs_time", "relative L2 against time", box, -1});
        }
        for (int i = 0; i < n; ++i) {
            ComparisonTile& tile = mComparison.tiles()[std::size_t(i)];
            const glm::vec2 at = area.min + glm::vec2(float(i % cols), float(i / cols)) * cell;
            const Rect box{at + pad, at + cell - glm::vec2(pad, pad + 2.0f * line)};
            const Rect image = fitImage(box, tile.pane.size);
            if (tile.pane.texture != 0) {
                DisplayMapping shared;
                shared.exposure = mComparison.exposure();
                mPaneDraws.push_back({image, &tile.pane, nullptr, shared});
            } else if (tile.failure.empty()) {
                dl.textClipped({box.min.x + 4.0f * mScale, box.min.y + 4.0f * mScale}, mComparison.waitingText(), kDim,
                               box.max.x);
            }
            std::string caption = tile.technique;
            std::string figures = tile.failure.empty()
                ? (tile.pane.texture == 0 ? std::string("")
                   : tile.technique == "reference" ? std::string("ground truth")
                                                 : format("%.1f ms", tile.milliseconds) + "   error " +
                                                       format("%.3g", tile.error.relativeL2))
                : "failed: " + firstLine(tile.failure);
            if (tile.error.nanPixels + tile.error.infPixels > 0)
                figures += "   " + std::to_string(tile.error.nanPixels + tile.error.infPixels) + " NaN/Inf px";
            dl.textClipped({box.min.x, box.max.y + 2.0f}, caption, kText, at.x + cell.x - pad);
            dl.textClipped({box.min.x, box.max.y + 2.0f + line}, figures, kDim, at.x + cell.x - pad);
        }
    }

    // ---- export ----

    // Files go to --export-dir (default airlight-exports/ in the working folder), named after the scene,
    // technique and view, so that successive exports of different views do not overwrite each other.
    std::string exportStem(const std::string& what) {
        std::string name = mScene.name + "-" + technique().id() + "-" + what;
        for (char& c : name)
            if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
        std::error_code ec;
        std::filesystem::create_directories(mOptions.exportDir, ec);
        return (std::filesystem::path(mOptions.exportDir) / name).string();
    }

    // E: the intermediate view as EXR (its float values) and PNG (as shown: exposure or range mapping).
    void exportView() {
        const PaneImage& pane = focusedView().pane;
        if (!mHaveOutput || pane.texture == 0) {
            mNotice = "nothing to export: the view holds no image";
            return;
        }
        viz::Image values = viz::gl::readTexture(pane.texture);  // rows flipped: GL row 0 is the bottom
        if (!pane.flipY) {
            // Uploaded CPU images keep row 0 at the top in GL too: undo readTexture's flip.
            viz::Image flipped = values;
            for (int y = 0; y < values.height; ++y)
                for (int x = 0; x < values.width; ++x)
                    for (int c = 0; c < values.channels; ++c) flipped.at(x, y, c) = values.at(x, values.height - 1 - y, c);
            values = std::move(flipped);
        }
        const std::string stem = exportStem(pane.id.empty() ? "view" : pane.id);
        try {
            viz::writeImage(values, stem + ".exr");
            const DisplayMapping m = resolveMapping(pane, focusedView().display, mExposure, focusedView().measured);
            const bool colour = m.mode == DisplayMode::HdrColor || m.mode == DisplayMode::RangeColor;
            if (colour) viz::writeImage(values, stem + ".png", std::exp2(m.exposure));
            else viz::writeImage(viz::toDisplay(values, m.lo, m.hi), stem + ".png");
            mNotice = "exported " + stem + ".exr and .png";
        } catch (const viz::InputError& e) {
            mNotice = e.what();
        }
    }

    // F12: the whole window as PNG (with its sidecar JSON of view rectangles).
    void exportWindow() {
        const std::string path = exportStem("window") + ".png";
        try {
            writeScreenshot(path);
            mNotice = "wrote " + path;
        } catch (const viz::InputError& e) {
            mNotice = e.what();
        }
    }

    // ---- stepping ----

    // The stage the cursor stands in (the last one for the complete frame).
    int stageShown() const {
        const int n = int(technique().stages().size());
        return mCursor.stage < 0 || mCursor.stage >= n ? n - 1 : mCursor.stage;
    }

    // The cursor's sub-step position: {at, count} (1-based; {count, count} when the stage runs whole,
    // {0, 0} for a stage without sub-steps).
    std::pair<int, int> substepState() const {
        const int count = int(technique().substepValues(stageShown(), mSettings).size());
        if (count == 0) return {0, 0};
        return {mCursor.substep <= 0 ? count : std::min(mCursor.substep, count), count};
    }

    // Whether the frame is the complete algorithm: the last stage, whole, and no sub-step parameter a
    // lesson (or --set) left cutting an earlier stage short.
    std::string stoppedEarly() const {
        const auto& stages = technique().stages();
        const int shown = stageShown();
        const auto [at, count] = substepState();
        std::string why;
        if (shown < int(stages.size()) - 1)
            why = "stopped after stage " + std::to_string(shown + 1) + "/" + std::to_string(stages.size()) + " " +
                  stages[std::size_t(shown)].id;
        if (count > 0 && at < count)
            why += (why.empty() ? "stopped in " + stages[std::size_t(shown)].id : std::string()) + " at sub-step " +
                   std::to_string(at) + "/" + std::to_string(count);
        const viz::Settings defaults = viz::completeSettings(technique(), {});
        for (const viz::StageInfo& st : stages)
            if (!st.substepParam.empty() && mSettings.count(st.substepParam) &&
                mSettings.at(st.substepParam) != defaults.at(st.substepParam))
                why += (why.empty() ? "" : "; ") + st.substepParam + "=" + format("%g", mSettings.at(st.substepParam)) +
                       " cuts " + st.id + " short";
        return why;
    }

    void moveCursor(StepCursor c) {
        const int n = int(technique().stages().size());
        if ((c.stage < 0 || c.stage >= n - 1) && c.substep <= 0) c = {};  // the complete frame
        if (c.stage < 0 && c.substep > 0) c.stage = n - 1;
        if (c == mCursor) return;
        mCursor = c;
        mDirty = true;
    }

    // S / Shift+S: the next / previous stage, wrapping (the last stage is the complete frame). A stage
    // with sub-steps is entered at its first.
    void stepStage(int delta) {
        const int n = int(technique().stages().size());
        const int stage = ((stageShown() + delta) % n + n) % n;
        const bool substeps = !technique().substepValues(stage, mSettings).empty();
        moveCursor({stage == n - 1 ? -1 : stage, substeps && stage < n - 1 ? 1 : 0});
        mNotice.clear();
    }

    // D / Shift+D: one sub-step more / fewer inside the current stage; Home / End: the first / last.
    void stepSubstep(int delta) { setSubstepAt(substepState().first + delta); }
    void setSubstepAt(int k) {
        const auto [at, count] = substepState();
        const std::string& id = technique().stages()[std::size_t(stageShown())].id;
        if (count <= 0) {
            mNotice = id + " has no sub-steps (S steps the stages)";
            return;
        }
        if (k < 1 || k > count) {
            mNotice = (k < 1 ? "already at the first sub-step of " : "already at the last sub-step of ") + id + " (" +
                      std::to_string(at) + "/" + std::to_string(count) + ")";
            return;
        }
        mNotice.clear();
        moveCursor({stageShown(), k == count ? 0 : k});
    }

    // The timeline under the views: a click or a drag puts the cursor there (step_timeline.h).
    void drawStepTimeline() {
        mTimeline = timelineSegments(technique(), mSettings, mTimelineRect.min.x, mTimelineRect.max.x);
        drawTimeline(*mBackground, *mDrawList, mTimelineRect, mTimeline, mCursor, mScale);
        mNamedRects["timeline"] = mTimelineRect;
        mHits.push_back({mTimelineRect, [this] {
                             mDragTimeline = true;
                             mNotice.clear();
                             moveCursor(timelineCursorAt(mTimeline, mHover.x));
                         }});
    }

    // ---- ray inspector ----

    // The exact ground truth along the ray of the final image's pixel under the cursor, beside the current
    // technique's value for that pixel. The cursor elsewhere clears it.
    void inspectPixelUnderCursor() {
        mProbe.reset();
        mPendingInspect.reset();
        // The cursor over any screen-space view (final, L_air, a frame-sized intermediate) picks the pixel.
        if (mHoveredView < 0 || !mViews.count(mHoveredView) || mOptions.width < 1) return;
        const ViewState& hovered = mViews.at(mHoveredView);
        if (!isScreenSpace(hovered) || !hovered.image.contains(mHover)) return;
        const glm::dvec2 uv = hovered.transform.paneToUv(glm::dvec2((mHover - hovered.image.min) / hovered.image.size()));
        const int x = std::clamp(int(uv.x * double(mOptions.width)), 0, mOptions.width - 1);
        const int y = std::clamp(int(uv.y * double(mOptions.height)), 0, mOptions.height - 1);
        inspectPixel(x, y);
    }

    void inspectPixel(int x, int y) {
        mProbe.reset();
        mProbeInspection.reset();
        mScene.camera = mController.camera();
        try {
            mProbe = viz::reference::probePixel(mScene, mOptions.width, mOptions.height, x, y);
        } catch (const std::exception& e) {
            mError = e.what();
            return;
        }
        mProbeTechnique = technique().id();
        // The technique's per-ray intermediates (a walk, a voxel column, per-VPL terms) follow the pixel.
        if (pickPixel(technique(), mSettings, {x, y})) mDirty = true;
        const viz::Image& a = mOutput.airlight;
        mProbeHasValue = mHaveOutput && a.width == mOptions.width && a.height == mOptions.height;
        if (mProbeHasValue) mProbeValue = {a.at(x, y, 0), a.at(x, y, 1), a.at(x, y, 2)};
    }

    void drawInspector(DrawList& dl, const Rect& area) {
        const float line = mFont->lineHeight();
        const auto& p = *mProbe;
        const double ref = p.airlight.x + p.airlight.y + p.airlight.z;
        std::string head = "ray inspector (I): pixel (" + std::to_string(p.x) + ", " + std::to_string(p.y) +
                           ")  d = " + format("%.3g", p.d) + "  reference L_air = " + format("%.4g", p.airlight.x) +
                           format(" %.4g", p.airlight.y) + format(" %.4g", p.airlight.z);
        std::string second = mProbeTechnique + ": ";
        if (mProbeHasValue) {
            const double v = mProbeValue.x + mProbeValue.y + mProbeValue.z;
            second += format("%.4g", mProbeValue.x) + format(" %.4g", mProbeValue.y) + format(" %.4g", mProbeValue.z) +
                      (ref > 0.0 ? "   relative error " + format("%+.2f%%", 100.0 * (v - ref) / ref) : "");
        } else {
            second += "(no value at this resolution yet)";
        }
        dl.textClipped(area.min, head, kText, area.max.x);
        dl.textClipped({area.min.x, area.min.y + line}, second, kDim, area.max.x);
        viz::plot::PlotSpec spec;
        spec.xLabel = "t along the ray";
        spec.yLabel = "integrand (sum of RGB), V included";
        viz::plot::Series curve{"integrand", viz::plot::categoricalColor(0), {}, true, false};
        for (std::size_t i = 0; i < p.t.size(); ++i) {
            const glm::dvec3& v = p.integrand[i];
            curve.points.push_back({p.t[i], v.x + v.y + v.z});
        }
        spec.series.push_back(std::move(curve));
        // The technique's own samples along the ray (slices: one point per plane), on the same axes.
        if (mHaveOutput && technique().id() == mProbeTechnique)
            for (const viz::plot::Series& s : probeInspection().series) spec.series.push_back(s);
        for (std::size_t k = 0; k < p.lights.size(); ++k) {
            viz::plot::Band band{"lit: " + p.lights[k].name, viz::plot::categoricalColor(int(k) + 1), {}};
            for (const auto& iv : p.lights[k].lit) band.spans.push_back({iv.a, iv.b});
            spec.bands.push_back(std::move(band));
        }
        Rect plotArea{{area.min.x, area.min.y + 2.0f * line + 4.0f * mScale}, area.max};
        // The technique's own view of the ray beside the plot: its per-pixel intermediates at this pixel
        // and the per-ray views that follow the picked pixel.
        if (mHaveOutput && technique().id() == mProbeTechnique && plotArea.size().x > 500.0f * mScale) {
            const Rect side{{plotArea.max.x - 0.42f * plotArea.size().x, plotArea.min.y}, plotArea.max};
            plotArea.max.x = side.min.x - kPad * mScale;
            float y = side.min.y;
            const PixelInspection& seen = probeInspection();
            const std::vector<std::string>& perRay = seen.rayViews;
            std::string title = mProbeTechnique + " at this pixel";
            if (!perRay.empty()) {
                title += " (its ray in views:";
                for (const std::string& id : perRay) title += " " + id;
                title += ")";
            }
            dl.textClipped({side.min.x, y}, title + ":", kAccent, side.max.x);
            y += line;
            for (const PixelReading& r : seen.readings) {
                if (y + line > side.max.y) break;
                std::string text = r.label + ":";
                for (int c = 0; c < std::min(r.channels, 4); ++c) text += format(" %.4g", r.value[c]);
                if (!r.units.empty()) text += " " + r.units;
                dl.textClipped({side.min.x, y}, text, kText, side.max.x);
                y += line;
            }
        }
        if (plotArea.size().y > 4.0f * line) viz::plot::drawPlot(dl, plotArea, spec);
    }

    // A cross on the inspected pixel in a screen-space view.
    void markProbe(DrawList& dl, const ViewState& v) {
        if (!mProbe || mOptions.width < 1 || !isScreenSpace(v)) return;
        const glm::dvec2 uv = (glm::dvec2(mProbe->x, mProbe->y) + 0.5) / glm::dvec2(mOptions.width, mOptions.height);
        const glm::vec2 c = v.image.min + glm::vec2(v.transform.uvToPane(uv)) * v.image.size();
        if (!v.image.contains(c)) return;
        const float r = 6.0f * mScale;
        dl.line({c.x - r, c.y}, {c.x + r, c.y}, 2.0f * mScale, {1.0f, 0.2f, 0.8f, 1.0f});
        dl.line({c.x, c.y - r}, {c.x, c.y + r}, 2.0f * mScale, {1.0f, 0.2f, 0.8f, 1.0f});
    }

    // ---- techniques and rendering ----

    // The main views' instance of the current technique (its own: no other consumer runs it).
    viz::Technique& technique() { return mRunners.at(mIds[std::size_t(mCurrent)])->technique(); }
    const viz::Technique& technique() const { return mRunners.at(mIds[std::size_t(mCurrent)])->technique(); }

    void selectTechnique(int index) {
        const int n = int(mIds.size());
        index = ((index % n) + n) % n;
        const std::string& id = mIds[std::size_t(index)];
        try {
            if (!mRunners.count(id)) mRunners[id] = std::make_unique<StageRunner>(viz::makeTechnique(id));
        } catch (const std::exception& e) {
            mError = e.what();
            return;
        }
        mCurrent = index;
        mCursor = {};  // a new technique starts on its complete frame
        mError.clear();
        mSettingsError.clear();
        // The session's values for this technique, then the command line's on top.
        viz::Settings given = mSession.settings.count(id) ? mSession.settings.at(id) : viz::Settings{};
        for (const auto& [name, value] : mOptions.settings) given[name] = value;
        mSettings = settingsFor(technique(), given, mSettingsError);
        if (auto c = takeSubsteps(technique(), mSettings)) mCursor = *c;
        try {
            mPlan = technique().plan(mScene, mSettings);
        } catch (const std::exception& e) {
            mPlan = {};
            mError = e.what();
        }
        // The previous technique's frame does not belong to this one.
        clearPanes();
        mOutput = {};
        mHaveOutput = false;
        mPass = 0;
        mWindow.setTitle("Airlight - " + mScene.name + " - " + id);
        mDirty = true;
    }

    void render() {
        mDirty = false;
        mScene.camera = mController.camera();
        viz::Technique& t = technique();
        if (!t.needsGl()) {
            mReduced = false;  // the worker's progressive passes play that role
            mWorker->submit({t.id(), mScene.camera, mSettings, mOptions.width, mOptions.height});
            return;
        }
        glm::ivec2 size{mOptions.width, mOptions.height};
        // While the camera is being dragged or flown, render at half size to keep up; the full size
        // follows when the interaction stops.
        mReduced = (mDragButton >= 0 || mGizmoDrag || anyFlyKeyDown()) && size.x >= 64 && size.y >= 48;
        if (mReduced) size /= 2;
        // Panes borrow textures the run is about to replace.
        clearPanes();
        const auto start = Clock::now();
        try {
            // The scheduler re-runs only the stages whose inputs changed (a sub-step: its stage alone).
            mOutput = mRunners.at(t.id())->run(mScene, size.x, size.y, mSettings, mCursor);
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
    }

    void acceptCpuResult(CpuResult result) {
        if (result.technique != mIds[std::size_t(mCurrent)]) return;  // from a technique no longer shown
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

    // ---- the view grid: what each view shows ----

    // The other side of a difference view: one technique's images for one scene, camera and size.
    struct OtherRun {
        std::string key;  // scene, camera, size and settings it was run for
        viz::Image airlight, final;
        std::string failure;
        std::string pending;  // a CPU technique: the key of the run the worker computes
    };

    // Contents in the views list: the final frame, L_air, then every intermediate of the run.
    int contentCount() const { return 2 + int(mOutput.intermediates.size()); }
    std::string contentId(int index) const {
        return index == 0 ? "final" : index == 1 ? "airlight" : mOutput.intermediates[std::size_t(index - 2)].id;
    }
    std::string contentLabel(int index) const {
        return index == 0 ? "Final image" : index == 1 ? "Airlight L_air" : mOutput.intermediates[std::size_t(index - 2)].label;
    }

    ViewState& focusedView() {
        if (!mViews.count(mFocused)) mFocused = mLayout.views().front();
        return mViews[mFocused];
    }

    void clearPanes() {
        mMarkerCache.clear();
        for (auto& [id, v] : mViews) {
            v.pane = {};
            v.values = {};
            updateStatistics(v);
        }
    }

    // The default grid: the final frame on the left, `content` on the right (focused).
    void resetLayout(const std::string& content) {
        mLayout = ViewLayout(0);
        mLayout.split(0, SplitAxis::X, 1);
        mViews.clear();
        mViews[0].content = "final";
        mViews[1].content = content.empty() ? "airlight" : content;
        mFocused = 1;
        mNextView = 2;
    }

    // The session's grid, or the default one around its `view`.
    void applySessionGrid() {
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

    // A view of the final frame, L_air or an intermediate the size of the frame: its texels are the
    // frame's pixels, so cursors link across such views.
    // A view with one texel per frame pixel (an orbit view is frame-sized but seen from elsewhere).
    bool isScreenSpace(const ViewState& v) const {
        return v.pane.texture != 0 && mOutputSize.x > 0 && v.pane.size == mOutputSize && !isOrbitView(v);
    }

    // Builds the view's pane from the last run (and its difference image in difference mode).
    void buildPane(ViewState& v) {
        v.pane = {};
        v.error.reset();
        v.differenceNote.clear();
        v.shown = -1;
        if (!mHaveOutput) return;
        const auto& all = mOutput.intermediates;
        std::string content = v.content;
        int index = -1;
        if (content != "final" && content != "airlight") {
            // Ids may repeat (one shadow map per light): prefer the same position, then the first match.
            if (v.index >= 0 && v.index < int(all.size()) && all[std::size_t(v.index)].id == content) {
                index = v.index;
            } else {
                for (int i = int(all.size()) - 1; i >= 0; --i)
                    if (all[std::size_t(i)].id == content) index = i;
            }
            if (index < 0) content = "airlight";  // not in this run: L_air (the choice is kept for later runs)
        }
        // Stepped to a stage before L_air exists: show what that stage published instead.
        if (content == "airlight" && mOutput.airlight.empty() && mOutput.lastStageRun >= 0) {
            const auto& declared = technique().stages()[std::size_t(mOutput.lastStageRun)].intermediates;
            for (int i = int(all.size()) - 1; i >= 0; --i)
                if (std::find(declared.begin(), declared.end(), all[std::size_t(i)].id) != declared.end()) index = i;
            if (index >= 0) content = all[std::size_t(index)].id;
        }
        if (index >= 0) v.index = index;
        // The two radiance images every run has: contents 0 (final) and 1 (L_air).
        const auto radiancePane = [&](int shown, const char* id, const char* note, const viz::Image& image) {
            v.shown = shown;
            v.pane.id = id;
            v.pane.label = contentLabel(shown);
            v.pane.note = note;
            v.pane.units = "radiance";
            v.pane.kind = viz::ViewKind::Color;
            v.pane.mode = DisplayMode::HdrColor;
            uploadImage(v.pane, image);
        };
        if (content == "final") {
            radiancePane(0, "final", "surface radiance * exp(-sigma_t d) + L_air", mOutput.final);
        } else if (content == "airlight") {
            radiancePane(1, "airlight", "in-scattered radiance along each eye ray, before the surface term",
                         mOutput.airlight);
        } else {
            v.shown = index + 2;
            makePane(v.pane, all[std::size_t(index)], v.layer);
            v.layer = v.pane.layer;
        }
        if (v.display.difference != DifferenceMode::Off && (content == "final" || content == "airlight"))
            makeDifference(v, content);
    }

    // Difference mode: this technique's image against the same image of `against` (same scene, camera,
    // size; that technique's own settings), as a heat map (or blue-white-red when signed), with the
    // report's error figures in the title.
    void makeDifference(ViewState& v, const std::string& content) {
        const DisplaySettings& d = v.display;
        const viz::Image& mine = content == "final" ? mOutput.final : mOutput.airlight;
        const OtherRun* other = otherRun(d.against);
        if (!other) {
            v.differenceNote = mReduced ? "difference to " + d.against + ": after the interaction"
                                        : "difference to " + d.against + ": computing it...";
            return;
        }
        if (!other->failure.empty()) {
            v.differenceNote = d.against + " failed: " + firstLine(other->failure);
            return;
        }
        const viz::Image& theirs = content == "final" ? other->final : other->airlight;
        if (mine.empty() || theirs.empty() || mine.width != theirs.width || mine.height != theirs.height ||
            mine.channels != theirs.channels) {
            v.differenceNote = "difference to " + d.against + ": no image of the same size yet";
            return;
        }
        v.error = viz::report::compareImages(mine, theirs);
        const viz::Image diff = differenceImage(mine, theirs, d.difference);
        PaneImage pane;
        pane.id = v.pane.id;
        pane.label = v.pane.label + ": " + differenceModeNames()[std::size_t(d.difference)] + ", b = " + d.against;
        pane.note = d.difference == DifferenceMode::Signed
            ? "sum over RGB of (a - b): blue where a is darker, red where brighter"
            : d.difference == DifferenceMode::Relative
                ? "sum_c |a - b| / max(sum_c |b|, 1% of its mean): the report's per-pixel relative error"
                : "sum over RGB of |a - b|, a = " + technique().id();
        pane.units = d.difference == DifferenceMode::Relative ? "" : "radiance";
        pane.kind = d.difference == DifferenceMode::Signed ? viz::ViewKind::Signed : viz::ViewKind::Scalar;
        pane.mode = d.difference == DifferenceMode::Signed ? DisplayMode::Signed : DisplayMode::Heat;
        // Suggested range: up to the 99.9th percentile, so a few outliers do not wash out the map.
        const ValueRange r = percentileRange(diff.pixels, 0.001, 0.999);
        const float top = r.valid ? std::max({std::abs(r.lo), std::abs(r.hi), 1e-12f}) : 1.0f;
        pane.rangeMin = d.difference == DifferenceMode::Signed ? -top : 0.0f;
        pane.rangeMax = top;
        uploadImage(pane, diff);
        v.pane = std::move(pane);
    }

    // The other side of difference views: `id`'s images for the current scene, camera and size, kept
    // until any of those change. CPU techniques (the reference, from its on-disk cache when it has the
    // frame) run on a worker thread of their own, so that the window stays responsive: null until its
    // full-size pass arrives (pollOtherWorker). GPU techniques need this thread's GL context: they are
    // queued and run at the start of the next frame (runDueGpuOthers), after a frame that says so, as
    // the window does for a slow run of its own technique. The current technique is its own last output.
    const OtherRun* otherRun(const std::string& id) {
        if (mReduced) return nullptr;
        if (id == technique().id()) {
            mSelfRun = {"", mOutput.airlight, mOutput.final, "", ""};
            return &mSelfRun;
        }
        const std::string key = otherRunKey(id);
        OtherRun& run = mOtherRuns[id];
        if (run.key == key) return &run;
        try {
            if (!mTechniques.count(id)) mTechniques[id] = viz::makeTechnique(id);
        } catch (const std::exception& e) {
            run = OtherRun{key, {}, {}, e.what(), ""};
            return &run;
        }
        if (run.pending == key) return nullptr;
        run.pending = key;
        if (mTechniques.at(id)->needsGl()) {
            mGpuOthersDue = true;
            return nullptr;
        }
        // The worker keeps its own copy of the scene: handed the new one when the medium or lights changed.
        if (!mOtherWorker) mOtherWorker = std::make_unique<CpuWorker>(mScene);
        else if (mOtherSceneKey != sceneOnlyKey()) mOtherWorker->setScene(mScene);
        mOtherSceneKey = sceneOnlyKey();
        std::string ignored;
        mOtherWorker->submit({id, mController.camera(), settingsFor(*mTechniques.at(id), otherSettings(id), ignored),
                              mOutputSize.x, mOutputSize.y});
        return nullptr;
    }

    // The settings `id` runs with on the other side: the session's for it, then the command line's.
    viz::Settings otherSettings(const std::string& id) const {
        viz::Settings given = mSession.settings.count(id) ? mSession.settings.at(id) : viz::Settings{};
        for (const auto& [name, value] : mOptions.settings) given[name] = value;
        return given;
    }

    // What the other side's images depend on: technique, size, camera, scene (medium, lights), settings.
    std::string otherRunKey(const std::string& id) const {
        std::string key = id + " " + std::to_string(mOutputSize.x) + "x" + std::to_string(mOutputSize.y);
        const viz::scene::Camera c = mController.camera();
        char buf[512];
        std::snprintf(buf, sizeof buf, " %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g", c.position.x,
                      c.position.y, c.position.z, c.forward.x, c.forward.y, c.forward.z, c.up.x, c.up.y, c.up.z, c.yfov);
        key += buf;
        key += " " + sceneOnlyKey();
        for (const auto& [name, value] : otherSettings(id)) key += " " + name + "=" + format("%.17g", value);
        return key;
    }

    // The GPU techniques queued by otherRun: run now (this blocks the thread; the frame before said
    // "computing it..."), unless the scene, camera or size moved on since they were asked for.
    void runDueGpuOthers() {
        mGpuOthersDue = false;
        for (auto& [id, run] : mOtherRuns) {
            if (run.pending.empty() || !mTechniques.count(id) || !mTechniques.at(id)->needsGl()) continue;
            const std::string key = std::exchange(run.pending, std::string());
            if (key != otherRunKey(id)) continue;  // stale: the next refresh asks again
            run = OtherRun{key, {}, {}, "", ""};
            try {
                viz::Technique& t = *mTechniques.at(id);
                std::string ignored;
                viz::scene::Scene scene = mScene;
                scene.camera = mController.camera();
                viz::FrameInput in{&scene, mOutputSize.x, mOutputSize.y, settingsFor(t, otherSettings(id), ignored), -1};
                viz::FrameOutput out = t.run(in);
                glBindFramebuffer(GL_FRAMEBUFFER, 0);
                run.airlight = std::move(out.airlight);
                run.final = std::move(out.final);
            } catch (const std::exception& e) {
                run.failure = e.what();
            }
            for (auto& [vid, v] : mViews)
                if (v.display.difference != DifferenceMode::Off && v.display.against == id) refreshView(v);
        }
    }

    // The medium and lights: what a CPU worker's scene copy depends on besides the camera.
    std::string sceneOnlyKey() const {
        char buf[96];
        std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g", mScene.medium.sigma_s, mScene.medium.sigma_a,
                      mScene.medium.g);
        std::string key = buf;
        for (const auto& l : mScene.lights)
            for (const double x : {l.position.x, l.position.y, l.position.z, l.direction.x, l.direction.y,
                                   l.direction.z, l.intensity, l.color.x, l.color.y, l.color.z}) {
                key += ' ';  // appended apart: GCC 12 at -O3 warns (-Wrestrict) on " " + a temporary here
                key += format("%.17g", x);
            }
        return key;
    }

    // The difference worker's full-size pass: the other side of the difference views it was asked for.
    void pollOtherWorker() {
        if (!mOtherWorker) return;
        std::optional<CpuResult> result = mOtherWorker->take();
        if (!result || (result->error.empty() && result->pass < result->passCount)) return;
        auto it = mOtherRuns.find(result->technique);
        if (it == mOtherRuns.end() || it->second.pending.empty()) return;
        OtherRun& run = it->second;
        run.key = std::exchange(run.pending, std::string());
        run.failure = result->error;
        run.airlight = std::move(result->output.airlight);
        run.final = std::move(result->output.final);
        for (auto& [id, v] : mViews)
            if (v.display.difference != DifferenceMode::Off && v.display.against == result->technique) refreshView(v);
    }

    bool otherPending() const {
        for (const auto& [id, run] : mOtherRuns)
            if (!run.pending.empty()) return true;
        return false;
    }

    void refreshView(ViewState& v) {
        buildPane(v);
        if (mReduced) {
            // During an interaction the frames are smaller and short-lived: no readback.
            v.values = {};
            updateStatistics(v);
        } else {
            readBackValues(v);
        }
    }

    // The technique's view of the inspected pixel in the last run, read back once per run and pixel.
    const PixelInspection& probeInspection() {
        if (!mProbeInspection)
            mProbeInspection = inspectRun(technique(), mOutput, {mOptions.width, mOptions.height}, {mProbe->x, mProbe->y});
        return *mProbeInspection;
    }

    void refreshPanes() {
        mMarkerCache.clear();
        mProbeInspection.reset();
        if (mHaveOutput && !mExposureSet && !mOutput.final.empty()) {
            mExposure = std::round(std::log2(autoExposure(mOutput.final)) / kExposureStep) * kExposureStep;
            mExposureSet = true;
        }
        for (auto& [id, v] : mViews) refreshView(v);
    }

    // [ ] and the views list: what the focused view shows.
    void stepView(int delta) {
        if (!mHaveOutput) return;
        ViewState& v = focusedView();
        const int n = contentCount();
        selectView((((v.shown < 0 ? 1 : v.shown) + delta) % n + n) % n);
    }

    void selectView(int index) {
        if (!mHaveOutput || index < 0 || index >= contentCount()) return;
        ViewState& v = focusedView();
        v.content = contentId(index);
        v.index = index - 2;
        v.layer = 0;
        v.transform.fit();
        refreshView(v);
    }

    void stepLayer(int delta) {
        ViewState& v = focusedView();
        if (v.pane.layers <= 1) return;
        v.layer = (v.pane.layer + delta + v.pane.layers) % v.pane.layers;
        refreshView(v);
    }

    // H / J: a new view beside / below the focused one, showing the content after the focused one's.
    void splitFocused(SplitAxis axis) {
        mLayout.restore();
        const int id = mNextView++;
        if (!mLayout.split(mFocused, axis, id)) return;
        ViewState& v = mViews[id];
        const int shown = mViews.at(mFocused).shown;
        if (mHaveOutput) {
            const int next = (shown < 0 ? 1 : shown + 1) % contentCount();
            v.content = contentId(next);
            v.index = next - 2;
        }
        mFocused = id;
        refreshView(v);
    }

    // K: closes the focused view (not the last one).
    void closeFocused() {
        if (!mLayout.close(mFocused)) {
            mNotice = "the last view stays open";
            return;
        }
        mViews.erase(mFocused);
        mFocused = mLayout.views().front();
    }

    // O / Shift+O: the focused view trades places with the next / previous one (it keeps the focus).
    void swapFocused(int step) {
        mLayout.restore();
        mLayout.swap(mFocused, mLayout.next(mFocused, step));
    }

    // F: the focused view's difference to the reference on or off (final frame and L_air views).
    void toggleDifference() {
        ViewState& v = focusedView();
        if (v.pane.id != "final" && v.pane.id != "airlight" && v.display.difference == DifferenceMode::Off) {
            mNotice = "difference views are for the final frame and L_air";
            return;
        }
        v.display.difference = v.display.difference == DifferenceMode::Off ? DifferenceMode::Absolute : DifferenceMode::Off;
        refreshView(v);
    }

    // ---- input ----

    glm::vec2 cursorPixels(double x, double y) const {
        int ww = 1, wh = 1;
        glfwGetWindowSize(mWindow.handle(), &ww, &wh);
        const glm::ivec2 fb = mWindow.framebufferSize();
        return {float(x) * float(fb.x) / float(std::max(ww, 1)), float(y) * float(fb.y) / float(std::max(wh, 1))};
    }

    void onKey(int key, int action, int mods) {
        if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
        if (mLesson && mLesson->onKey(key, action == GLFW_REPEAT)) return;
        const bool shift = (mods & GLFW_MOD_SHIFT) != 0;
        mUiInput.shift = shift;
        mUiInput.ctrl = (mods & GLFW_MOD_CONTROL) != 0;
        // Home / End: the first / last sub-step, unless a text field is being edited.
        if ((key == GLFW_KEY_HOME || key == GLFW_KEY_END) && !mUi->textFocused()) {
            setSubstepAt(key == GLFW_KEY_HOME ? 1 : substepState().second);
            return;
        }
        if (const auto k = uiKey(key)) {
            mUiInput.keys.push_back(*k);  // widgets: arrows, Enter, Space, editing keys
            return;
        }
        // In fly mode W A S D Q E drive the camera (fly() reads them as held keys) and nothing else: S
        // does not also step the stage, nor E export a view.
        if (mController.mode() == CameraController::Mode::Fly &&
            (key == GLFW_KEY_W || key == GLFW_KEY_A || key == GLFW_KEY_S || key == GLFW_KEY_D || key == GLFW_KEY_Q ||
             key == GLFW_KEY_E))
            return;
        if (key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(mWindow.handle(), GLFW_TRUE);
        else if (key == GLFW_KEY_TAB) selectTechnique(mCurrent + (shift ? -1 : 1));
        else if (key >= GLFW_KEY_1 && key <= GLFW_KEY_9 && key - GLFW_KEY_1 < int(mIds.size())) selectTechnique(key - GLFW_KEY_1);
        else if (key == GLFW_KEY_RIGHT_BRACKET || (key == GLFW_KEY_V && !shift)) stepView(1);
        else if (key == GLFW_KEY_LEFT_BRACKET || (key == GLFW_KEY_V && shift)) stepView(-1);
        else if (key == GLFW_KEY_PERIOD || key == GLFW_KEY_COMMA) stepLayer(key == GLFW_KEY_PERIOD ? 1 : -1);
        else if (key == GLFW_KEY_C && action == GLFW_PRESS) mController.toggleMode();
        else if (key == GLFW_KEY_F5 && action == GLFW_PRESS) saveSessionNow();
        else if (key == GLFW_KEY_0 && action == GLFW_PRESS) focusedView().transform.fit();
        else if (key == GLFW_KEY_H && action == GLFW_PRESS) splitFocused(SplitAxis::X);
        else if (key == GLFW_KEY_J && action == GLFW_PRESS) splitFocused(SplitAxis::Y);
        else if (key == GLFW_KEY_K && action == GLFW_PRESS) closeFocused();
        else if (key == GLFW_KEY_M && action == GLFW_PRESS) mLayout.toggleMaximise(mFocused);
        else if (key == GLFW_KEY_O && action == GLFW_PRESS) swapFocused(shift ? -1 : 1);
        else if (key == GLFW_KEY_N && action == GLFW_PRESS) mFocused = mLayout.next(mFocused, shift ? -1 : 1);
        else if (key == GLFW_KEY_F && action == GLFW_PRESS) toggleDifference();
        else if (key == GLFW_KEY_I && action == GLFW_PRESS) inspectPixelUnderCursor();
        else if (key == GLFW_KEY_P && action == GLFW_PRESS) togglePlaying();
        else if (key == GLFW_KEY_L && action == GLFW_PRESS) mShowGizmo = !mShowGizmo;
        else if (key == GLFW_KEY_E && action == GLFW_PRESS) exportView();
        else if (key == GLFW_KEY_G && action == GLFW_PRESS) toggleComparison();
        else if (key == GLFW_KEY_F12 && action == GLFW_PRESS) exportWindow();
        else if (key == GLFW_KEY_S) stepStage(shift ? -1 : 1);
        else if (key == GLFW_KEY_D) stepSubstep(shift ? -1 : 1);
        else if (key == GLFW_KEY_F9 && action == GLFW_PRESS) loadSessionNow();
        else if (key == GLFW_KEY_R && action == GLFW_PRESS) {
            mController.reset();
            mDirty = true;
        } else if (key == GLFW_KEY_X && action == GLFW_PRESS) {
            mExposureSet = false;  // auto exposure again on the next frame
            if (!mOutput.final.empty()) {
                mExposure = std::round(std::log2(autoExposure(mOutput.final)) / kExposureStep) * kExposureStep;
                mExposureSet = true;
            }
        }
    }

    void onChar(unsigned codepoint) {
        if (codepoint == '+' || codepoint == '=') mExposure += kExposureStep;
        if (codepoint == '-' || codepoint == '_') mExposure -= kExposureStep;
    }

    void onMouseButton(int button, int action) {
        double x = 0, y = 0;
        glfwGetCursorPos(mWindow.handle(), &x, &y);
        onMouseButtonAt(button, action, cursorPixels(x, y));
    }

    void onMouseButtonAt(int button, int action, glm::vec2 p) {
        if (action == GLFW_RELEASE && mDragTimeline) {
            mDragTimeline = false;
            return;
        }
        if (action == GLFW_PRESS) {
            if (button == GLFW_MOUSE_BUTTON_LEFT) {
                for (const auto& [rect, action2] : mHits) {
                    if (rect.contains(p)) {
                        action2();
                        return;
                    }
                }
            }
            if (mParamsRect.contains(p)) return;  // the widgets read the button state themselves
            // A widget (or an open list hanging over a view) was under this very point last frame.
            if (mUi->hot() != 0 && p == mHoverDrawn) return;
            for (const Rect& r : mStripRects)
                if (r.contains(p)) return;
            for (const Rect& r : mDividerRects)  // the splitter widget takes the drag
                if (r.contains(p)) return;
            if (button == GLFW_MOUSE_BUTTON_LEFT) {
                if (auto handle = gizmoHandleAt(p)) {
                    mGizmoDrag = handle;
                    mFocused = handle->view;
                    return;
                }
            }
            const int view = ViewLayout::hit(mCells, p);
            if (view >= 0 && mViews.count(view)) {
                mFocused = view;  // any click in a view focuses it
                const ViewState& v = mViews.at(view);
                if (button == GLFW_MOUSE_BUTTON_LEFT && v.title.contains(p)) {
                    mDragTitle = view;  // dropped on another view: the two swap places
                    return;
                }
                if (button == GLFW_MOUSE_BUTTON_LEFT && v.image.contains(p) && isOrbitView(v)) {
                    mDragOrbit = view;  // an orbit view: dragging turns its camera
                    mLastCursor = p;
                    return;
                }
                if (v.image.contains(p) && v.transform.zoom > 1.0) {
                    mDragView = view;  // zoomed in: dragging pans the view, not the camera
                    mLastCursor = p;
                    return;
                }
            }
            if (!mViewArea.contains(p)) return;
            mDragButton = button;
            mLastCursor = p;
        } else if (action == GLFW_RELEASE && mDragTitle >= 0) {
            const int target = ViewLayout::hit(mCells, p);
            if (target >= 0 && target != mDragTitle) mLayout.swap(mDragTitle, target);
            mDragTitle = -1;
        } else if (action == GLFW_RELEASE && mGizmoDrag) {
            mGizmoDrag.reset();
            if (mReduced) mDirty = true;  // the full size follows
        } else if (action == GLFW_RELEASE && mDragOrbit >= 0) {
            mDragOrbit = -1;
        } else if (action == GLFW_RELEASE && mDragView >= 0) {
            mDragView = -1;
        } else if (action == GLFW_RELEASE && button == mDragButton) {
            mDragButton = -1;
            if (mReduced) mDirty = true;
        }
    }

    void onCursor(double x, double y) { onCursorPixels(cursorPixels(x, y)); }

    // Orbit views (render::MeshView: polyvol's light volume, slices' planes) turn with a left drag:
    // their mesh_yaw / mesh_pitch parameters, 0.4 degrees per pixel.
    bool isOrbitView(const ViewState& v) const {
        const auto& all = mOutput.intermediates;
        return mHaveOutput && v.index >= 0 && v.index < int(all.size()) && all[std::size_t(v.index)].id == v.content &&
               all[std::size_t(v.index)].orbit && mSettings.count("mesh_yaw") && mSettings.count("mesh_pitch");
    }

    void turnOrbitView(glm::vec2 d) {
        double yaw = mSettings.at("mesh_yaw") - 0.4 * double(d.x);
        yaw = std::remainder(yaw, 360.0);
        mSettings["mesh_yaw"] = yaw;
        mSettings["mesh_pitch"] = std::clamp(mSettings.at("mesh_pitch") + 0.4 * double(d.y), -89.0, 89.0);
        mDirty = true;
    }

    void onCursorPixels(glm::vec2 p) {
        mHover = p;
        if (mDragTimeline) {
            moveCursor(timelineCursorAt(mTimeline, p.x));
            return;
        }
        if (mGizmoDrag) {
            dragGizmo(p);
            return;
        }
        if (mDragOrbit >= 0) {
            turnOrbitView(p - mLastCursor);
            mLastCursor = p;
            return;
        }
        if (mDragView >= 0 && mViews.count(mDragView)) {
            ViewState& v = mViews.at(mDragView);
            v.transform.panBy(glm::dvec2((p - mLastCursor) / glm::max(v.image.size(), glm::vec2(1.0f))));
            mLastCursor = p;
            return;
        }
        if (mDragButton < 0) return;
        const glm::dvec2 d = glm::dvec2(p - mLastCursor);
        mLastCursor = p;
        if (d == glm::dvec2(0.0)) return;
        const double paneHeight = std::max(1.0f, mImageHeight);
        const bool orbitMode = mController.mode() == CameraController::Mode::Orbit;
        if (orbitMode && mDragButton == GLFW_MOUSE_BUTTON_LEFT) {
            // Dragging right turns the scene right: the eye moves the other way round the target.
            mController.orbit(-d.x * kOrbitRadiansPerPixel, d.y * kOrbitRadiansPerPixel);
        } else if (orbitMode) {
            // The scene follows the cursor: the camera moves against the drag.
            mController.pan(-d.x / paneHeight, d.y / paneHeight);
        } else if (mDragButton == GLFW_MOUSE_BUTTON_RIGHT || mDragButton == GLFW_MOUSE_BUTTON_LEFT) {
            mController.look(-d.x * kLookRadiansPerPixel, -d.y * kLookRadiansPerPixel);
        } else {
            mController.pan(-d.x / paneHeight, d.y / paneHeight);
        }
        mDirty = true;
    }

    void onScroll(double dy) {
        if (mLesson && mLesson->area().contains(mHover)) {
            mLesson->scroll(float(dy));
            return;
        }
        bool overWidgets = mParamsRect.contains(mHover);
        for (const Rect& r : mStripRects) overWidgets = overWidgets || r.contains(mHover);
        if (overWidgets) {
            mUiInput.wheel += float(dy);
            return;
        }
        const int view = ViewLayout::hit(mCells, mHover);
        if (view >= 0 && mViews.count(view) && isOrbitView(mViews.at(view)) && mSettings.count("mesh_zoom") &&
            mViews.at(view).image.contains(mHover)) {
            // An orbit view: the wheel moves its own camera in (mesh_zoom, 1.25x a notch), not the texture.
            const auto& params = technique().params();
            const auto zoom = std::find_if(params.begin(), params.end(), [](const auto& p) { return p.name == "mesh_zoom"; });
            if (zoom == params.end()) return;
            mSettings["mesh_zoom"] = std::clamp(mSettings.at("mesh_zoom") * std::pow(1.25, dy), zoom->minValue, zoom->maxValue);
            mDirty = true;
            return;
        }
        if (view >= 0 && mViews.count(view) && mViews.at(view).content != "final" && mViews.at(view).image.contains(mHover)) {
            // The wheel over a view zooms it about the cursor (the camera stays); over the final frame
            // it moves the camera.
            ViewState& v = mViews.at(view);
            v.transform.zoomAt(glm::dvec2((mHover - v.image.min) / v.image.size()), std::pow(1.25, dy));
            return;
        }
        // Titles, readouts and histograms do not move the camera.
        if (view >= 0 && mViews.count(view) && !mViews.at(view).image.contains(mHover)) return;
        if (!mViewArea.contains(mHover)) return;
        if (mController.mode() == CameraController::Mode::Orbit) {
            mController.zoom(dy);
        } else {
            mController.move({0.0, 0.0, 0.1 * dy});
        }
        mDirty = true;
    }

    bool anyFlyKeyDown() const {
        for (int key : {GLFW_KEY_W, GLFW_KEY_A, GLFW_KEY_S, GLFW_KEY_D, GLFW_KEY_Q, GLFW_KEY_E})
            if (glfwGetKey(mWindow.handle(), key) == GLFW_PRESS) return true;
        return false;
    }

    void fly(double dt) {
        GLFWwindow* w = mWindow.handle();
        const auto down = [&](int key) { return glfwGetKey(w, key) == GLFW_PRESS ? 1.0 : 0.0; };
        const glm::dvec3 dir{down(GLFW_KEY_D) - down(GLFW_KEY_A), down(GLFW_KEY_E) - down(GLFW_KEY_Q),
                             down(GLFW_KEY_W) - down(GLFW_KEY_S)};
        if (dir == glm::dvec3(0.0)) return;
        const bool fast = glfwGetKey(w, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS;
        mController.move(dir * (kFlySpeed * dt * (fast ? 4.0 : 1.0)));
        mDirty = true;
    }

    // ---- drawing ----

    // Largest rectangle of the image's aspect ratio (the render's when the pane is empty) inside
    // `area`, centred at the top.
    Rect fitImage(const Rect& area, glm::ivec2 imageSize) const {
        if (imageSize.x <= 0 || imageSize.y <= 0) imageSize = {mOptions.width, mOptions.height};
        const float aspect = float(imageSize.x) / float(std::max(1, imageSize.y));
        float w = area.size().x, h = w / aspect;
        if (h > area.size().y) {
            h = area.size().y;
            w = h * aspect;
        }
        const float x = area.min.x + 0.5f * (area.size().x - w);
        return {{x, area.min.y}, {x + w, area.min.y + h}};
    }

    // A clickable list entry: highlighted when selected, lighter under the cursor.
    void listItem(const Rect& r, const std::string& text, bool selected, std::function<void()> onClick) {
        DrawList& dl = *mDrawList;
        if (selected) dl.rect(r, kHighlight);
        else if (r.contains(mHover)) dl.rect(r, kHover);
        dl.textClipped({r.min.x + 6.0f * mScale, r.min.y + 1.0f * mScale}, text, selected ? kText : kDim, r.max.x - 4.0f * mScale);
        mHits.push_back({r, std::move(onClick)});
    }

    // The texel of `pane` under a window point, through the view's pan and zoom; row 0 is the row shown
    // at the top (the image convention: for a frame-sized view, the frame's pixel).
    static glm::ivec2 texelAt(const PaneImage& pane, const Rect& image, const viz::ui::ImageViewTransform& view,
                              glm::vec2 p) {
        const glm::dvec2 uv = view.paneToUv(glm::dvec2((p - image.min) / image.size()));
        return glm::clamp(glm::ivec2(glm::floor(uv * glm::dvec2(pane.size))), glm::ivec2(0), pane.size - 1);
    }

    // Zoomed in until a texel is large enough to hold its value: write the value in every visible texel
    // (one read of the visible block per frame).
    void texelValues(const PaneImage& pane, const Rect& image, const viz::ui::ImageViewTransform& view) {
        const float cell = float(view.texelPixels(image.size().x, std::max(1, pane.size.x)));
        const float line = mFont->lineHeight();
        if (cell < 4.2f * line || pane.size.x < 1 || pane.size.y < 1) return;
        const glm::ivec2 lo = texelAt(pane, image, view, image.min), hi = texelAt(pane, image, view, image.max - 1.0f);
        const glm::ivec2 count = hi - lo + 1;
        if (count.x * count.y > 4096) return;
        std::vector<glm::vec4> values(std::size_t(count.x * count.y));
        // GL rows: flipped textures keep row 0 at the bottom.
        const int glRow0 = pane.flipY ? pane.size.y - 1 - hi.y : lo.y;
        glGetTextureSubImage(pane.texture, 0, lo.x, glRow0, 0, count.x, count.y, 1, GL_RGBA, GL_FLOAT,
                             GLsizei(values.size() * sizeof(glm::vec4)), values.data());
        const int channels = std::clamp(pane.channels, 1, 3);
        const bool allChannels = cell >= float(channels) * line + 4.0f * mScale;
        for (int ty = lo.y; ty <= hi.y; ++ty)
            for (int tx = lo.x; tx <= hi.x; ++tx) {
                const int row = pane.flipY ? hi.y - ty : ty - lo.y;
                const glm::vec4 v = values[std::size_t(row * count.x + (tx - lo.x))];
                const glm::vec2 corner = image.min + glm::vec2(view.uvToPane(glm::dvec2(tx, ty) / glm::dvec2(pane.size))) * image.size();
                // The part of the texel inside the view holds the text.
                const glm::vec2 shownMin = glm::max(corner, image.min), shownMax = glm::min(corner + cell, image.max);
                if (shownMax.x - shownMin.x < 3.0f * line || shownMax.y - shownMin.y < line + 4.0f * mScale) continue;
                for (int c = 0; c < (allChannels ? channels : 1); ++c) {
                    const glm::vec2 at = shownMin + glm::vec2(3.0f * mScale, 2.0f * mScale + float(c) * line);
                    if (at.y + line > shownMax.y) break;
                    const std::string text = format("%.3g", v[c]);
                    mDrawList->rect({at - 1.0f, at + glm::vec2(mFont->measure(text) + 1.0f, line)}, {0.0f, 0.0f, 0.0f, 0.55f});
                    mDrawList->textClipped(at, text, kText, shownMax.x - 2.0f);
                }
            }
    }

    // ---- the view grid: drawing ----

    // Title (two lines), image, value readout and, when open, the display strip inside one cell.
    void layoutCell(ViewState& v, const Rect& cell) {
        const float line = mFont->lineHeight(), s = mScale;
        v.cell = cell;
        v.title = {cell.min, {cell.max.x, cell.min.y + 2.0f * line + 4.0f * s}};
        const float readout = line + 6.0f * s;
        float stripHeight = 0.0f;
        if (v.display.stripOpen) {
            const float rows = (v.display.range == RangeMode::Manual ? 8.0f : 6.0f) +
                               (v.display.difference != DifferenceMode::Off ? 1.0f : 0.0f);
            float wanted = rows * (mUi->rowHeight() + 4.0f * s) + 8.0f * s;
            // A narrow view stacks the histogram under the widgets instead of beside them.
            if (cell.size().x < kStripSideBySide * s) wanted += kHistogramHeight * s;
            stripHeight = std::min(wanted, 0.6f * (cell.size().y - v.title.size().y - readout));
        }
        const Rect imageArea{{cell.min.x, v.title.max.y}, {cell.max.x, cell.max.y - readout - stripHeight}};
        v.image = v.pane.plots.empty() ? fitImage(imageArea, v.pane.size) : imageArea;  // plots take the whole area
        v.strip = stripHeight > 0.0f ? Rect{{cell.min.x, cell.max.y - stripHeight}, cell.max} : Rect{};
    }

    // ---- the light gizmo (light_gizmo.h): the first light's handles over the frame views ----

    std::optional<LightGizmo> gizmoFor(const ViewState& v) const {
        if (!mShowGizmo || !mHaveOutput || mScene.lights.empty() || !LightGizmo::hasHandles(mScene.lights[0])) return {};
        if ((v.content != "final" && v.content != "airlight") || !isScreenSpace(v)) return {};
        return LightGizmo(mController.camera(), v.pane.size, mGizmoArm, mController.target());
    }

    // Frame pixels (continuous, y down) <-> window pixels, through the view's pan and zoom.
    static glm::vec2 frameToWindow(const ViewState& v, glm::dvec2 px) {
        return v.image.min + glm::vec2(v.transform.uvToPane(px / glm::dvec2(v.pane.size))) * v.image.size();
    }
    static glm::dvec2 windowToFrame(const ViewState& v, glm::vec2 p) {
        return v.transform.paneToUv(glm::dvec2((p - v.image.min) / v.image.size())) * glm::dvec2(v.pane.size);
    }

    // Where a handle is drawn and grabbed: its window point, or (off the view) the nearest point just
    // inside the image's edge; `inside` says which.
    glm::vec2 handlePoint(const ViewState& v, glm::dvec2 px, bool& inside) const {
        const glm::vec2 p = frameToWindow(v, px);
        const float inset = 7.0f * mScale;
        const glm::vec2 q = glm::clamp(p, v.image.min + inset, v.image.max - inset);
        inside = q == p;
        return q;
    }

    // The handle under `p` (the direction handle first: it is the smaller target), within 8 pixels.
    // Drags are relative: a handle off the view is grabbed at the view's edge and follows the cursor.
    std::optional<GizmoDrag> gizmoHandleAt(glm::vec2 p) const {
        const float grab = 8.0f * mScale;
        for (const ViewCellRect& c : mCells) {
            const ViewState& v = mViews.at(c.view);
            const auto gizmo = gizmoFor(v);
            if (!gizmo || !v.image.contains(p)) continue;
            const GizmoHandles h = gizmo->handles(mScene.lights[0]);
            bool inside = true;
            const glm::dvec2 cursor = windowToFrame(v, p), size(v.pane.size);
            if (h.tip && glm::length(handlePoint(v, *h.tip, inside) - p) <= grab)
                return GizmoDrag{c.view, true, (*h.tip - cursor) / size};
            if (h.position && glm::length(handlePoint(v, *h.position, inside) - p) <= grab)
                return GizmoDrag{c.view, false, (*h.position - cursor) / size};
        }
        return std::nullopt;
    }

    void dragGizmo(glm::vec2 p) {
        if (!mViews.count(mGizmoDrag->view) || mScene.lights.empty()) return;
        const ViewState& v = mViews.at(mGizmoDrag->view);
        const auto gizmo = gizmoFor(v);
        if (!gizmo) return;
        viz::scene::Light& light = mScene.lights[0];
        const glm::dvec2 px = windowToFrame(v, p) + mGizmoDrag->offset * glm::dvec2(v.pane.size);
        if (mGizmoDrag->direction ? gizmo->dragDirection(light, px) : gizmo->dragPosition(light, px)) sceneEdited();
    }

    // The first light's handles: a square at its position (point, spot), a diamond at the end of its
    // direction arm (spot: where the light goes; directional: where it comes from, the arm ending at
    // the orbit target). Scripts name them "gizmo:position" and "gizmo:direction" (in the first view
    // that shows them).
    void drawGizmo(DrawList& dl, int id, const ViewState& v) {
        const auto gizmo = gizmoFor(v);
        if (!gizmo) return;
        const GizmoHandles h = gizmo->handles(mScene.lights[0]);
        const float r = 5.0f * mScale, w = 1.5f * mScale;
        const glm::vec4 shadow{0.0f, 0.0f, 0.0f, 0.8f}, yellow{1.0f, 0.9f, 0.25f, 1.0f};
        dl.pushClip(v.image);
        const auto lit = [&](bool direction) {
            return (mGizmoDrag && mGizmoDrag->view == id && mGizmoDrag->direction == direction) ? kText : yellow;
        };
        bool inside = true;
        if (h.tip) {
            // The arm, when its root is in front of the camera too (a light behind the camera can still be
            // turned by its tip).
            if (h.root) {
                const glm::vec2 a = frameToWindow(v, *h.root), tip = frameToWindow(v, *h.tip);
                dl.line(a, tip, w + 2.0f * mScale, shadow);
                dl.line(a, tip, w, yellow);
            }
            const glm::vec2 b = handlePoint(v, *h.tip, inside);
            const glm::vec2 corners[4] = {{b.x, b.y - r - 1.0f}, {b.x + r + 1.0f, b.y}, {b.x, b.y + r + 1.0f}, {b.x - r - 1.0f, b.y}};
            for (int pass = 0; pass < 2; ++pass)
                for (int i = 0; i < 4; ++i)
                    dl.line(corners[i], corners[(i + 1) % 4], pass == 0 ? w + 2.0f * mScale : w, pass == 0 ? shadow : lit(true));
            if (!mNamedRects.count("gizmo:direction")) mNamedRects["gizmo:direction"] = {b - r, b + r};
        }
        if (h.position) {
            const glm::vec2 c = handlePoint(v, *h.position, inside);
            dl.rect({c - r - 1.0f * mScale, c + r + 1.0f * mScale}, shadow);
            // Off the view: a hollow square at the edge nearest the light.
            dl.rect({c - r, c + r}, lit(false));
            if (!inside) dl.rect({c - r + 2.0f * mScale, c + r - 2.0f * mScale}, shadow);
            const std::string name = (mScene.lights[0].name.empty() ? std::string("light") : mScene.lights[0].name) +
                                     (inside ? "" : " (off view)");
            const float tx = c.x + r + 4.0f * mScale + mFont->measure(name) < v.image.max.x
                                 ? c.x + r + 4.0f * mScale
                                 : c.x - r - 4.0f * mScale - mFont->measure(name);
            dl.textClipped({tx, c.y - 0.5f * mFont->lineHeight()}, name, yellow, v.image.max.x);
            if (!mNamedRects.count("gizmo:position")) mNamedRects["gizmo:position"] = {c - r, c + r};
        }
        dl.popClip();
    }

    // The scene's medium or lights changed (panel, gizmo): the CPU worker keeps its own copy of the
    // scene, and the plan may change.
    void sceneEdited() {
        mWorker->setScene(mScene);
        replan();
    }

    // The gaps between views: each is the toolkit's splitter over its split (scripts name them
    // "divider:root", "divider:1", ... by the split's path).
    void drawDividers(const Rect& area) {
        const auto dividers = !mComparison.isOpen() ? mLayout.dividers(area, kPad * mScale) : std::vector<ViewDivider>{};
        std::optional<SplitAxis> over;
        mDividerRects.clear();
        for (const ViewDivider& d : dividers) {
            const std::string name = "divider:" + (d.path.empty() ? std::string("root") : d.path);
            float fraction = d.fraction;
            if (mUi->splitter(name, d.track, d.axis == SplitAxis::X, fraction)) mLayout.setFraction(d.path, fraction);
            if (const auto it = mUi->widgetRects().find(name); it != mUi->widgetRects().end()) {
                mDividerRects.push_back(it->second);
                if (it->second.contains(mHover)) over = d.axis;
            }
        }
        setResizeCursor(over);
    }

    // The window's cursor shows a divider can be dragged.
    void setResizeCursor(std::optional<SplitAxis> axis) {
        if (axis == mCursorAxis) return;
        mCursorAxis = axis;
        GLFWcursor*& cursor = !axis ? mArrowCursor : *axis == SplitAxis::X ? mColumnCursor : mRowCursor;
        if (!cursor && axis)
            cursor = glfwCreateStandardCursor(*axis == SplitAxis::X ? GLFW_HRESIZE_CURSOR : GLFW_VRESIZE_CURSOR);
        glfwSetCursor(mWindow.handle(), cursor);  // nullptr: the default arrow
    }

    void drawViewGrid(const Rect& area) {
        mStripRects.clear();
        // The comparison grid takes the right half; the first view keeps the left.
        const float half = 0.5f * (area.size().x - kPad * mScale);
        if (!mComparison.isOpen()) mCells = mLayout.arrange(area, kPad * mScale);
        else mCells = {{mLayout.views().front(), {area.min, {area.min.x + half, area.max.y}}}};
        drawDividers(area);
        for (const ViewCellRect& c : mCells) layoutCell(mViews[c.view], c.rect);
        // The frame pixel under the cursor, if the cursor is over a screen-space view.
        mHoveredView = ViewLayout::hit(mCells, mHover);
        mLinkedPixel.reset();
        if (mHoveredView >= 0) {
            const ViewState& h = mViews.at(mHoveredView);
            if (isScreenSpace(h) && h.image.contains(mHover)) mLinkedPixel = texelAt(h.pane, h.image, h.transform, mHover);
        }
        // Camera drags are scaled by the tallest frame-shaped view (the last one when none is shown).
        float frameHeight = 0.0f;
        for (const ViewCellRect& c : mCells) {
            ViewState& v = mViews.at(c.view);
            if (isScreenSpace(v)) frameHeight = std::max(frameHeight, v.image.size().y);
            drawView(c.view, v);
        }
        if (frameHeight > 1.0f) mImageHeight = frameHeight;
        if (mComparison.isOpen()) {
            const Rect grid{{area.max.x - half, area.min.y + mFont->lineHeight()}, area.max};
            drawComparison(*mDrawList, grid);
            mViewRects.push_back({"comparison", "comparison grid", grid, -1});
        }
    }

    // "name  [i/n]  id  layer k/n  |  3 negative px" and the note with the range or the error figures.
    std::pair<std::string, std::string> viewTitle(const ViewState& v) const {
        if (!mHaveOutput) return {technique().needsGl() ? "(no view)" : "computing...", ""};
        std::string title = v.pane.label.empty() ? v.content : v.pane.label;
        if (v.shown >= 0) title += "   [" + std::to_string(v.shown + 1) + "/" + std::to_string(contentCount()) + "]";
        if (v.pane.id != "final" && v.pane.id != "airlight") {
            title += "  " + v.pane.id;
            // The stage that publishes it (stepping shows it from that stage on).
            for (const viz::StageInfo& st : technique().stages())
                if (std::find(st.intermediates.begin(), st.intermediates.end(), v.pane.id) != st.intermediates.end()) {
                    title += "  (stage " + st.id + ")";
                    break;
                }
        }
        if (v.pane.layers > 1) title += "   layer " + std::to_string(v.pane.layer + 1) + "/" + std::to_string(v.pane.layers);
        std::string note = v.pane.note;
        if (v.pane.id == "final" && v.display.difference == DifferenceMode::Off)
            note = "surface radiance * exp(-sigma_t d) + L_air   (exposure " + format("%+.1f EV)", mExposure);
        const DisplayMapping m = resolveMapping(v.pane, v.display, mExposure, v.measured);
        if (m.mode != DisplayMode::HdrColor) {
            note += "   [" + format("%.4g", m.lo) + ", " + format("%.4g", m.hi) + "]" + (v.display.logScale ? " log" : "") +
                    (v.pane.units.empty() ? "" : " " + v.pane.units) + ", " + viz::viewKindName(v.pane.kind);
        }
        if (v.error) {
            const auto figure = [](double x) { return std::isfinite(x) ? format("%.3g", x) : std::string("n/a"); };
            note = "relative L2 " + figure(v.error->relativeL2) + "   max |a - b| " + figure(v.error->maxAbsolute) +
                   "   RMSE " + figure(v.error->rmse) + "   |   " + note;
        } else if (!v.differenceNote.empty()) {
            note = v.differenceNote + "   |   " + note;
        }
        if (v.transform.zoom > 1.0) note = format("zoom %.0fx (wheel; drag to pan; 0 fits)   ", v.transform.zoom) + note;
        return {title, note};
    }

    void drawView(int id, ViewState& v) {
        DrawList& dl = *mDrawList;
        const float line = mFont->lineHeight(), s = mScale;
        const bool focused = id == mFocused;
        const auto [title, note] = viewTitle(v);
        // Title bar: highlighted when focused (keys and the views list act on it); drag it onto another
        // view to swap the two.
        mBackground->rect(v.title, focused ? kHighlight : kPanel);
        const std::string toggle = v.display.stripOpen ? "display -" : "display +";
        const float toggleWidth = mFont->measure(toggle) + 16.0f * s;
        const Rect toggleRect{{v.title.max.x - toggleWidth, v.title.min.y + 1.0f * s},
                              {v.title.max.x - 2.0f * s, v.title.min.y + line + 2.0f * s}};
        float x = dl.textClipped({v.title.min.x + 4.0f * s, v.title.min.y + 2.0f * s}, title, kAccent,
                                 toggleRect.min.x - 4.0f * s);
        // Not the complete algorithm: every view says where the run stopped, in the warning colour.
        const std::string why = mHaveOutput ? stoppedEarly() : std::string();
        const std::string early = why.empty() ? why : "   [" + why + "]";
        if (!early.empty()) x = dl.textClipped({x, v.title.min.y + 2.0f * s}, early, kError, toggleRect.min.x - 4.0f * s);
        const SpecialCounts& n = v.counts;
        std::string counts;
        if (n.nan + n.inf + n.negative > 0) {
            counts = " ";
            if (n.negative) counts += " " + std::to_string(n.negative) + " negative";
            if (n.nan) counts += " " + std::to_string(n.nan) + " NaN";
            if (n.inf) counts += " " + std::to_string(n.inf) + " Inf";
            counts += " px";
            dl.textClipped({x, v.title.min.y + 2.0f * s}, counts, kError, toggleRect.min.x - 4.0f * s);
        }
        dl.textClipped({v.title.min.x + 4.0f * s, v.title.min.y + 2.0f * s + line}, note, kDim, v.title.max.x - 4.0f * s);
        listItem(toggleRect, toggle, v.display.stripOpen, [this, id] {
            ViewState& w = mViews.at(id);
            w.display.stripOpen = !w.display.stripOpen;
            mFocused = id;
        });
        mNamedRects["strip:" + std::to_string(id)] = toggleRect;
        mNamedRects["title:" + std::to_string(id)] = v.title;
        mNamedRects["cell:" + std::to_string(id)] = v.image;

        // The image, framed; the background batch is drawn before the images.
        mBackground->rect({v.image.min - 1.0f, v.image.max + 1.0f}, focused ? kHighlight : kPanel);
        if (!v.pane.plots.empty()) {
            // The technique's plots of this intermediate, stacked (its image is what `render --layer` writes).
            drawPlots(v);
            mViewRects.push_back({v.pane.id, title + early + counts, v.image, id});
            drawStatusBands(dl, v.image);
            if (v.display.stripOpen && v.strip.size().y > 0.0f) drawStrip(id, v);
            return;
        }
        mPaneDraws.push_back({v.image, &v.pane, &v.transform, resolveMapping(v.pane, v.display, mExposure, v.measured)});
        mViewRects.push_back({mHaveOutput ? (v.pane.id.empty() ? v.content : v.pane.id) : std::string("none"),
                              title + early + counts, v.image, id});
        if (!v.pane.unavailable.empty())
            dl.textClipped({v.image.min.x + 8.0f * s, v.image.min.y + 8.0f * s}, v.pane.unavailable, kDim, v.image.max.x);
        if (v.pane.texture != 0) texelValues(v.pane, v.image, v.transform);

        // Linked cursors: the hovered frame pixel in every other screen-space view; what the technique
        // can map of it in algorithm-space views (the epipolar row in minmax's rectified map, ...).
        std::optional<glm::ivec2> readAt;
        if (v.pane.texture != 0 && id == mHoveredView && v.image.contains(mHover))
            readAt = texelAt(v.pane, v.image, v.transform, mHover);
        if (mLinkedPixel && isScreenSpace(v)) {
            // The hovered view marks its own pixel too (the cross leaves the pixel's centre free), so
            // that screenshots and a projector show which pixel the others follow.
            if (id != mHoveredView) readAt = *mLinkedPixel;
            const glm::dvec2 uv = (glm::dvec2(*mLinkedPixel) + 0.5) / glm::dvec2(v.pane.size);
            crosshair(dl, v.image.min + glm::vec2(v.transform.uvToPane(uv)) * v.image.size(), v.image);
        }
        if (mLinkedPixel && !isScreenSpace(v) && v.pane.texture != 0) drawMarkers(dl, v, markersFor(v));
        markProbe(dl, v);
        drawGizmo(dl, id, v);

        // The value under the cursor (or at the linked pixel), from the view's CPU copy.
        const glm::vec2 readoutAt{v.image.min.x, v.image.max.y + 3.0f * s};
        if (readAt) {
            glm::vec4 value(0.0f);
            if (!valueAt(v, *readAt, value)) {
                const int glRow = v.pane.flipY ? v.pane.size.y - 1 - readAt->y : readAt->y;
                glGetTextureSubImage(v.pane.texture, 0, readAt->x, glRow, 0, 1, 1, 1, GL_RGBA, GL_FLOAT, sizeof value,
                                     &value);
            }
            std::string text = (id == mHoveredView ? "pixel (" : "linked (") + std::to_string(readAt->x) + ", " +
                               std::to_string(readAt->y) + ")  =";
            for (int c = 0; c < std::clamp(v.pane.channels, 1, 3); ++c) text += format("  %.4g", value[c]);
            dl.textClipped(readoutAt, text, kText, v.cell.max.x);
        }
        drawStatusBands(dl, v.image);
        if (v.display.stripOpen && v.strip.size().y > 0.0f) drawStrip(id, v);
    }

    void drawPlots(const ViewState& v) {
        const float gap = 4.0f * mScale;
        const int n = int(v.pane.plots.size());
        const float h = (v.image.size().y - gap * float(n - 1)) / float(n);
        for (int i = 0; i < n; ++i) {
            const float top = v.image.min.y + float(i) * (h + gap);
            viz::plot::drawPlot(*mDrawList, {{v.image.min.x, top}, {v.image.max.x, top + h}},
                                plotSpecOf(v.pane.plots[std::size_t(i)]));
        }
    }

    // The technique's marks for the linked pixel, asked once per pixel and run (a GPU technique may
    // read a texel back for them).
    std::vector<viz::ViewMarker> markersFor(const ViewState& v) {
        if (!mLinkedPixel || !mHaveOutput) return {};
        auto& cached = mMarkerCache[v.pane.id];
        if (cached.first == *mLinkedPixel && cached.second) return *cached.second;
        try {
            cached = {*mLinkedPixel, technique().markersFor(*mLinkedPixel, v.pane.id)};
            return *cached.second;
        } catch (const std::exception& e) {
            mError = e.what();
            return {};
        }
    }

    // A small cross with a dark outline, so that it shows on bright and dark images alike.
    void crosshair(DrawList& dl, glm::vec2 c, const Rect& clip) {
        if (!clip.contains(c)) return;
        const float r = 7.0f * mScale, w = 1.5f * mScale;
        for (int pass = 0; pass < 2; ++pass) {
            const float width = pass == 0 ? w + 2.0f * mScale : w;
            const glm::vec4 colour = pass == 0 ? glm::vec4(0.0f, 0.0f, 0.0f, 0.8f) : glm::vec4(0.2f, 1.0f, 1.0f, 1.0f);
            dl.line({c.x - r, c.y}, {c.x - 2.0f * mScale, c.y}, width, colour);
            dl.line({c.x + 2.0f * mScale, c.y}, {c.x + r, c.y}, width, colour);
            dl.line({c.x, c.y - r}, {c.x, c.y - 2.0f * mScale}, width, colour);
            dl.line({c.x, c.y + 2.0f * mScale}, {c.x, c.y + r}, width, colour);
        }
    }

    // Technique markers: data uv (row 0 = the first row stored; a GL texture's row 0, shown at the bottom,
    // also when the pane shows a layer read back) -> the view's image uv -> window. Marks of another layer
    // (cube face, array layer) than the one shown are left out.
    void drawMarkers(DrawList& dl, const ViewState& v, const std::vector<viz::ViewMarker>& marks) {
        const auto toWindow = [&](glm::vec2 data) {
            const glm::dvec2 uv{data.x, v.pane.glRows ? 1.0 - double(data.y) : double(data.y)};
            return v.image.min + glm::vec2(v.transform.uvToPane(uv)) * v.image.size();
        };
        dl.pushClip(v.image);
        std::vector<Rect> placed;  // labels drawn so far
        glm::vec4 colour(0.0f);
        float width = 1.0f;
        const float line = mFont->lineHeight();
        const auto shown = [&](const viz::ViewMarker& m) { return m.layer < 0 || m.layer == v.pane.layer; };
        // Several labelled points (a ray's crossings lie close together): each gets a number beside it and
        // its label goes into a key at the image's bottom left, so that labels do not pile up.
        const auto points = std::count_if(marks.begin(), marks.end(), [&](const viz::ViewMarker& m) {
            return shown(m) && m.from == m.to && !m.label.empty();
        });
        std::vector<std::string> key;
        for (std::size_t i = 0; i < marks.size(); ++i) {
            if (!shown(marks[i])) continue;
            const glm::vec2 a = toWindow(marks[i].from), b = toWindow(marks[i].to);
            // The first mark thin cyan, the others yellow; an unlabelled one continues the previous (a
            // polyline).
            if (i == 0 || !marks[i].label.empty()) {
                colour = i == 0 ? glm::vec4(0.2f, 1.0f, 1.0f, 0.9f) : glm::vec4(1.0f, 0.85f, 0.2f, 1.0f);
                width = i == 0 ? 1.0f : 2.0f;
            }
            if (a == b) {
                crosshair(dl, a, v.image);
            } else {
                dl.line(a, b, 3.0f * mScale, {0.0f, 0.0f, 0.0f, 0.6f});
                dl.line(a, b, width * mScale, colour);
            }
            const glm::vec2 at{std::max(std::min(a.x, b.x), v.image.min.x) + 4.0f * mScale,
                               std::min(a.y, b.y) - line - 2.0f * mScale};
            if (marks[i].label.empty()) continue;  // a piece of a polyline labelled once
            if (a == b && points > 2) {
                const std::string tag = std::to_string(key.size() + 1);
                const glm::vec2 tagAt = a + glm::vec2(5.0f, -line - 1.0f) * glm::vec2(mScale, 1.0f);
                dl.rect({tagAt - 1.0f, tagAt + glm::vec2(mFont->measure(tag) + 2.0f, line)}, {0.0f, 0.0f, 0.0f, 0.6f});
                dl.textClipped(tagAt, tag, colour, v.image.max.x);
                key.push_back(tag + "  " + marks[i].label);
                continue;
            }
            // A label that would run past the image's right edge moves left to end there; one that would
            // cover a label already placed moves down a line (marks close together, e.g. a ray's crossings).
            const float labelWidth = mFont->measure(marks[i].label);
            const float labelX = i == 0 ? at.x : std::max(a.x, b.x) + 4.0f * mScale;
            glm::vec2 labelAt{std::max(v.image.min.x, std::min(labelX, v.image.max.x - labelWidth - 2.0f)),
                              std::clamp(i == 0 ? at.y : std::max(a.y, b.y) + 2.0f * mScale, v.image.min.y,
                                         v.image.max.y - line)};
            const auto overlaps = [&](const Rect& r) {
                return labelAt.x < r.max.x && labelAt.x + labelWidth > r.min.x && labelAt.y < r.max.y &&
                       labelAt.y + line > r.min.y;
            };
            for (int tries = 0; tries < 8 && std::any_of(placed.begin(), placed.end(), overlaps); ++tries)
                labelAt.y += line + 1.0f;
            placed.push_back({labelAt, labelAt + glm::vec2(labelWidth, line)});
            dl.rect({labelAt - 1.0f, labelAt + glm::vec2(labelWidth + 2.0f, line)}, {0.0f, 0.0f, 0.0f, 0.6f});
            dl.textClipped(labelAt, marks[i].label, colour, v.image.max.x);
        }
        if (!key.empty()) {
            float keyWidth = 0.0f;
            for (const std::string& k : key) keyWidth = std::max(keyWidth, mFont->measure(k));
            const float pad = 3.0f * mScale;
            const glm::vec2 origin{v.image.min.x + pad, v.image.max.y - pad - float(key.size()) * line};
            dl.rect({origin - pad, origin + glm::vec2(keyWidth + pad, float(key.size()) * line + pad)},
                    {0.0f, 0.0f, 0.0f, 0.7f});
            for (std::size_t k = 0; k < key.size(); ++k)
                dl.textClipped(origin + glm::vec2(0.0f, float(k) * line), key[k], {1.0f, 0.85f, 0.2f, 1.0f}, v.image.max.x);
        }
        dl.popClip();
    }

    // "rendering..." while a slow GPU run blocks, the CPU worker's progress while it computes.
    void drawStatusBands(DrawList& dl, const Rect& image) {
        const float line = mFont->lineHeight();
        if (mRendering) {
            const std::string text = mHaveOutput ? "rendering... (last run " + format("%.1f s)", mLastRunSeconds)
                                                 : std::string("rendering...");
            const Rect band{{image.min.x, image.max.y - line - 10.0f * mScale}, image.max};
            dl.rect(band, {0.0f, 0.0f, 0.0f, 0.65f});
            dl.textClipped({band.min.x + 6.0f * mScale, band.min.y + 3.0f * mScale}, text, kText, band.max.x);
        }
        const CpuProgress progress = mWorker->progress();
        if (progress.busy && !technique().needsGl()) {
            // Progress of the running pass, estimated from the previous pass's time per pixel.
            std::string text = "computing... pass " + std::to_string(progress.pass) + "/" + std::to_string(progress.passCount) +
                               " (" + std::to_string(progress.size.x) + "x" + std::to_string(progress.size.y) + ")  " +
                               format("%.1f s", progress.elapsed);
            float fraction = -1.0f;
            // An estimate the pass has clearly outrun (the previous pass came from the cache, say)
            // is dropped rather than shown as a full bar.
            if (progress.estimate > 0.0 && progress.elapsed < 1.5 * progress.estimate) {
                fraction = float(std::min(0.99, progress.elapsed / progress.estimate));
                text += format(" of ~%.1f s", progress.estimate);
            }
            const Rect band{{image.min.x, image.max.y - line - 10.0f * mScale}, image.max};
            dl.rect(band, {0.0f, 0.0f, 0.0f, 0.65f});
            if (fraction >= 0.0f) {
                dl.rect({{band.min.x, band.max.y - 3.0f * mScale}, {band.min.x + fraction * band.size().x, band.max.y}}, kAccent);
            }
            dl.textClipped({band.min.x + 6.0f * mScale, band.min.y + 3.0f * mScale}, text, kText, band.max.x);
        }
    }

    // The display strip: channel, range (auto or manual), log scale, colour map, negative overlay and
    // difference mode as widgets on the left; the histogram of the shown values on the right.
    void drawStrip(int id, ViewState& v) {
        const float s = mScale;
        const Rect& strip = v.strip;
        Rect widgets = strip, plot = strip;
        if (strip.size().x >= kStripSideBySide * s) {
            const float split = strip.min.x + std::max(0.5f * strip.size().x, std::min(0.62f * strip.size().x, 360.0f * s));
            widgets.max.x = split - 2.0f * s;
            plot.min.x = split + 2.0f * s;
        } else {
            const float h = std::min(kHistogramHeight * s, 0.45f * strip.size().y);
            widgets.max.y = strip.max.y - h - 2.0f * s;
            plot.min.y = strip.max.y - h;
        }
        mStripRects.push_back(widgets);
        const std::string tag = "##v" + std::to_string(id);
        DisplaySettings& d = v.display;
        const DisplaySettings before = d;
        mUi->beginPanel(tag, widgets);
        int channel = int(d.channel), range = int(d.range), map = int(d.colourMap), difference = int(d.difference);
        if (mUi->combo("channel" + tag, channel, channelNames())) d.channel = Channel(channel);
        if (mUi->combo("range" + tag, range, rangeModeNames())) {
            if (RangeMode(range) == RangeMode::Manual) {
                // Manual starts from what is shown now.
                const DisplayMapping m = resolveMapping(v.pane, d, mExposure, v.measured);
                d.manualMin = m.lo;
                d.manualMax = m.hi;
            }
            d.range = RangeMode(range);
        }
        if (d.range == RangeMode::Manual) {
            const float span = v.finite.valid ? std::max(v.finite.hi - v.finite.lo, 1e-6f) : 1.0f;
            mUi->dragFloat("min" + tag, d.manualMin, 0.004f * span, -1e30f, 1e30f);
            mUi->dragFloat("max" + tag, d.manualMax, 0.004f * span, -1e30f, 1e30f);
        }
        mUi->checkbox("log scale" + tag, d.logScale);
        if (mUi->combo("colour map" + tag, map, colourMapNames())) d.colourMap = ColourMap(map);
        bool negative = resolveMapping(v.pane, d, mExposure, v.measured).markNegative;
        if (mUi->checkbox("mark negative (green)" + tag, negative)) d.markNegative = negative ? 1 : 0;
        mUi->tooltip("NaN shows magenta and Inf cyan always; negative values green unless the map is diverging");
        const bool frameImage = v.content == "final" || v.content == "airlight";
        if (frameImage && mUi->combo("difference" + tag, difference, differenceModeNames()))
            d.difference = DifferenceMode(difference);
        if (frameImage && d.difference != DifferenceMode::Off) {
            int against = int(std::find(mIds.begin(), mIds.end(), d.against) - mIds.begin());
            if (against >= int(mIds.size())) against = 0;
            if (mUi->combo("against" + tag, against, mIds)) d.against = mIds[std::size_t(against)];
        }
        mUi->endPanel();
        if (d.difference != before.difference || d.against != before.against) {
            refreshView(v);
        } else if (d.channel != before.channel || d.range != before.range || d.logScale != before.logScale) {
            updateStatistics(v);
        }
        drawHistogram(v, plot);
    }

    // Counts of the shown channel's finite values over their range, with the display range marked.
    void drawHistogram(const ViewState& v, const Rect& area) {
        if (area.size().x < 80.0f * mScale || area.size().y < 4.0f * mFont->lineHeight()) return;
        const Histogram& h = v.histogram;
        viz::plot::PlotSpec spec;
        spec.title = "histogram, " + channelNames()[std::size_t(v.display.channel)] +
                     (v.values.empty() ? " (no values)" : ", % of values per bin");
        spec.logX = h.logarithmic;
        const auto edge = [&](std::size_t i) {
            const double t = double(i) / double(std::max<std::size_t>(1, h.bins.size()));
            return h.logarithmic ? std::pow(10.0, std::log10(h.lo) + t * (std::log10(h.hi) - std::log10(h.lo)))
                                 : h.lo + t * (double(h.hi) - double(h.lo));
        };
        viz::plot::Series counts{"", {0.85f, 0.45f, 0.05f, 1.0f}, {}, true, false};
        std::size_t total = h.below + h.above;
        for (std::size_t c : h.bins) total += c;
        const double percent = 100.0 / double(std::max<std::size_t>(total, 1));
        double top = 1.0;
        for (std::size_t i = 0; i < h.bins.size(); ++i) {
            counts.points.push_back({edge(i), double(h.bins[i]) * percent});
            counts.points.push_back({edge(i + 1), double(h.bins[i]) * percent});
            top = std::max(top, double(h.bins[i]) * percent);
        }
        spec.series.push_back(std::move(counts));
        const DisplayMapping m = resolveMapping(v.pane, v.display, mExposure, v.measured);
        if (m.mode != DisplayMode::HdrColor && !h.bins.empty()) {
            viz::plot::Series shown{"range", {0.3f, 0.85f, 1.0f, 1.0f}, {}, true, false};
            for (double x : {double(m.lo), double(m.hi)}) {
                if (x < h.lo || x > h.hi) continue;  // outside the data: the axis would stretch to it
                viz::plot::Series mark{"", shown.color, {{x, 0.0}, {x, top}}, true, false};
                spec.series.push_back(std::move(mark));
            }
        }
        viz::plot::drawPlot(*mDrawList, area, spec);
    }

    // What the sidecar says of a view (tests assert on it).
    nlohmann::json viewSidecar(int id, const ViewState& v) {
        const DisplaySettings& d = v.display;
        const DisplayMapping m = resolveMapping(v.pane, d, mExposure, v.measured);
        nlohmann::json j = {{"cell", id},
                            {"content", v.content},
                            {"cell_rect", {v.cell.min.x, v.cell.min.y, v.cell.max.x, v.cell.max.y}},
                            {"focused", id == mFocused},
                            {"layer", v.pane.layer},
                            {"zoom", v.transform.zoom},
                            {"center", {v.transform.center.x, v.transform.center.y}},
                            {"size", {v.pane.size.x, v.pane.size.y}},
                            {"screen_space", isScreenSpace(v)},
                            {"display", {{"channel", channelNames()[std::size_t(d.channel)]},
                                         {"range", rangeModeNames()[std::size_t(d.range)]},
                                         {"lo", m.lo}, {"hi", m.hi}, {"log", d.logScale},
                                         {"colour_map", colourMapNames()[std::size_t(d.colourMap)]},
                                         {"mode", int(m.mode)}, {"mark_negative", m.markNegative},
                                         {"strip_open", d.stripOpen}}},
                            {"negative_pixels", v.counts.negative},
                            {"nan_pixels", v.counts.nan},
                            {"inf_pixels", v.counts.inf}};
        if (d.difference != DifferenceMode::Off) {
            const auto figure = [](double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); };
            j["difference"] = {{"mode", differenceModeNames()[std::size_t(d.difference)]},
                               {"against", d.against},
                               {"relative_l2", v.error ? figure(v.error->relativeL2) : nlohmann::json(nullptr)},
                               {"max_abs", v.error ? figure(v.error->maxAbsolute) : nlohmann::json(nullptr)},
                               {"note", v.differenceNote}};
        }
        // The linked cursor as this view marks it: the pixel itself in screen-space views.
        std::optional<glm::ivec2> at;
        if (mLinkedPixel && isScreenSpace(v)) at = *mLinkedPixel;
        if (at) {
            glm::vec4 value(0.0f);
            j["cursor"] = {at->x, at->y};
            if (valueAt(v, *at, value)) {
                nlohmann::json values = nlohmann::json::array();
                for (int c = 0; c < std::clamp(v.meaningful, 1, 4); ++c)
                    values.push_back(std::isfinite(value[c]) ? nlohmann::json(value[c]) : nlohmann::json(nullptr));
                j["cursor_value"] = values;
            }
        } else {
            j["cursor"] = nullptr;
        }
        if (mLinkedPixel && !isScreenSpace(v) && v.pane.texture != 0) {
            nlohmann::json marks = nlohmann::json::array();
            for (const viz::ViewMarker& mk : markersFor(v))
                marks.push_back({{"from", {mk.from.x, mk.from.y}}, {"to", {mk.to.x, mk.to.y}}, {"label", mk.label},
                                 {"layer", mk.layer}});
            j["markers"] = marks;
        }
        return j;
    }

    void draw() {
        const glm::ivec2 fb = mWindow.framebufferSize();
        if (fb.x <= 0 || fb.y <= 0) return;
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, fb.x, fb.y);
        glDisable(GL_FRAMEBUFFER_SRGB);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_SCISSOR_TEST);
        glDisable(GL_BLEND);
        glDisable(GL_CULL_FACE);
        glClearColor(kBackground.r, kBackground.g, kBackground.b, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        const auto frameStart = Clock::now();

        DrawList& dl = *mDrawList;
        dl.clear();
        mBackground->clear();
        mHits.clear();
        mPaneDraws.clear();
        mViewRects.clear();
        mNamedRects.clear();
        const float s = mScale;
        const float pad = kPad * s;
        const float line = mFont->lineHeight();
        const viz::Technique& t = technique();

        // Status lines at the top.
        const CameraController::Mode mode = mController.mode();
        std::string head = "scene: " + mScene.name + "   technique: " + t.id() + " - " + t.description() +
                           "   render " + std::to_string(mOptions.width) + "x" + std::to_string(mOptions.height);
        if (mHaveOutput && mReduced) head += "   (interactive: " + std::to_string(mOutputSize.x) + "x" + std::to_string(mOutputSize.y) + ")";
        if (mHaveOutput && mPassCount > 1) {
            head += "   (showing pass " + std::to_string(mPass) + "/" + std::to_string(mPassCount) + ": " +
                    std::to_string(mOutputSize.x) + "x" + std::to_string(mOutputSize.y) + ")";
        }
        {
            const auto& stages = t.stages();
            const int shown = stageShown();
            head += "   stage " + std::to_string(shown + 1) + "/" + std::to_string(stages.size()) + " " +
                    stages[std::size_t(shown)].id;
            const auto [at, count] = substepState();
            if (count > 0) head += " sub-step " + std::to_string(at) + "/" + std::to_string(count);
            head += " (S, D, Home, End)";
            if (mHaveOutput && mOutput.firstStageRun > 0)
                head += "   re-ran from stage " + std::to_string(mOutput.firstStageRun + 1) + " (earlier ones kept)";
        }
        mBackground->rect({{0.0f, 0.0f}, {float(fb.x), 3.0f * line + 2.0f * pad}}, kPanel);
        dl.textClipped({pad, pad}, head, kText, float(fb.x) - pad);
        viz::Timing timing = mOutput.timing;
        if (timing.clock.empty()) timing.clock = t.needsGl() ? mClockName : "steady_clock";
        dl.textClipped({pad, pad + line}, mHaveOutput ? timingLine(timing) : "timings: (no run yet)", kDim, float(fb.x) - pad);
        std::string third = skippedLine(mHaveOutput ? mOutput.plan : mPlan);
        glm::vec4 thirdColor = kDim;
        if (!mError.empty() || !mSettingsError.empty()) {
            third = "error: " + firstLine(mError.empty() ? mSettingsError + " (using defaults)" : mError);
            thirdColor = kError;
        } else if (!mNotice.empty()) {
            third = mNotice + "   |   " + third;
        } else if (mHaveOutput && !mOutput.notes.empty()) {
            third = "note: " + mOutput.notes.front() + "   |   " + third;
            thirdColor = kAccent;
        }
        dl.textClipped({pad, pad + 2.0f * line}, third, thirdColor, float(fb.x) - pad);
        const float top = 3.0f * line + 3.0f * pad;

        // Help line at the bottom.
        const std::string help = mode == CameraController::Mode::Orbit
            ? "camera: ORBIT (target " + format("%.2f", mController.targetDistance()) + ")   Tab/Shift+Tab or 1-9 technique   S/Shift+S stage   D/Shift+D sub-step   Home/End   [ ] view   , . layer   +/- exposure (X auto)   C fly   R reset   P play/pause   "
              "left drag orbit, wheel zoom, right/middle drag pan   Esc quit"
            : "camera: FLY   Tab/Shift+Tab or 1-9 technique   [ ] view   , . layer   +/- exposure (X auto)   C orbit   R reset   P play/pause   "
              "right drag look, WASD move, Q/E down/up, Shift faster, middle drag pan   Esc quit";
        const float bottom = float(fb.y) - 2.0f * line - pad;
        dl.textClipped({pad, bottom}, help, kDim, float(fb.x) - pad);
        dl.textClipped({pad, bottom + line},
                       "views: click to focus   H / J split   drag a gap: resize   K close   M maximise   O swap (or drag a "
                       "title)   N next   F difference   0 fit   L light gizmo   'display +': controls",
                       kDim, float(fb.x) - pad);

        // Sidebar: techniques, then views.
        float sidebarWidth = kSidebarMin * s;
        for (const std::string& id : mIds) sidebarWidth = std::max(sidebarWidth, mFont->measure(id) + 4.0f * pad);
        const Rect sidebar{{0.0f, top - pad}, {sidebarWidth, bottom - pad}};
        mBackground->rect(sidebar, kPanel);
        float y = top;
        dl.text({pad, y}, "Techniques (Tab)", kAccent);
        y += line + 2.0f * s;
        for (int i = 0; i < int(mIds.size()); ++i) {
            const std::string name = (i < 9 ? std::to_string(i + 1) + "  " : "   ") + mIds[std::size_t(i)];
            const Rect item{{pad * 0.5f, y}, {sidebarWidth - pad * 0.5f, y + line + 2.0f * s}};
            listItem(item, name, i == mCurrent, [this, i] { selectTechnique(i); });
            mNamedRects["technique:" + mIds[std::size_t(i)]] = item;
            y += line + 4.0f * s;
        }
        y += line;
        dl.text({pad, y}, "Views ([ ])", kAccent);
        y += line + 2.0f * s;
        if (mHaveOutput) {
            // Clicking an entry shows it in the focused view.
            const int shown = focusedView().shown;
            for (int i = 0; i < contentCount() && y + line < sidebar.max.y; ++i) {
                const std::string name = contentLabel(i);
                const Rect item{{pad * 0.5f, y}, {sidebarWidth - pad * 0.5f, y + line + 2.0f * s}};
                listItem(item, name, i == shown, [this, i] { selectView(i); });
                mNamedRects["view:" + name] = item;
                y += line + 4.0f * s;
            }
        }

        // The view grid on top; under it the ray inspector or the stage times (left) and the widgets (right);
        // the lesson panel (if a lesson is open) at the right edge.
        const float lessonWidth = mLesson ? LessonPlayer::panelWidth(float(fb.x), s) : 0.0f;
        if (mLesson) mLesson->place({{float(fb.x) - lessonWidth, top - pad}, {float(fb.x), bottom - pad}});
        const Rect panes{{sidebarWidth + pad, top}, {float(fb.x) - pad - lessonWidth, bottom - pad}};
        mViewArea = panes;
        const float half = 0.5f * (panes.size().x - pad);
        // As tall as two frame-shaped views side by side need, leaving room for the panels below.
        const float chrome = 3.0f * line + 10.0f * s;
        const float aspect = float(mOptions.height) / float(std::max(1, mOptions.width));
        float gridHeight = std::clamp(half * aspect + chrome, 0.5f * panes.size().y, 0.74f * panes.size().y);
        // The ray inspector's plot needs height: the grid gives some up while it is open.
        if (mProbe) gridHeight = std::min(gridHeight, 0.56f * panes.size().y);
        // The stepping timeline sits between the grid and the panels.
        const float timelineHeight = line + 8.0f * s;
        const Rect gridArea{panes.min, {panes.max.x, panes.min.y + gridHeight}};
        mViewArea = gridArea;
        mTimelineRect = {{panes.min.x, gridArea.max.y + 0.5f * pad}, {panes.max.x, gridArea.max.y + 0.5f * pad + timelineHeight}};
        beginWidgets(fb);
        {
            // CPU cost of the view grid (layout, titles, readouts, markers, strips), for the sidecar.
            const auto start = Clock::now();
            drawViewGrid(gridArea);
            mGridMilliseconds = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        }
        drawStepTimeline();
        const Rect left{{panes.min.x, mTimelineRect.max.y + pad}, {panes.min.x + half, panes.max.y}};
        const Rect right{{panes.max.x - half, mTimelineRect.max.y + pad}, panes.max};
        if (mProbe) {
            if (left.size().y > 6.0f * line) drawInspector(dl, left);
        } else if (mHaveOutput && !mOutput.timing.stages.empty()) {
            // Per-stage timings of the last run as bars, with the clock that measured them.
            viz::plot::BarChart chart;
            chart.title = "stage times (" + timing.clock + "), total " + format("%.1f ms", timing.totalMilliseconds());
            for (const viz::StageTiming& st : mOutput.timing.stages)
                chart.bars.push_back({st.stage, st.milliseconds, format("%.1f ms", st.milliseconds), kAccent});
            if (left.size().y > 2.0f * line) viz::plot::drawBarChart(dl, left, chart, kDim);
        }
        mParamsRect = right;
        if (mParamsRect.size().y < 4.0f * line) mParamsRect = {};
        drawParameters(fb);

        mUiMilliseconds = std::chrono::duration<double, std::milli>(Clock::now() - frameStart).count();
        // Panels, then the images, then the text batch over them.
        mTextRenderer->draw(*mBackground, fb);
        for (const PaneDraw& d : mPaneDraws)
            mImageDisplay->draw(*d.pane, d.rect, fb, d.mapping, d.view ? *d.view : viz::ui::ImageViewTransform{});
        mTextRenderer->draw(dl, fb);
        mTextRenderer->draw(mUi->drawList(), fb);
    }

    // ---- scene and technique controls (immediate-mode widgets) ----

    // Medium and light sliders and the technique's parameters, generated from its declarations.
    // The widgets' frame starts before the view grid (its display strips) and ends after this panel.
    void beginWidgets(glm::ivec2 fb) {
        viz::ui::Input in = mUiInput;
        in.mouse = mHover;
        mHoverDrawn = mHover;
        in.mouseDown = mSyntheticDown ? *mSyntheticDown
                                      : glfwGetMouseButton(mWindow.handle(), GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
        mUiInput = {};
        mUi->setTime(glfwGetTime());
        mUi->beginFrame(in, glm::vec2(fb), mScale);
    }

    void drawParameters(glm::ivec2 fb) {
        (void)fb;
        if (mParamsRect.size().y > 0.0f) {
            mUi->beginPanel("Scene and parameters", mParamsRect);
            scenePicker();
            bool sceneChanged = false;
            if (mUi->collapsingHeader("Medium", true)) {
                // Values change only when a widget reports a change, so the scene keeps its exact doubles.
                float sigmaS = float(mScene.medium.sigma_s), sigmaA = float(mScene.medium.sigma_a), g = float(mScene.medium.g);
                if (mUi->sliderFloat("sigma_s (scattering)", sigmaS, 1e-4f, 10.0f, true))
                    mScene.medium.sigma_s = sigmaS, sceneChanged = true;
                if (mUi->dragFloat("sigma_a (absorption)", sigmaA, 0.001f, 0.0f, 50.0f))
                    mScene.medium.sigma_a = sigmaA, sceneChanged = true;
                if (mUi->sliderFloat("g (Henyey-Greenstein)", g, -0.99f, 0.99f)) mScene.medium.g = g, sceneChanged = true;
                mUi->tooltip("phase function asymmetry: > 0 scatters forward, < 0 back");
            }
            if (!mScene.lights.empty() && mUi->collapsingHeader("Light: " + mScene.lights[0].name, true)) {
                // The slider's range is declared, never derived from the light (a light of intensity 0, or
                // one from a millimetre model, once gave an empty or inverted range): a log scale over the
                // intensities scenes use, and "on" for the light switched off (0).
                double& value = mScene.lights[0].intensity;
                bool on = value > 0.0;
                if (mUi->checkbox("on", on)) {
                    if (on) value = mLightIntensityOff > 0.0 ? mLightIntensityOff : 1.0;
                    else mLightIntensityOff = value, value = 0.0;
                    sceneChanged = true;
                }
                if (on) {
                    float intensity = float(value);
                    if (mUi->sliderFloat("intensity", intensity, kIntensitySliderMin, kIntensitySliderMax, true)) {
                        value = intensity;
                        sceneChanged = true;
                    }
                }
            }
            // Folded by default: the technique's parameters stay in view on small windows.
            if (!mScene.lights.empty() && mUi->collapsingHeader("Light placement", false)) {
                sceneChanged = lightPlacementWidgets(mScene.lights[0]) || sceneChanged;
            }
            if (mUi->collapsingHeader(technique().id() + " parameters", true)) parameterWidgets();
            mUi->endPanel();
            if (sceneChanged) sceneEdited();
        }
        if (mLesson) mLesson->draw(*mUi, *mDrawList, *mBackground, mScale);
        mUi->endFrame();
    }

    // The preset picker: "ours" (the defaults) or "paper" (the technique's paperSettings(), as --preset
    // paper) for the parameters where the two differ; "(mixed)" when those parameters are neither.
    void presetWidget(const std::string& id) {
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

    // The scene pickers: the built-in scenes (and the file given on the command line, if any) in one
    // list, the stiff cases of `airlight report --suite stiff` in another (one long list would not fit
    // the window). Picking one loads it with its own camera, medium and lights; a scene that fails to
    // load leaves the current one and shows the error.
    void scenePicker() {
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
        if (picked.empty() || picked == mOptions.scene) return;
        try {
            loadLessonScene(picked);
            replan();
        } catch (const std::exception& e) {
            mError = e.what();
        }
    }

    // Where the light points and where it is: azimuth and elevation of the direction for spot and
    // directional lights, position for point and spot lights (an area light's rectangle is scene
    // geometry and stays put). Returns whether the light changed.
    bool lightPlacementWidgets(viz::scene::Light& light) {
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

    void parameterWidgets() {
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

    void replan() {
        try {
            mPlan = technique().plan(mScene, mSettings);
        } catch (const std::exception& e) {
            mError = e.what();
        }
        mDirty = true;
    }

    GuiOptions mOptions;
    long mGlErrors = 0;  // GL errors seen by the script's stats actions
    int mScriptRevealFrames = 0;
    bool mPlaying = false;                        // P: the animation runs
    double mPlayClock = 0.0, mPlayTurn = 0.0;     // seconds played; the light's turn (0..1)
    std::optional<viz::scene::Light> mPlayLight;  // the first light as it was when play started
    glm::dvec3 mPlayCentre{0.0};  // frames left until a script action's widget is scrolled into view
    std::vector<std::string> mSceneChoices, mStiffChoices;  // the scene pickers' lists (built lazily)
    SessionState mSession;  // as loaded (or defaults); settings of techniques not yet visited come from it
    std::string mNotice;    // last session message, shown in the status line
    viz::scene::Scene mScene;  // the camera follows the controller
    viz::Window& mWindow;
    CameraController mController;
    double mGizmoArm = 1.0;  // scene units (kGizmoArm of the scene camera's orbit distance)
    std::vector<std::string> mIds;
    // Instances for the other consumers (difference views, the comparison grid), apart from mRunners.
    std::map<std::string, std::unique_ptr<viz::Technique>> mTechniques;
    int mCurrent = 0;
    viz::Settings mSettings;
    viz::Plan mPlan;
    std::string mSettingsError, mError, mClockName;

    std::unique_ptr<viz::ui::FontAtlas> mFont;
    std::unique_ptr<viz::ui::TextRenderer> mTextRenderer;
    std::unique_ptr<DrawList> mDrawList;    // text and overlays, drawn last in one call
    std::unique_ptr<DrawList> mBackground;  // panels behind the images
    std::unique_ptr<ImageDisplay> mImageDisplay;
    std::unique_ptr<CpuWorker> mWorker;
    float mScale = 1.0f;

    viz::FrameOutput mOutput;
    bool mHaveOutput = false;
    glm::ivec2 mOutputSize{0};
    int mPass = 0, mPassCount = 1;
    // ---- the view grid ----
    ViewLayout mLayout{0};
    std::map<int, ViewState> mViews;  // by the layout's view number
    int mFocused = 1;                 // keys, the views list and exports act on it
    int mNextView = 2;
    std::vector<ViewCellRect> mCells;        // where the last frame put each view
    std::optional<glm::ivec2> mLinkedPixel;  // frame pixel under the cursor (a screen-space view)
    int mHoveredView = -1;
    int mDragTitle = -1;                     // a title dragged onto another view swaps the two
    std::vector<Rect> mStripRects;           // open display strips' widget panels last frame
    std::map<std::string, OtherRun> mOtherRuns;  // difference views' other side, by technique id
    OtherRun mSelfRun;
    std::unique_ptr<CpuWorker> mOtherWorker;  // CPU techniques on the other side of difference views
    bool mGpuOthersDue = false;               // GPU techniques queued for difference views (next frame)
    std::string mOtherSceneKey;
    double mGridMilliseconds = 0.0;  // CPU time drawViewGrid took last frame
    double mUiMilliseconds = 0.0;    // CPU time of building the whole frame's UI (before its draw calls)
    glm::vec2 mHoverDrawn{-1.0f};    // the mouse position the widgets saw last frame
    // markersFor answers by intermediate id, for one pixel of the current run.
    std::map<std::string, std::pair<glm::ivec2, std::optional<std::vector<viz::ViewMarker>>>> mMarkerCache;
    float mExposure = 0.0f;
    bool mExposureSet = false;
    bool mDirty = true;
    bool mRendering = false;  // a GPU run is about to block the thread
    double mLastRunSeconds = 0.0;
    bool mReduced = false;  // the last GPU run was at half size during an interaction

    std::vector<std::pair<Rect, std::function<void()>>> mHits;  // clickable rectangles of the last frame
    struct PaneDraw {
        Rect rect;
        const PaneImage* pane;
        const viz::ui::ImageViewTransform* view;  // nullptr: the whole image
        DisplayMapping mapping;
    };
    ComparisonGrid mComparison;  // G
    std::vector<PaneDraw> mPaneDraws;
    std::unique_ptr<viz::ui::Context> mUi;   // the widgets
    viz::ui::Input mUiInput;                 // keys, text and wheel gathered since the last frame
    Rect mParamsRect;                        // the widget panel's area last frame
    std::optional<viz::reference::RayProbe> mProbe;  // the ray inspector's pixel, if any
    std::optional<glm::ivec2> mPendingInspect;  // a lesson step's pixel, inspected when its result is in
    std::unique_ptr<LessonPlayer> mLesson;      // the lesson panel, when a lesson is open
    glm::ivec2 mLessonSize{0};                  // --size given with a lesson: every step at that size
    StepCursor mCursor;                      // stepping: where the main views' run stops (not a setting)
    // The main views' technique instances, one per technique, each with its last run's key.
    std::map<std::string, std::unique_ptr<StageRunner>> mRunners;
    std::vector<TimelineSegment> mTimeline;  // the stepping timeline as drawn last
    Rect mTimelineRect;
    bool mDragTimeline = false;
    std::string mProbeTechnique;
    bool mProbeHasValue = false;
    glm::dvec3 mProbeValue{0.0};
    // The light panel's intensity slider: a declared log range (candela or lux) covering every scene's
    // lights, from millimetre models to the stiff cases; 0 is the "on" box unticked.
    static constexpr float kIntensitySliderMin = 1e-6f, kIntensitySliderMax = 1e12f;
    double mLightIntensityOff = 0.0;  // the intensity before "on" was unticked
    int mDragView = -1;                      // the view a drag pans
    int mDragOrbit = -1;                     // the orbit view a drag turns
    bool mShowGizmo = true;                   // L: the light gizmo over the frame views
    std::optional<GizmoDrag> mGizmoDrag;       // the light handle being dragged
    std::vector<Rect> mDividerRects;          // the grid's splitters last frame
    std::optional<SplitAxis> mCursorAxis;     // the resize cursor shown (none: the arrow)
    GLFWcursor* mArrowCursor = nullptr;       // stays null: the default cursor
    GLFWcursor* mColumnCursor = nullptr;      // created on first use, destroyed with the app
    GLFWcursor* mRowCursor = nullptr;
    std::optional<PixelInspection> mProbeInspection;  // cache of probeInspection()
    int mScriptDragStep = 0;                 // a script's drag: 0 before the press, 1-4 moving, 5 release
    glm::vec2 mScriptDragFrom{0.0f}, mScriptDragTo{0.0f};  // its ends, fixed at the press
    struct ViewRect {
        std::string name, title;
        Rect rect;      // the image's rectangle in window pixels
        int cell = -1;  // the grid's view number (-1: the comparison grid)
    };
    std::vector<ViewRect> mViewRects;  // what the last frame showed where (screenshot sidecar)
    // Sidebar items "technique:ID", "view:LABEL"; per grid view N: "cell:N" (image), "title:N", "strip:N"
    // (the display strip's toggle).
    std::map<std::string, Rect> mNamedRects;
    std::size_t mScriptIndex = 0;
    int mScriptWait = 0;
    std::optional<bool> mSyntheticDown;  // the script holds the left button (down / just released)
    glm::vec2 mScriptPoint{0.0f};
    int mFramesDrawn = 0;
    Rect mViewArea;
    float mImageHeight = 1.0f;
    glm::vec2 mHover{-1.0f};
    glm::vec2 mLastCursor{0.0f};
    int mDragButton = -1;
};

}  // namespace

int runGui(const GuiOptions& options) {
    if (options.width < 1 || options.height < 1) throw viz::InputError("render size must be at least 1x1");
    // The session: a broken file is reported and the defaults are used, never an error.
    SessionState session;
    std::string notice;
    GuiOptions effective = options;
    if (options.loadStateAtStart) {
        session = loadSession(options.statePath, notice);
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
    if (session.medium && effective.scene == session.scene) scene.medium = *session.medium;
    if (effective.scene == session.scene) applyLightPlacements(session.lights, scene);
    // Each --set must name a parameter of some technique (the window switches between them), and the
    // values must suit the technique the window opens with.
    std::vector<std::unique_ptr<viz::Technique>> all;
    for (const std::string& id : viz::techniqueIds()) all.push_back(viz::makeTechnique(id));
    for (const auto& [name, value] : options.settings) {
        bool known = false;
        for (const auto& t : all)
            for (const viz::ParamInfo& p : t->params()) known = known || p.name == name;
        if (!known) throw viz::InputError("no technique has a parameter '" + name + "'");
    }
    const std::unique_ptr<viz::Technique> first =
        viz::makeTechnique(options.technique.empty() ? viz::techniqueIds().front() : options.technique);
    viz::Settings mine;
    for (const auto& [name, value] : options.settings)
        for (const viz::ParamInfo& p : first->params())
            if (p.name == name) mine[name] = value;
    (void)viz::completeSettings(*first, mine);
    all.clear();
#ifdef NDEBUG
    constexpr bool kDebugContext = false;
#else
    constexpr bool kDebugContext = true;
#endif
    std::unique_ptr<viz::Window> window = viz::Window::create(1280, 720, "Airlight", kDebugContext);
    if (kDebugContext) viz::gl::installDebugOutput();
    int code = 0;
    {
        GuiApp app(effective, std::move(scene), *window, std::move(session), std::move(notice));
        code = app.run();
    }
    return code;
}

}  // namespace airlight
