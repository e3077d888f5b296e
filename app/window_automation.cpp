// The window under automation: the script player (gui --script) and the screenshot sidecar.
#include "gui_app.h"

#include <cmath>

namespace airlight {

Rect GuiApp::scriptTarget(const ScriptAction& a) const {
    if (const std::optional<Rect> r = mCanvas.screen.find(a.target, mUi->widgetRects())) return *r;
    throw viz::InputError(mOptions.scriptPath + ":" + std::to_string(a.line) + ": nothing named '" + a.target +
                          "' is on screen (on screen: " + mCanvas.screen.known(mUi->widgetRects()) + ")");
}

bool GuiApp::revealScriptTarget(const ScriptAction& a) {
    if (mScriptRevealFrames > 0) return --mScriptRevealFrames > 0;  // 0: revealed, go on
    if (!mUi->widgetRects().count(a.target)) return false;
    mUi->reveal(a.target);
    mScriptRevealFrames = 2;
    return true;
}

bool GuiApp::stepScript() {
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
            case ScriptAction::Kind::Hold:
                if (mScriptWait == 0) {
                    onKey(scriptKeyCode(a.target), GLFW_PRESS, a.modifiers);
                    mScriptHeld = scriptKeyCode(a.target);
                    mScriptHeldShift = (a.modifiers & GLFW_MOD_SHIFT) != 0;
                    mScriptWait = a.frames + 1;
                }
                if (--mScriptWait > 0) return true;
                mScriptHeld = -1;
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
            case ScriptAction::Kind::Sidecar:
                writeScreenshot(a.target, a.kind == ScriptAction::Kind::Screenshot);
                ++mScriptIndex;
                break;
            case ScriptAction::Kind::Type:
                if (mUi->textFocused()) {
                    mUiInput.text += a.target;
                } else {
                    for (unsigned char c : a.target) onChar(c);
                }
                ++mScriptIndex;
                return true;
            case ScriptAction::Kind::Drop:
                onDrop({a.target});
                ++mScriptIndex;
                return true;
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
        if (v.cell >= 0 && mViews.count(v.cell)) entry.update(viewSidecar(v.cell, mViews.at(v.cell)));
        views.push_back(entry);
    }
    nlohmann::json sidecar = {{"window", {fb.x, fb.y}},
                                    {"scale", mScale},
                                    {"ui_scale", mUiScale},
                                    {"titles_elided", mElidedTitles},
                                    {"scene", mScene.name},
                                    {"scene_title", sceneTitle()},
                                    {"error", mError},
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
    {
        // The plan the parameter panel's plan section shows: skipped stages and every feature, with reasons.
        const viz::Plan& plan = shownPlan();
        nlohmann::json skipped = nlohmann::json::array(), features = nlohmann::json::array();
        for (const viz::StagePlan& st : plan.stages)
            if (!st.runs) skipped.push_back({{"stage", st.stage}, {"why", st.why}});
        for (const viz::FeaturePlan& f : plan.features)
            features.push_back({{"feature", f.feature}, {"on", f.enabled}, {"why", f.why}});
        sidecar["plan"] = {{"skipped", skipped}, {"features", features}};
    }
    {
        nlohmann::json lights = nlohmann::json::array();
        for (const auto& l : mScene.lights)
            lights.push_back({{"name", l.name},
                              {"position", {l.position.x, l.position.y, l.position.z}},
                              {"direction", {l.direction.x, l.direction.y, l.direction.z}},
                              {"intensity", l.intensity}});
        sidecar["lights"] = lights;
    }
    // The last run's stage times with the clock that took them (a GPU's ring: the latest known).
    if (mHaveOutput) {
        nlohmann::json stages = nlohmann::json::array();
        for (const viz::StageTiming& s : mOutput.timing.stages)
            if (std::isfinite(s.milliseconds)) stages.push_back({{"stage", s.stage}, {"ms", s.milliseconds}});
        sidecar["timing"] = {{"clock", mOutput.timing.clock}, {"stages", stages}};
    }
    // The light gizmo in the first view that shows it: its handles in that view's frame pixels.
    sidecar["gizmo"] = nullptr;
    for (const ViewCellRect& c : mCells) {
        const auto gizmo = gizmoFor(mViews.at(c.view));
        if (!gizmo) continue;
        const GizmoHandles h = gizmo->handles(selectedLight());
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
    sidecar["animation"] = {{"playing", mAnimation.playing},
                            {"seconds", mAnimation.clock},
                            {"light_turn", mAnimation.turn},
                            {"frame", mAnimation.frame},
                            {"temporal_pairs", mAnimation.temporal.pairs()}};
    // The temporal view's score, once there is one (two frames played).
    if (std::isfinite(mAnimation.temporal.score())) sidecar["animation"]["temporal_change_rms"] = mAnimation.temporal.score();
    // Against the reference (--path with a temporal view shown): its frames and the error's score.
    sidecar["animation"]["temporal_error_pairs"] = mAnimation.temporal.errorPairs();
    if (std::isfinite(mAnimation.temporal.errorScore()))
        sidecar["animation"]["temporal_error_rms"] = mAnimation.temporal.errorScore();
    sidecar["animation"]["reference_frames"] = {{"ready", mAnimation.reference.ready()},
                                                {"total", mAnimation.reference.total()},
                                                {"seconds_per_frame", mAnimation.reference.secondsPerFrame()},
                                                {"error", mAnimation.reference.error()}};
    // --path: the motion and the loop's frame shown.
    if (mAnimation.path)
        sidecar["animation"]["path"] = {{"text", mAnimation.path->text},
                                        {"frames", mAnimation.pathFrames},
                                        {"frame", mAnimation.pathFrame}};
    // The scene and parameter panel under the grid (null when there is no room for it).
    sidecar["parameters_panel"] = mParamsRect.size().y > 0.0f
                                      ? nlohmann::json::array({mParamsRect.min.x, mParamsRect.min.y, mParamsRect.max.x,
                                                               mParamsRect.max.y})
                                      : nlohmann::json(nullptr);
    sidecar["view_grid"] = {{"layout", mLayout.toText()}, {"focused", mFocused},
                            {"maximised", mLayout.maximised()},
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

nlohmann::json GuiApp::viewSidecar(int id, const ViewState& v) {
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
                        {"display", {{"channel", channelChoices(v.pane)[std::size_t(d.channel)]},
                                     {"range", rangeModeNames()[std::size_t(d.range)]},
                                     {"lo", m.lo}, {"hi", m.hi}, {"log", d.logScale},
                                     {"colour_map", colourMapNames()[std::size_t(d.colourMap)]},
                                     {"mode", int(m.mode)}, {"mark_negative", m.markNegative},
                                     {"strip_open", d.stripOpen}}},
                        {"plots", v.pane.plots.size()},
                        {"title_elided", v.titleElided},
                        {"note_elided", v.noteElided},
                        {"negative_pixels", v.counts.negative},
                        {"nan_pixels", v.counts.nan},
                        {"inf_pixels", v.counts.inf}};
    if (v.colourBar.kind != ColourBar::Kind::None) {
        // What the bar under the view says, as drawn in the last frame (non-finite numbers as null).
        const auto number = [](double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); };
        const ColourBar& b = v.colourBar;
        const char* kind = b.kind == ColourBar::Kind::Ramp ? "ramp" : b.kind == ColourBar::Kind::Classes ? "classes" : "picture";
        nlohmann::json bar = {{"kind", kind},
                              {"lo", number(b.lo)}, {"hi", number(b.hi)}, {"log", b.logarithmic},
                              {"units", b.units}, {"caption", b.caption},
                              {"rect", {v.bar.min.x, v.bar.min.y, v.bar.max.x, v.bar.max.y}},
                              {"ramp_rect", {v.ramp.min.x, v.ramp.min.y, v.ramp.max.x, v.ramp.max.y}}};
        nlohmann::json ticks = nlohmann::json::array(), at = nlohmann::json::array();
        for (std::size_t i = 0; i < b.ticks.size(); ++i) ticks.push_back(number(b.ticks[i])), at.push_back(b.tickAt[i]);
        bar["ticks"] = ticks;
        bar["tick_labels"] = b.tickLabels;
        bar["tick_at"] = at;
        if (b.kind == ColourBar::Kind::Classes) bar["classes"] = b.classLabels;
        nlohmann::json legend = nlohmann::json::array();
        for (const LegendSwatch& sw : b.legend)
            // The overlays' values are NaN and Inf themselves: named, not null.
            legend.push_back({{"label", sw.label},
                              {"value", std::isfinite(sw.value) ? nlohmann::json(sw.value)
                                                                : nlohmann::json(std::isnan(sw.value) ? "NaN" : sw.value > 0 ? "Inf" : "-Inf")},
                              {"pixels", sw.pixels}, {"sentinel", sw.sentinel}});
        bar["legend"] = legend;
        j["colour_bar"] = std::move(bar);
    }
    if (d.difference != DifferenceMode::Off) {
        // Figures only where they were computed and are defined (relative L2 is not against a black
        // reference); the note says why one is missing.
        nlohmann::json diff = {{"mode", differenceModeNames()[std::size_t(d.difference)]},
                               {"against", d.against}, {"note", v.differenceNote}};
        if (v.error && std::isfinite(v.error->relativeL2)) diff["relative_l2"] = v.error->relativeL2;
        if (v.error && std::isfinite(v.error->maxAbsolute)) diff["max_abs"] = v.error->maxAbsolute;
        j["difference"] = std::move(diff);
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

}  // namespace airlight
