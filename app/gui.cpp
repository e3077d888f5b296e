// The window: one GLFW window with the final frame (left pane) beside one chosen view (right pane, or
// the comparison grid), a clickable technique list, a view list, a status line with the stage shown,
// per-stage timings and the plan's skipped stages, the ray inspector or timing bars under the final
// frame, the scene and parameter panel (immediate-mode widgets) under the view, and an orbit/fly
// camera. GPU techniques run on the main thread whenever the camera, the settings or the technique
// change; CPU techniques (the reference) run on a worker thread in progressive passes (1/4, 1/2, then
// full resolution) so the window never freezes.
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
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "camera_controller.h"
#include "cpu_worker.h"
#include "lesson_player.h"
#include "pane_image.h"
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
#include "scene/scene_source.h"
#include "scene/stiff_scenes.h"
#include "scene/builtin_scenes.h"
#include "session_state.h"
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
constexpr float kSidebarMin = 170.0f;
constexpr float kExposureStep = 0.5f;  // stops per +/- key press
constexpr double kOrbitRadiansPerPixel = 0.008;
constexpr double kLookRadiansPerPixel = 0.004;
constexpr double kFlySpeed = 0.6;  // target distances per second

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

// Distance along the ray to the nearest triangle of the scene (Moller-Trumbore, brute force over every
// triangle: done once per reset, scenes here have a few thousand triangles), or -1 for a miss.
double firstHit(const viz::scene::Scene& scene, glm::dvec3 origin, glm::dvec3 dir) {
    double best = -1.0;
    for (const auto& mesh : scene.meshes) {
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            const glm::dvec3 a(mesh.positions[mesh.indices[i]]);
            const glm::dvec3 e1 = glm::dvec3(mesh.positions[mesh.indices[i + 1]]) - a;
            const glm::dvec3 e2 = glm::dvec3(mesh.positions[mesh.indices[i + 2]]) - a;
            const glm::dvec3 p = glm::cross(dir, e2);
            const double det = glm::dot(e1, p);
            if (std::abs(det) < 1e-12) continue;
            const glm::dvec3 s = origin - a;
            const double u = glm::dot(s, p) / det;
            if (u < 0.0 || u > 1.0) continue;
            const glm::dvec3 q = glm::cross(s, e1);
            const double v = glm::dot(dir, q) / det;
            if (v < 0.0 || u + v > 1.0) continue;
            const double t = glm::dot(e2, q) / det;
            if (t > 1e-6 && (best < 0.0 || t < best)) best = t;
        }
    }
    return best;
}

// Distance from the scene camera to the orbit target: the first surface on the view axis; failing
// that, where the axis passes closest to the centre of the scene's bounding box; failing that (the
// centre is behind the camera), the box's size.
double orbitDistance(const viz::scene::Scene& scene) {
    const glm::dvec3 forward = glm::normalize(scene.camera.forward);
    const double hit = firstHit(scene, scene.camera.position, forward);
    if (hit > 0.0 && hit < scene.camera.zfar) return hit;
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const auto& mesh : scene.meshes)
        for (const glm::vec3& p : mesh.positions) {
            lo = glm::min(lo, glm::dvec3(p));
            hi = glm::max(hi, glm::dvec3(p));
        }
    if (lo.x > hi.x) return 5.0;
    const glm::dvec3 centre = 0.5 * (lo + hi);
    const double radius = std::max(0.5 * glm::length(hi - lo), 1e-3);
    const double along = glm::dot(centre - scene.camera.position, forward);
    return along > 0.1 * radius ? along : radius;
}

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
        , mIds(viz::techniqueIds()) {
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
        // Panes may borrow the techniques' textures: drop them first.
        mFinal = {};
        mRight = {};
        mCompare.clear();
        mOutput = {};
        mTechniques.clear();
    }

    int run() {
        auto last = Clock::now();
        while (!mWindow.shouldClose()) {
            const bool flying = mController.mode() == CameraController::Mode::Fly && anyFlyKeyDown();
            const bool busy = mWorker->progress().busy;
            const bool automated = !mOptions.screenshot.empty() || !mOptions.script.empty();
            if (flying || mDirty || automated || (mLesson && mLesson->animating())) {
                glfwPollEvents();
            } else {
                // Nothing animates: sleep until input arrives, waking a few times a second while the
                // worker computes so that its progress stays current.
                glfwWaitEventsTimeout(busy ? 0.1 : 0.5);
            }
            const auto now = Clock::now();
            const double dt = std::min(0.1, std::chrono::duration<double>(now - last).count());
            last = now;
            if (mController.mode() == CameraController::Mode::Fly) fly(dt);
            // Automation advances animations by a fixed 1/30 s per frame, so runs repeat exactly.
            if (mLesson) mLesson->update(*this, automated ? 1.0 / 30.0 : dt);
            if (mReduced && mDragButton < 0 && !anyFlyKeyDown()) mDirty = true;
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
            draw();
            ++mFramesDrawn;
            if (!mOptions.script.empty()) {
                // Each frame runs the script's next actions; the window closes when it is done.
                if (mHaveOutput && !mWorker->progress().busy && !stepScript()) {
                    if (!mOptions.screenshot.empty()) writeScreenshot(mOptions.screenshot);
                    return 0;
                }
            } else if (automated && mFramesDrawn >= mOptions.frames && mHaveOutput && !mWorker->progress().busy) {
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
                case ScriptAction::Kind::Screenshot:
                    writeScreenshot(a.target);
                    ++mScriptIndex;
                    break;
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
        for (const auto& v : mViewRects)
            views.push_back({{"name", v.name}, {"title", v.title}, {"rect", {v.rect.min.x, v.rect.min.y, v.rect.max.x, v.rect.max.y}}});
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
        if (!mCompare.empty()) {
            nlohmann::json tiles = nlohmann::json::array();
            for (const auto& t : mCompare)
                tiles.push_back({{"technique", t.technique},
                                 {"milliseconds", t.milliseconds},
                                 {"relative_l2", std::isfinite(t.error.relativeL2) ? nlohmann::json(t.error.relativeL2)
                                                                                   : nlohmann::json(nullptr)},
                                 {"nan_inf_pixels", t.error.nanPixels + t.error.infPixels},
                                 {"failure", t.failure}});
            sidecar["comparison"] = tiles;
        }
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
                const glm::ivec2 frame{mOptions.width, mOptions.height};
                nlohmann::json readings = nlohmann::json::object();
                for (const PixelReading& r : readingsAtPixel(mOutput, frame, {mProbe->x, mProbe->y})) {
                    std::vector<double> values;
                    for (int c = 0; c < r.channels; ++c) values.push_back(r.value[c]);
                    readings[r.id] = values;
                }
                sidecar["inspector"]["readings"] = readings;
                sidecar["inspector"]["ray_views"] = pickedRayViews(technique(), mOutput, frame);
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
        // Only what differs from the technique's defaults is kept, per technique.
        const auto defaults = viz::completeSettings(*mTechniques.at(s.technique), {});
        viz::Settings changed;
        for (const auto& [name, value] : mSettings)
            if (!defaults.count(name) || defaults.at(name) != value) changed[name] = value;
        s.settings[s.technique] = changed;
        s.view = mViewId;
        s.viewZoom = mRightView.zoom;
        s.viewCenter = mRightView.center;
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
        if (mSession.medium) {
            mScene.medium = *mSession.medium;
            mWorker = std::make_unique<CpuWorker>(mScene);  // the CPU worker keeps its own copy of the scene
        }
        const auto it = std::find(mIds.begin(), mIds.end(), mSession.technique);
        selectTechnique(it == mIds.end() ? mCurrent : int(it - mIds.begin()));
        applySessionView();
    }

    // ---- the lesson player's hooks (lesson_player.h): the window's own state changes ----

    void loadLessonScene(const std::string& name) override {
        viz::scene::Scene scene = viz::scene::loadScene(name);  // InputError: the window keeps its scene
        mScene = std::move(scene);
        mOptions.scene = name;
        mController = CameraController(mScene.camera, orbitDistance(mScene));
        mWorker = std::make_unique<CpuWorker>(mScene);
        mLightIntensity0 = 0.0;
        mCompare.clear();
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
        s.view = mViewId;
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
        if (lighting) mWorker = std::make_unique<CpuWorker>(mScene);  // it keeps its own copy of the scene
        mController.place(s.camera, s.orbitTarget);
        mOptions.width = s.size.x;
        mOptions.height = s.size.y;
        const auto it = std::find(mIds.begin(), mIds.end(), s.technique);
        if (it == mIds.end()) throw viz::InputError("unknown technique '" + s.technique + "'");
        selectTechnique(int(it - mIds.begin()));  // also drops the last frame: the step's pixel waits for its own
        mSettings = s.settings;
        mSettingsError.clear();
        mStopAfter = s.stage;
        replan();
        mViewId = s.view;
        mLayer = 0;
        mRightView.fit();
        mProbe.reset();
        mPendingInspect = s.inspect;
        mExposureSet = false;
        mCompare.clear();
    }

    void showLessonView(const std::string& id) override {
        mViewId = id;
        mLayer = 0;
        refreshPanes();
    }

    void setLessonSetting(const std::string& name, double value) override {
        if (mSettings.count(name) && mSettings.at(name) == value) return;
        mSettings[name] = value;
        mDirty = true;
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
        mViewId = mSession.view;
        mRightView.zoom = mSession.viewZoom;
        mRightView.center = mSession.viewCenter;
        mRightView.clampCenter();
        mExposure = mSession.exposure;
        mExposureSet = mSession.exposureSet;
        mDirty = true;
    }

    // ---- comparison grid ----

    // G: every technique renders the current scene and camera with its current settings; their L_air
    // sit in a grid at one shared exposure (the reference's), each with its time and error against the
    // reference. G again closes it. The grid is a snapshot: it does not follow later changes.
    void toggleComparison() {
        if (!mCompare.empty()) {
            mCompare.clear();
            return;
        }
        mScene.camera = mController.camera();
        const int w = mOptions.width, h = mOptions.height;
        viz::Image reference;
        try {
            auto r = viz::makeTechnique("reference");
            viz::FrameInput in{&mScene, w, h, viz::completeSettings(*r, {}), -1};
            reference = r->run(in).airlight;
        } catch (const std::exception& e) {
            mError = std::string("comparison: ") + e.what();
            return;
        }
        const float exposure = std::log2(autoExposure(reference));
        for (const std::string& id : mIds) {
            CompareTile tile;
            tile.technique = id;
            try {
                if (!mTechniques.count(id)) mTechniques[id] = viz::makeTechnique(id);
                viz::Technique& t = *mTechniques.at(id);
                viz::Settings given = mSession.settings.count(id) ? mSession.settings.at(id) : viz::Settings{};
                for (const auto& [name, value] : mOptions.settings) given[name] = value;
                std::string ignored;
                viz::FrameInput in{&mScene, w, h, settingsFor(t, given, ignored), -1};
                const viz::FrameOutput out = id == "reference" ? viz::FrameOutput{} : t.run(in);
                glBindFramebuffer(GL_FRAMEBUFFER, 0);
                const viz::Image& airlight = id == "reference" ? reference : out.airlight;
                tile.milliseconds = out.timing.totalMilliseconds();
                tile.error = viz::report::compareImages(airlight, reference);
                tile.pane.id = id;
                tile.pane.mode = DisplayMode::HdrColor;
                uploadImage(tile.pane, airlight);
            } catch (const std::exception& e) {
                tile.failure = e.what();
            }
            mCompare.push_back(std::move(tile));
        }
        mCompareExposure = exposure;
    }

    void drawComparison(DrawList& dl, const Rect& area) {
        const float line = mFont->lineHeight(), pad = 4.0f * mScale;
        const int n = int(mCompare.size());
        const int cols = int(std::ceil(std::sqrt(double(n)))), rows = (n + cols - 1) / cols;
        const glm::vec2 cell{area.size().x / float(cols), area.size().y / float(rows)};
        dl.textClipped({area.min.x, area.min.y - line}, "comparison (G): L_air at the reference's exposure, time and "
                       "relative L2 against the reference", kAccent, area.max.x);
        for (int i = 0; i < n; ++i) {
            CompareTile& tile = mCompare[std::size_t(i)];
            const glm::vec2 at = area.min + glm::vec2(float(i % cols), float(i / cols)) * cell;
            const Rect box{at + pad, at + cell - glm::vec2(pad, pad + 2.0f * line)};
            const Rect image = fitImage(box, tile.pane.size);
            mPaneDraws.push_back({image, &tile.pane, nullptr, mCompareExposure});
            std::string caption = tile.technique;
            std::string figures = tile.failure.empty()
                ? (tile.technique == "reference" ? std::string("ground truth")
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
        if (!mHaveOutput || mRight.texture == 0) {
            mNotice = "nothing to export: the view holds no image";
            return;
        }
        viz::Image values = viz::gl::readTexture(mRight.texture);  // rows flipped: GL row 0 is the bottom
        if (!mRight.flipY) {
            // Uploaded CPU images keep row 0 at the top in GL too: undo readTexture's flip.
            viz::Image flipped = values;
            for (int y = 0; y < values.height; ++y)
                for (int x = 0; x < values.width; ++x)
                    for (int c = 0; c < values.channels; ++c) flipped.at(x, y, c) = values.at(x, values.height - 1 - y, c);
            values = std::move(flipped);
        }
        const std::string stem = exportStem(mRight.id.empty() ? "view" : mRight.id);
        try {
            viz::writeImage(values, stem + ".exr");
            const bool colour = mRight.mode == DisplayMode::HdrColor || mRight.mode == DisplayMode::RangeColor;
            if (colour) viz::writeImage(values, stem + ".png", std::exp2(mExposure));
            else viz::writeImage(viz::toDisplay(values, mRight.rangeMin, mRight.rangeMax), stem + ".png");
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

    int stageShown() const {
        const int n = int(mTechniques.at(mIds[std::size_t(mCurrent)])->stages().size());
        return mStopAfter < 0 || mStopAfter >= n ? n - 1 : mStopAfter;
    }

    // S / Shift+S: run up to the next / previous stage (the last stage runs everything).
    void stepStage(int delta) {
        const int n = int(technique().stages().size());
        mStopAfter = std::clamp(stageShown() + delta, 0, n - 1);
        mDirty = true;
    }

    // The current stage's sub-step count and position (1-based; the count when it runs them all).
    std::pair<int, int> substepState() {
        const viz::SubstepPosition pos = viz::substepPosition(technique(), stageShown(), mSettings);
        return {pos.at, pos.count};
    }

    // D / Shift+D: one sub-step more / fewer inside the current stage (planes, levels, passes, VPLs).
    void stepSubstep(int delta) {
        const auto [at, count] = substepState();
        if (count <= 0) return;
        if (viz::setSubstep(technique(), stageShown(), mSettings, at + delta)) mDirty = true;
    }

    // ---- ray inspector ----

    // The exact ground truth along the ray of the final image's pixel under the cursor, beside the current
    // technique's value for that pixel. The cursor elsewhere clears it.
    void inspectPixelUnderCursor() {
        mProbe.reset();
        mPendingInspect.reset();
        if (!mFinalRect.contains(mHover) || mOptions.width < 1) return;
        const glm::vec2 uv = (mHover - mFinalRect.min) / mFinalRect.size();
        inspectPixel(std::clamp(int(uv.x * float(mOptions.width)), 0, mOptions.width - 1),
                     std::clamp(int(uv.y * float(mOptions.height)), 0, mOptions.height - 1));
    }

    void inspectPixel(int x, int y) {
        mProbe.reset();
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
        for (std::size_t k = 0; k < p.lights.size(); ++k) {
            viz::plot::Band band{"lit: " + p.lights[k].name, viz::plot::categoricalColor(int(k) + 1), {}};
            for (const auto& iv : p.lights[k].lit) band.spans.push_back({iv.a, iv.b});
            spec.bands.push_back(std::move(band));
        }
        Rect plotArea{{area.min.x, area.min.y + 2.0f * line + 4.0f * mScale}, area.max};
        // The technique's own view of the ray beside the plot: its per-pixel intermediates at this pixel
        // and the per-ray views that follow the picked pixel.
        if (mHaveOutput && technique().id() == mProbeTechnique && plotArea.size().x > 500.0f * mScale) {
            const glm::ivec2 frame{mOptions.width, mOptions.height};
            const Rect side{{plotArea.max.x - 0.42f * plotArea.size().x, plotArea.min.y}, plotArea.max};
            plotArea.max.x = side.min.x - kPad * mScale;
            float y = side.min.y;
            const std::vector<std::string> perRay = pickedRayViews(technique(), mOutput, frame);
            std::string title = mProbeTechnique + " at this pixel";
            if (!perRay.empty()) {
                title += " (its ray in views:";
                for (const std::string& id : perRay) title += " " + id;
                title += ")";
            }
            dl.textClipped({side.min.x, y}, title + ":", kAccent, side.max.x);
            y += line;
            for (const PixelReading& r : readingsAtPixel(mOutput, frame, {p.x, p.y})) {
                if (y + line > side.max.y) break;
                std::string text = r.label + ":";
                for (int c = 0; c < std::min(r.channels, 3); ++c) text += format(" %.4g", r.value[c]);
                if (!r.units.empty()) text += " " + r.units;
                dl.textClipped({side.min.x, y}, text, kText, side.max.x);
                y += line;
            }
        }
        if (plotArea.size().y > 4.0f * line) viz::plot::drawPlot(dl, plotArea, spec);
    }

    // A cross on the inspected pixel of the final image.
    void markProbe(DrawList& dl) {
        if (!mProbe || mOptions.width < 1) return;
        const glm::vec2 c = mFinalRect.min + (glm::vec2(float(mProbe->x), float(mProbe->y)) + 0.5f) /
                                                 glm::vec2(float(mOptions.width), float(mOptions.height)) * mFinalRect.size();
        const float r = 6.0f * mScale;
        dl.line({c.x - r, c.y}, {c.x + r, c.y}, 2.0f * mScale, {1.0f, 0.2f, 0.8f, 1.0f});
        dl.line({c.x, c.y - r}, {c.x, c.y + r}, 2.0f * mScale, {1.0f, 0.2f, 0.8f, 1.0f});
    }

    // ---- techniques and rendering ----

    viz::Technique& technique() { return *mTechniques.at(mIds[std::size_t(mCurrent)]); }

    void selectTechnique(int index) {
        const int n = int(mIds.size());
        index = ((index % n) + n) % n;
        const std::string& id = mIds[std::size_t(index)];
        try {
            if (!mTechniques.count(id)) mTechniques[id] = viz::makeTechnique(id);
        } catch (const std::exception& e) {
            mError = e.what();
            return;
        }
        mCurrent = index;
        mStopAfter = -1;  // a new technique starts complete
        mError.clear();
        mSettingsError.clear();
        // The session's values for this technique, then the command line's on top.
        viz::Settings given = mSession.settings.count(id) ? mSession.settings.at(id) : viz::Settings{};
        for (const auto& [name, value] : mOptions.settings) given[name] = value;
        mSettings = settingsFor(technique(), given, mSettingsError);
        try {
            mPlan = technique().plan(mScene, mSettings);
        } catch (const std::exception& e) {
            mPlan = {};
            mError = e.what();
        }
        // The previous technique's frame does not belong to this one.
        mFinal = {};
        mRight = {};
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
        viz::FrameInput input;
        input.scene = &mScene;
        input.width = mOptions.width;
        input.height = mOptions.height;
        input.settings = mSettings;
        const int stageCount = int(t.stages().size());
        input.stopAfterStage = mStopAfter >= 0 && mStopAfter < stageCount - 1 ? mStopAfter : -1;
        // While the camera is being dragged or flown, render at half size to keep up; the full size
        // follows when the interaction stops.
        mReduced = (mDragButton >= 0 || anyFlyKeyDown()) && input.width >= 64 && input.height >= 48;
        if (mReduced) {
            input.width /= 2;
            input.height /= 2;
        }
        // Panes borrow textures the run is about to replace.
        mRight = {};
        const auto start = Clock::now();
        try {
            mOutput = t.run(input);
            mError.clear();
            mHaveOutput = true;
            mPass = 1;
            mPassCount = 1;
            mOutputSize = {input.width, input.height};
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

    // Number of views the right pane cycles through: the airlight image, then every intermediate.
    int viewCount() const { return 1 + int(mOutput.intermediates.size()); }

    void refreshPanes() {
        mFinal = {};
        mRight = {};
        if (!mHaveOutput) return;
        mFinal.label = "Final image";
        mFinal.note = "surface * exp(-sigma_t d) + L_air";
        mFinal.mode = DisplayMode::HdrColor;
        uploadImage(mFinal, mOutput.final);
        if (!mExposureSet && !mOutput.final.empty()) {
            mExposure = std::round(std::log2(autoExposure(mOutput.final)) / kExposureStep) * kExposureStep;
            mExposureSet = true;
        }
        // Keep showing the same view id across runs and techniques when it still exists.
        // Ids may repeat (one shadow map per light): prefer the same position, then the first match.
        int index = 0;
        const auto& all = mOutput.intermediates;
        if (mView >= 1 && mView <= int(all.size()) && all[std::size_t(mView - 1)].id == mViewId) {
            index = mView;
        } else {
            for (int i = int(all.size()) - 1; i >= 0; --i)
                if (all[std::size_t(i)].id == mViewId) index = i + 1;
        }
        if (mViewId == "airlight" || mViewId.empty()) index = 0;
        // Stepped to a stage before L_air exists: show what that stage published instead.
        if (index == 0 && mOutput.airlight.empty() && mOutput.lastStageRun >= 0) {
            const auto& declared = technique().stages()[std::size_t(mOutput.lastStageRun)].intermediates;
            for (int i = int(all.size()) - 1; i >= 0; --i)
                if (std::find(declared.begin(), declared.end(), all[std::size_t(i)].id) != declared.end()) index = i + 1;
        }
        mView = index;
        if (index == 0) {
            mRight.id = "airlight";
            mRight.label = "Airlight L_air";
            mRight.note = "in-scattered radiance along each eye ray, before the surface term";
            mRight.units = "radiance";
            mRight.kind = viz::ViewKind::Color;
            mRight.mode = DisplayMode::HdrColor;
            uploadImage(mRight, mOutput.airlight);
        } else {
            makePane(mRight, mOutput.intermediates[std::size_t(index - 1)], mLayer);
        }
    }

    void stepView(int delta) {
        if (!mHaveOutput) return;
        const int n = viewCount();
        const int next = ((mView + delta) % n + n) % n;
        mViewId = next == 0 ? "airlight" : mOutput.intermediates[std::size_t(next - 1)].id;
        mView = next;
        mLayer = 0;
        refreshPanes();
    }

    void selectView(int index) {
        if (!mHaveOutput || index < 0 || index >= viewCount()) return;
        mViewId = index == 0 ? "airlight" : mOutput.intermediates[std::size_t(index - 1)].id;
        mView = index;
        mLayer = 0;
        refreshPanes();
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
        if (const auto k = uiKey(key)) {
            mUiInput.keys.push_back(*k);  // widgets: arrows, Enter, Space, editing keys
            return;
        }
        if (key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(mWindow.handle(), GLFW_TRUE);
        else if (key == GLFW_KEY_TAB) selectTechnique(mCurrent + (shift ? -1 : 1));
        else if (key >= GLFW_KEY_1 && key <= GLFW_KEY_9 && key - GLFW_KEY_1 < int(mIds.size())) selectTechnique(key - GLFW_KEY_1);
        else if (key == GLFW_KEY_RIGHT_BRACKET || (key == GLFW_KEY_V && !shift)) stepView(1);
        else if (key == GLFW_KEY_LEFT_BRACKET || (key == GLFW_KEY_V && shift)) stepView(-1);
        else if (key == GLFW_KEY_PERIOD || key == GLFW_KEY_COMMA) stepLayer(key == GLFW_KEY_PERIOD ? 1 : -1);
        else if (key == GLFW_KEY_C && action == GLFW_PRESS) mController.toggleMode();
        else if (key == GLFW_KEY_F5 && action == GLFW_PRESS) saveSessionNow();
        else if (key == GLFW_KEY_0 && action == GLFW_PRESS) mRightView.fit();
        else if (key == GLFW_KEY_I && action == GLFW_PRESS) inspectPixelUnderCursor();
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

    void stepLayer(int delta) {
        if (mRight.layers <= 1) return;
        mLayer = (mRight.layer + delta + mRight.layers) % mRight.layers;
        refreshPanes();
    }

    void onMouseButton(int button, int action) {
        double x = 0, y = 0;
        glfwGetCursorPos(mWindow.handle(), &x, &y);
        onMouseButtonAt(button, action, cursorPixels(x, y));
    }

    void onMouseButtonAt(int button, int action, glm::vec2 p) {
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
            if (mRightImage.contains(p) && mRightView.zoom > 1.0) {
                mDragView = true;  // zoomed in: dragging pans the intermediate view, not the camera
                mLastCursor = p;
                return;
            }
            if (!mViewArea.contains(p)) return;
            mDragButton = button;
            mLastCursor = p;
        } else if (action == GLFW_RELEASE && mDragView) {
            mDragView = false;
        } else if (action == GLFW_RELEASE && button == mDragButton) {
            mDragButton = -1;
            if (mReduced) mDirty = true;
        }
    }

    void onCursor(double x, double y) {
        const glm::vec2 p = cursorPixels(x, y);
        mHover = p;
        if (mDragView) {
            mRightView.panBy(glm::dvec2((p - mLastCursor) / glm::max(mRightImage.size(), glm::vec2(1.0f))));
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
        if (mParamsRect.contains(mHover)) {
            mUiInput.wheel += float(dy);
            return;
        }
        if (mRightImage.contains(mHover)) {
            // The wheel over the intermediate zooms it about the cursor (the camera stays).
            mRightView.zoomAt(glm::dvec2((mHover - mRightImage.min) / mRightImage.size()), std::pow(1.25, dy));
            return;
        }
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

    // The raw value under the cursor, written below the image. Pixel coordinates follow the image
    // convention (row 0 at the top); one texel is read back from the texture.
    // The texel of `pane` under a window point, through the view's pan and zoom.
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

    void hoverReadout(const PaneImage& pane, const Rect& image, const viz::ui::ImageViewTransform& view) {
        const glm::ivec2 texel = texelAt(pane, image, view, mHover);
        const int glRow = pane.flipY ? pane.size.y - 1 - texel.y : texel.y;
        glm::vec4 v(0.0f);
        glGetTextureSubImage(pane.texture, 0, texel.x, glRow, 0, 1, 1, 1, GL_RGBA, GL_FLOAT, sizeof v, &v);
        std::string text = "pixel (" + std::to_string(texel.x) + ", " + std::to_string(texel.y) + ")  =";
        for (int c = 0; c < std::clamp(pane.channels, 1, 3); ++c) text += format("  %.4g", v[c]);
        mDrawList->textClipped({image.min.x, image.max.y + 4.0f * mScale}, text, kText, image.max.x);
    }

    // Returns where the image went.
    Rect drawPane(const Rect& area, const PaneImage& pane, const std::string& title, const std::string& note,
                  const viz::ui::ImageViewTransform* view = nullptr) {
        DrawList& dl = *mDrawList;
        const float line = mFont->lineHeight();
        dl.textClipped(area.min, title, kAccent, area.max.x);
        dl.textClipped({area.min.x, area.min.y + line}, note, kDim, area.max.x);
        const Rect imageArea{{area.min.x, area.min.y + 2.0f * line + 4.0f * mScale}, area.max};
        const Rect image = fitImage(imageArea, pane.size);
        // Frame behind the image: the background batch is drawn before the images.
        mBackground->rect({image.min - 1.0f, image.max + 1.0f}, kPanel);
        mPaneDraws.push_back({image, &pane, view, NAN});
        if (!pane.unavailable.empty()) {
            dl.textClipped({image.min.x + 8.0f * mScale, image.min.y + 8.0f * mScale}, pane.unavailable, kDim, image.max.x);
        }
        const viz::ui::ImageViewTransform whole;
        const viz::ui::ImageViewTransform& v = view ? *view : whole;
        if (pane.texture != 0 && view) texelValues(pane, image, v);
        if (pane.texture != 0 && image.contains(mHover)) hoverReadout(pane, image, v);
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
        return image;
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
            if (count > 0) head += " step " + std::to_string(at) + "/" + std::to_string(count);
            head += " (S, D)";
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
        }
        dl.textClipped({pad, pad + 2.0f * line}, third, thirdColor, float(fb.x) - pad);
        const float top = 3.0f * line + 3.0f * pad;

        // Help line at the bottom.
        const std::string help = mode == CameraController::Mode::Orbit
            ? "camera: ORBIT (target " + format("%.2f", mController.targetDistance()) + ")   Tab/Shift+Tab or 1-9 technique   [ ] view   , . layer   +/- exposure (X auto)   C fly   R reset   "
              "left drag orbit, wheel zoom, right/middle drag pan   Esc quit"
            : "camera: FLY   Tab/Shift+Tab or 1-9 technique   [ ] view   , . layer   +/- exposure (X auto)   C orbit   R reset   "
              "right drag look, WASD move, Q/E down/up, Shift faster, middle drag pan   Esc quit";
        const float bottom = float(fb.y) - line - pad;
        dl.textClipped({pad, bottom}, help, kDim, float(fb.x) - pad);

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
            for (int i = 0; i < viewCount() && y + line < sidebar.max.y; ++i) {
                const std::string name = i == 0 ? "Airlight L_air" : mOutput.intermediates[std::size_t(i - 1)].label;
                const Rect item{{pad * 0.5f, y}, {sidebarWidth - pad * 0.5f, y + line + 2.0f * s}};
                listItem(item, name, i == mView, [this, i] { selectView(i); });
                mNamedRects["view:" + name] = item;
                y += line + 4.0f * s;
            }
        }

        // Two panes side by side, and the lesson panel (if a lesson is open) at the right edge.
        const float lessonWidth = mLesson ? LessonPlayer::panelWidth(float(fb.x), s) : 0.0f;
        if (mLesson) mLesson->place({{float(fb.x) - lessonWidth, top - pad}, {float(fb.x), bottom - pad}});
        const Rect panes{{sidebarWidth + pad, top}, {float(fb.x) - pad - lessonWidth, bottom - pad}};
        mViewArea = panes;
        const float half = 0.5f * (panes.size().x - pad);
        const Rect left{panes.min, {panes.min.x + half, panes.max.y}};
        const Rect right{{panes.max.x - half, panes.min.y}, panes.max};
        // Camera drags are scaled by the final image's on-screen height.
        const Rect finalRect = drawPane(left, mFinal, "Final image", "surface radiance * exp(-sigma_t d) + L_air   (exposure " + format("%+.1f EV)", mExposure));
        mImageHeight = finalRect.size().y;
        mViewRects.push_back({"final", "Final image", finalRect});
        mFinalRect = finalRect;
        markProbe(dl);
        if (mProbe) {
            const float inspectorTop = finalRect.max.y + 2.0f * line;
            if (inspectorTop + 6.0f * line < left.max.y) drawInspector(dl, {{left.min.x, inspectorTop}, left.max});
        } else if (mHaveOutput && !mOutput.timing.stages.empty()) {
            // Per-stage timings of the last run as bars, with the clock that measured them.
            viz::plot::BarChart chart;
            chart.title = "stage times (" + timing.clock + "), total " + format("%.1f ms", timing.totalMilliseconds());
            for (const viz::StageTiming& st : mOutput.timing.stages)
                chart.bars.push_back({st.stage, st.milliseconds, format("%.1f ms", st.milliseconds), kAccent});
            const float chartTop = finalRect.max.y + 2.0f * line;
            if (chartTop + 2.0f * line < left.max.y)
                viz::plot::drawBarChart(dl, {{left.min.x, chartTop}, {left.max.x, left.max.y}}, chart, kDim);
        }
        std::string rightTitle = "(no view)";
        std::string rightNote;
        if (mHaveOutput) {
            rightTitle = mRight.label + "   [" + std::to_string(mView + 1) + "/" + std::to_string(viewCount()) + "]  " + mRight.id;
            if (mRight.layers > 1) rightTitle += "   layer " + std::to_string(mRight.layer + 1) + "/" + std::to_string(mRight.layers);
            rightNote = mRight.note;
            if (mRight.mode != DisplayMode::HdrColor) {
                rightNote += "   [" + format("%g", mRight.rangeMin) + ", " + format("%g", mRight.rangeMax) + "]" +
                             (mRight.units.empty() ? "" : " " + mRight.units) + ", " + viz::viewKindName(mRight.kind);
            }
        } else if (!t.needsGl()) {
            rightTitle = "computing...";
        }
        if (mRightView.zoom > 1.0)
            rightNote = format("zoom %.0fx (wheel; drag to pan; 0 fits)   ", mRightView.zoom) + rightNote;
        if (!mCompare.empty()) {
            const Rect grid{{right.min.x, right.min.y + line}, right.max};
            drawComparison(dl, grid);
            mRightImage = {};
            mViewRects.push_back({"comparison", "comparison grid", grid});
        } else {
            mRightImage = drawPane(right, mRight, rightTitle, rightNote, &mRightView);
            mViewRects.push_back({mHaveOutput ? mRight.id : std::string("none"), rightTitle, mRightImage});
        }
        mParamsRect = {{right.min.x, mRightImage.max.y + 2.0f * line}, {right.max.x, right.max.y}};
        if (mParamsRect.size().y < 4.0f * line || !mCompare.empty()) mParamsRect = {};  // the grid fills the side
        drawParameters(fb);

        // Panels, then the images, then the text batch over them.
        mTextRenderer->draw(*mBackground, fb);
        for (const PaneDraw& d : mPaneDraws) {
            const float shared = std::isnan(d.exposure) ? mExposure : d.exposure;
            const float exposure = (d.pane->mode == DisplayMode::HdrColor || d.pane->mode == DisplayMode::RangeColor) ? shared : 0.0f;
            mImageDisplay->draw(*d.pane, d.rect, fb, exposure, d.view ? *d.view : viz::ui::ImageViewTransform{});
        }
        mTextRenderer->draw(dl, fb);
        mTextRenderer->draw(mUi->drawList(), fb);
    }

    // ---- scene and technique controls (immediate-mode widgets) ----

    // Medium and light sliders and the technique's parameters, generated from its declarations.
    void drawParameters(glm::ivec2 fb) {
        viz::ui::Input in = mUiInput;
        in.mouse = mHover;
        in.mouseDown = mSyntheticDown ? *mSyntheticDown
                                      : glfwGetMouseButton(mWindow.handle(), GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
        mUiInput = {};
        mUi->setTime(glfwGetTime());
        mUi->beginFrame(in, glm::vec2(fb), mScale);
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
                float intensity = float(mScene.lights[0].intensity);
                if (mLightIntensity0 <= 0.0) mLightIntensity0 = mScene.lights[0].intensity;
                const float lo = float(mLightIntensity0 * 1e-3), hi = float(mLightIntensity0 * 1e3);
                if (mUi->sliderFloat("intensity", intensity, lo, hi, true)) {
                    mScene.lights[0].intensity = intensity;
                    sceneChanged = true;
                }
            }
            // Folded by default: the technique's parameters stay in view on small windows.
            if (!mScene.lights.empty() && mUi->collapsingHeader("Light placement", false)) {
                sceneChanged = lightPlacementWidgets(mScene.lights[0]) || sceneChanged;
            }
            if (mUi->collapsingHeader(technique().id() + " parameters", true)) parameterWidgets();
            mUi->endPanel();
            if (sceneChanged) {
                mWorker = std::make_unique<CpuWorker>(mScene);  // the CPU worker keeps its own copy
                replan();
            }
        }
        if (mLesson) mLesson->draw(*mUi, *mDrawList, *mBackground, mScale);
        mUi->endFrame();
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
        for (const viz::ParamInfo& p : technique().params()) {
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
    int mScriptRevealFrames = 0;  // frames left until a script action's widget is scrolled into view
    std::vector<std::string> mSceneChoices, mStiffChoices;  // the scene pickers' lists (built lazily)
    SessionState mSession;  // as loaded (or defaults); settings of techniques not yet visited come from it
    std::string mNotice;    // last session message, shown in the status line
    viz::scene::Scene mScene;  // the camera follows the controller
    viz::Window& mWindow;
    CameraController mController;
    std::vector<std::string> mIds;
    std::map<std::string, std::unique_ptr<viz::Technique>> mTechniques;  // main-thread instances
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
    PaneImage mFinal, mRight;
    std::string mViewId = "airlight";
    int mView = 0, mLayer = 0;
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
        float exposure = NAN;                     // NaN: the window's exposure
    };
    struct CompareTile {
        std::string technique, failure;
        PaneImage pane;
        double milliseconds = 0.0;
        viz::report::ErrorMetrics error;
    };
    std::vector<CompareTile> mCompare;  // the comparison grid (G), empty when closed
    float mCompareExposure = 0.0f;
    std::vector<PaneDraw> mPaneDraws;
    viz::ui::ImageViewTransform mRightView;  // pan and zoom of the intermediate view
    std::unique_ptr<viz::ui::Context> mUi;   // the widgets
    viz::ui::Input mUiInput;                 // keys, text and wheel gathered since the last frame
    Rect mParamsRect;                        // the widget panel's area last frame
    Rect mFinalRect;                         // where the final image was drawn last frame
    std::optional<viz::reference::RayProbe> mProbe;  // the ray inspector's pixel, if any
    std::optional<glm::ivec2> mPendingInspect;  // a lesson step's pixel, inspected when its result is in
    std::unique_ptr<LessonPlayer> mLesson;      // the lesson panel, when a lesson is open
    glm::ivec2 mLessonSize{0};                  // --size given with a lesson: every step at that size
    int mStopAfter = -1;                     // stepping: run up to this stage (-1: all)
    std::string mProbeTechnique;
    bool mProbeHasValue = false;
    glm::dvec3 mProbeValue{0.0};
    double mLightIntensity0 = 0.0;           // the first light's intensity at start (slider range)
    Rect mRightImage;                        // where it was drawn last frame
    bool mDragView = false;                  // a drag that pans the intermediate view
    struct ViewRect {
        std::string name, title;
        Rect rect;  // the image's rectangle in window pixels
    };
    std::vector<ViewRect> mViewRects;  // what the last frame showed where (screenshot sidecar)
    std::map<std::string, Rect> mNamedRects;  // sidebar items: "technique:ID", "view:LABEL"
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
                (void)viz::scene::loadScene(effective.scene);
            } catch (const viz::InputError& e) {
                notice = "session scene: " + std::string(e.what()) + "; using '" + options.scene + "'";
                std::fprintf(stderr, "airlight: note: %s\n", notice.c_str());
                effective.scene = options.scene;
                session = SessionState{};
            }
        }
    }
    // Everything that can fail on user input fails before the window opens.
    viz::scene::Scene scene = viz::scene::loadScene(effective.scene);
    if (session.medium && effective.scene == session.scene) scene.medium = *session.medium;
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
