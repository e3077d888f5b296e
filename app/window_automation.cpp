// The window under automation: the script player (gui --script) and the screenshot sidecar.
#include "gui_app.h"
#include "sidecar_json.h"

#include <cmath>

namespace airlight {

// ---- ScriptHost: what the script player (script_player.h) does to the window ----

std::optional<Rect> GuiApp::scriptRect(const std::string& name) const { return mCanvas.screen.find(name, mUi->widgetRects()); }

std::string GuiApp::knownNames() const { return mCanvas.screen.known(mUi->widgetRects()); }

bool GuiApp::isWidget(const std::string& name) const { return mUi->widgetRects().count(name) > 0; }

void GuiApp::revealWidget(const std::string& name) { mUi->reveal(name); }

void GuiApp::pressKey(int key, int modifiers) { onKey(key, GLFW_PRESS, modifiers); }

void GuiApp::typeText(const std::string& text) {
    if (mUi->textFocused()) {
        mUiInput.text += text;
    } else {
        for (unsigned char c : text) onChar(c);
    }
}

void GuiApp::dropFile(const std::string& path) { onDrop({path}); }

void GuiApp::hoverAt(glm::vec2 p) { mHover = p; }

void GuiApp::dragTo(glm::vec2 p) { onCursorPixels(p); }

void GuiApp::leftButton(bool press, glm::vec2 p) { onMouseButtonAt(GLFW_MOUSE_BUTTON_LEFT, press ? GLFW_PRESS : GLFW_RELEASE, p); }

void GuiApp::wheel(float notches) { onScroll(double(notches)); }

void GuiApp::screenshot(const std::string& path, bool image) { writeScreenshot(path, image); }

bool GuiApp::appendStats(const std::string& path) {
    while (glGetError() != GL_NO_ERROR) ++mGlErrors;
    std::ofstream out(path, std::ios::app);
    out << statsJsonLine(currentProcessStats(), long(mFramesDrawn), mGlErrors) << "\n";
    return bool(out);
}

void GuiApp::writeScreenshot(const std::string& path, bool image) {
    if (image) writeWindowImage(path);
    writeSidecar(path);
}

void GuiApp::writeWindowImage(const std::string& path) {
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
}

void GuiApp::writeSidecar(const std::string& path) {
    const glm::ivec2 fb = mWindow.framebufferSize();
    nlohmann::json views = nlohmann::json::array();
    for (const auto& v : mCanvas.screen.views()) {
        nlohmann::json entry = {{"name", v.name}, {"title", v.title},
                                {"rect", {v.rect.min.x, v.rect.min.y, v.rect.max.x, v.rect.max.y}}};
        if (v.cell >= 0 && mGrid.views.count(v.cell)) entry.update(viewSidecar(mGrid.views.at(v.cell), viewSidecarFacts(v.cell)));
        views.push_back(entry);
    }
    nlohmann::json sidecar = {{"window", {fb.x, fb.y}},
                                    {"scale", mScale},
                                    {"ui_scale", mUiScale},
                                    {"titles_elided", mElidedTitles},
                                    {"scene", mScene.name},
                                    {"scene_title", sceneTitle()},
                                    {"error", mError},
                                    {"settings_error", mSettingsError},  // settings refused (the run used defaults)
                                    {"frames", mFramesDrawn},
                                    {"stage", technique().stages()[std::size_t(stageShown())].id},
                                    {"last_stage_run", mHaveOutput ? mOutput.lastStageRun : -1},
                                    {"first_stage_run", mHaveOutput ? mOutput.firstStageRun : -1},
                                    {"substep", substepState().first},
                                    {"substep_count", substepState().second},
                                    {"stopped_early", stoppedEarly()},
                                    {"notice", mNotice},
                                    {"views", views}};
    sidecar.update(sidecarStateOf(appState()));  // the app state: one function, as the session file
    // The plan the parameter panel's plan section shows: skipped stages and every feature, with reasons.
    sidecar["plan"] = planJson(shownPlan());
    sidecar["lights"] = lightsJson(mScene.lights);
    // The last run's stage times with the clock that took them (a GPU's ring: the latest known).
    if (mHaveOutput) sidecar["timing"] = timingJson(mOutput.timing);
    // The light gizmo in the first view that shows it: its handles in that view's frame pixels.
    sidecar["gizmo"] = nullptr;
    for (const ViewCellRect& c : mCells) {
        const auto gizmo = gizmoFor(mGrid.views.at(c.view));
        if (!gizmo) continue;
        const GizmoHandles h = gizmo->handles(selectedLight());
        const auto point = [](const std::optional<glm::dvec2>& p) {
            return p ? nlohmann::json::array({p->x, p->y}) : nlohmann::json(nullptr);
        };
        // Where each handle is grabbed in the window (off the view: at its edge).
        const auto grab = [&](const std::optional<glm::dvec2>& p) {
            bool inside = true;
            if (!p) return nlohmann::json(nullptr);
            const glm::vec2 w = handlePoint(mGrid.views.at(c.view), *p, inside);
            return nlohmann::json::array({w.x, w.y});
        };
        sidecar["gizmo"] = {{"cell", c.view},           {"position", point(h.position)}, {"tip", point(h.tip)},
                            {"root", point(h.root)},    {"arm", mGizmoArm},
                            {"position_grab", grab(h.position)}, {"tip_grab", grab(h.tip)}};
        break;
    }
    sidecar["animation"] = animationJson(mAnimation);
    // The scene and parameter panel under the grid (null when there is no room for it).
    sidecar["parameters_panel"] = mParamsRect.size().y > 0.0f
                                      ? nlohmann::json::array({mParamsRect.min.x, mParamsRect.min.y, mParamsRect.max.x,
                                                               mParamsRect.max.y})
                                      : nlohmann::json(nullptr);
    sidecar["view_grid"] = {{"layout", mGrid.layout.toText()}, {"focused", mState.focusedView},
                            {"maximised", mGrid.layout.maximised()},
                            {"cpu_ms_last_frame", mGridMilliseconds},
                            {"ui_cpu_ms_last_frame", mUiMilliseconds},
                            {"linked_pixel", mLinkedPixel ? nlohmann::json::array({mLinkedPixel->x, mLinkedPixel->y})
                                                          : nlohmann::json(nullptr)}};
    if (mComparison.isOpen()) sidecar["comparison"] = mComparison.toJson();
    if (mInspector.active()) sidecar["inspector"] = mInspector.sidecar(inspectedReadings());
    if (mLesson) sidecar["lesson"] = mLesson->sidecar(*this);
    std::filesystem::path json(path);
    json.replace_extension(".json");
    const std::string error = viz::writeFileAtomically(json, sidecar.dump(2) + "\n");
    if (!error.empty()) throw viz::InputError("cannot write '" + json.string() + "': " + error);
}

ViewSidecarFacts GuiApp::viewSidecarFacts(int id) {
    ViewState& v = mGrid.views.at(id);
    ViewSidecarFacts f;
    f.id = id;
    f.focused = id == mState.focusedView;
    f.screenSpace = isScreenSpace(v);
    f.exposure = mState.exposure;
    f.linkedPixel = mLinkedPixel;
    if (mLinkedPixel && !f.screenSpace && v.pane.texture != 0) f.markers = markersFor(v);
    return f;
}

}  // namespace airlight
