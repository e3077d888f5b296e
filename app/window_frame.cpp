// One frame of the window: the status lines, the sidebar, the view grid or comparison, the panels under it
// and the help lines; and the window's presentation (UI scale, full screen).
#include "gui_app.h"
#include "help_lines.h"

namespace airlight {

void GuiApp::draw() {
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
    mCanvas.scale = mScale;
    mCanvas.begin(fb);  // "window": scripts name any point by window fraction
    mElidedTitles = 0;
    const float s = mScale;
    const float pad = kPad * s;
    const float line = mFont->lineHeight();
    const viz::Technique& t = technique();

    // Status lines at the top.
    const CameraController::Mode mode = mController.mode();
    viz::Timing timing = mOutput.timing;
    if (timing.clock.empty()) timing.clock = t.needsGl() ? mClockName : "steady_clock";
    const float top = drawStatusLines(*mBackground, dl, statusLines(statusFacts(timing)), float(fb.x), pad, line);

    // Help lines at the bottom, from the key table.
    const bool flying = mode == CameraController::Mode::Fly;
    std::vector<std::string> frameHelp = {
        flying ? std::string("camera: FLY") : "camera: ORBIT (target " + format("%.3g", mController.targetDistance()) + ")"};
    if (mAnimation.path)
        frameHelp.push_back("path " + mAnimation.path->text + " frame " + std::to_string(mAnimation.pathFrame + 1) + "/" +
                            std::to_string(mAnimation.pathFrames) + (mAnimation.playing ? " (P pauses)" : " (P plays)"));
    for (std::string& b : helpBriefs(HelpLine::Frame, flying)) frameHelp.push_back(std::move(b));
    // Packed into whole lines (help_lines.h): a narrow window gives up a line of the views for every key.
    const auto measure = [this](std::string_view x) { return mFont->measure(x); };
    std::vector<std::string> helpLines = packHelp(frameHelp, float(fb.x) - 2.0f * pad, measure, 2);
    for (std::string& l : packHelp(helpBriefs(HelpLine::Views, flying), float(fb.x) - 2.0f * pad, measure, 2))
        helpLines.push_back(std::move(l));
    const float bottom = float(fb.y) - float(helpLines.size()) * line - pad;
    for (std::size_t i = 0; i < helpLines.size(); ++i)
        dl.textClipped({pad, bottom + float(i) * line}, helpLines[i], kDim, float(fb.x) - pad);

    // Sidebar: techniques, then views (sidebar.h).
    std::vector<std::string> views, viewStages;
    if (mHaveOutput)
        for (int i = 0; i < contentCount(); ++i) {
            views.push_back(contentLabel(i));
            // Under the stage that makes it, named as on the stage bar; the run's outputs have none.
            const int k = i < 2 ? -1 : viz::stageOfIntermediate(t.stages(), contentId(i));
            viewStages.push_back(k < 0 ? "" : std::to_string(k + 1) + " " + t.stages()[std::size_t(k)].label);
        }
    const SidebarLayout side =
        layoutSidebar(mIds, currentIndex(), views, viewStages, mHaveOutput ? focusedView().shown : -1,
                      {top, bottom, pad, line, s, kSidebarMin * s, [this](const std::string& x) { return mFont->measure(x); }});
    const float sidebarWidth = side.panel.max.x;
    mBackground->rect(side.panel, kPanel);
    for (const SidebarHeading& h : side.headings)
        dl.textClipped(h.at, h.text, h.stage || h.hidden ? kDim : kAccent, sidebarWidth - 0.5f * pad);
    for (const SidebarEntry& e : side.entries) {
        const int i = e.index;
        // Clicking a view's entry shows it in the focused view.
        if (e.list == SidebarEntry::List::Techniques) listEntry(mCanvas, mHover, e.rect, e.text, e.selected, [this, i] { selectTechnique(i); });
        else listEntry(mCanvas, mHover, e.rect, e.text, e.selected, [this, i] { selectView(i); });
        mCanvas.screen.place(e.screenName, e.rect);
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
    const float aspect = float(mState.size.y) / float(std::max(1, mState.size.x));
    float gridHeight = std::clamp(half * aspect + chrome, 0.5f * panes.size().y, 0.74f * panes.size().y);
    // The ray inspector's plot needs height: the grid gives some up while it is open.
    if (mInspector.active()) gridHeight = std::min(gridHeight, 0.56f * panes.size().y);
    // The stepping timeline sits between the grid and the panels.
    const float timelineHeight = line + 8.0f * s;
    // The panels below keep room for six lines (the parameter panel's header and a few rows, which then
    // scroll): at a large UI scale the grid gives up height, down to 45 % of the area, rather than hide
    // them.
    const float bottomRoom = panes.size().y - gridHeight - timelineHeight - 1.5f * pad;
    if (bottomRoom < 6.0f * line)
        gridHeight = std::max(0.45f * panes.size().y, gridHeight - (6.0f * line - bottomRoom));
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
    if (mInspector.active()) {
        if (left.size().y > 6.0f * line) mInspector.draw(dl, left, line, mScale, inspectedReadings());
    } else if (mHaveOutput && !mOutput.timing.stages.empty()) {
        // Per-stage timings of the last run as bars, with the clock that measured them.
        viz::plot::BarChart chart;
        chart.title = "stage times (" + timing.clock + "), total " + format("%.1f ms", timing.totalMilliseconds());
        // Stages that compiled shaders this run (first use): marked, and drawn dim, not warm figures.
        if (mOutput.timing.programsCompiled() > 0) chart.title += "; * compiled shaders (first use)";
        for (const viz::StageTiming& st : mOutput.timing.stages)
            chart.bars.push_back({st.stage, st.milliseconds, format("%.1f ms", st.milliseconds) + (st.programsCompiled ? "*" : ""),
                                  st.programsCompiled ? kDim : kAccent});
        if (left.size().y > 2.0f * line) viz::plot::drawBarChart(dl, left, chart, kDim);
    }
    mParamsRect = right;
    if (mParamsRect.size().y < 4.0f * line) mParamsRect = {};
    drawParameters(fb);

    mUiMilliseconds = std::chrono::duration<double, std::milli>(Clock::now() - frameStart).count();
    // Panels, then the images, then the text batch over them.
    mTextRenderer->draw(*mBackground, fb);
    for (const PaneDraw& d : mCanvas.panes)
        mImageDisplay->draw(*d.pane, d.rect, fb, d.mapping, d.view ? *d.view : viz::ui::ImageViewTransform{});
    mTextRenderer->draw(dl, fb);
    mTextRenderer->draw(mUi->drawList(), fb);
}

StatusFacts GuiApp::statusFacts(const viz::Timing& timing) const {
    const viz::Technique& t = technique();
    StatusFacts f;
    f.scene = sceneTitle();
    f.technique = t.id();
    f.description = t.description();
    f.renderSize = mState.size;
    f.haveOutput = mHaveOutput;
    f.reduced = mReduced;
    f.outputSize = mOutputSize;
    f.pass = mPass;
    f.passCount = mPassCount;
    f.stage = stageShown();
    f.stageCount = int(t.stages().size());
    f.stageId = t.stages()[std::size_t(f.stage)].id;
    std::tie(f.substep, f.substepCount) = substepState();
    f.fly = mController.mode() == CameraController::Mode::Fly;
    f.firstStageRun = mHaveOutput ? mOutput.firstStageRun : 0;
    f.timing = timing;
    f.plan = shownPlan();
    f.error = mError;
    f.settingsError = mSettingsError;
    f.notice = mNotice;
    if (mHaveOutput && !mOutput.notes.empty()) f.note = mOutput.notes.front();
    return f;
}

void GuiApp::beginWidgets(glm::ivec2 fb) {
    viz::ui::Input in = mUiInput;
    in.mouse = mHover;
    mHoverDrawn = mHover;
    in.mouseDown = mScript.leftButtonDown() ? *mScript.leftButtonDown()
                                  : glfwGetMouseButton(mWindow.handle(), GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    mUiInput = {};
    mUi->setTime(glfwGetTime());
    mUi->beginFrame(in, glm::vec2(fb), mScale);
}

void GuiApp::setUiScale(float scale) {
    scale = std::clamp(scale, kMinUiScale, kMaxUiScale);
    if (scale == mUiScale) {
        mNotice = "UI scale " + format("%.2f", double(mUiScale)) + " (the limit)";
        return;
    }
    mUiScale = scale;
    mScale = mContentScale * mUiScale;
    // The glyphs are baked at the new size into the same atlas (the draw lists and widgets keep their
    // reference to it); the text renderer uploads them again.
    *mFont = viz::ui::FontAtlas::bake(viz::ui::FontAtlas::defaultFontPath(), kFontSize * mScale);
    mTextRenderer = std::make_unique<viz::ui::TextRenderer>(*mFont);
    mNotice = "UI scale " + format("%.2f", double(mUiScale));
}

void GuiApp::toggleFullscreen() {
    GLFWwindow* w = mWindow.handle();
    if (GLFWmonitor* monitor = glfwGetWindowMonitor(w)) {
        (void)monitor;
        glfwSetWindowMonitor(w, nullptr, mWindowedRect.x, mWindowedRect.y, mWindowedRect.z, mWindowedRect.w, 0);
        return;
    }
    GLFWmonitor* primary = glfwGetPrimaryMonitor();
    const GLFWvidmode* mode = primary ? glfwGetVideoMode(primary) : nullptr;
    if (!mode) {
        mNotice = "full screen: no monitor found";
        return;
    }
    glfwGetWindowPos(w, &mWindowedRect.x, &mWindowedRect.y);
    glfwGetWindowSize(w, &mWindowedRect.z, &mWindowedRect.w);
    glfwSetWindowMonitor(w, primary, 0, 0, mode->width, mode->height, mode->refreshRate);
}

}  // namespace airlight
