// One frame of the window: the status lines, the sidebar, the view grid or comparison, the panels under it
// and the help lines.
#include "gui_app.h"

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
    dl.clear();
    mBackground->clear();
    mHits.clear();
    mPaneDraws.clear();
    mScreen.clear();
    mElidedTitles = 0;
    mScreen.place("window", Rect{{0.0f, 0.0f}, glm::vec2(fb)});  // scripts: any point, by window fraction
    const float s = mScale;
    const float pad = kPad * s;
    const float line = mFont->lineHeight();
    const viz::Technique& t = technique();

    // Status lines at the top.
    const CameraController::Mode mode = mController.mode();
    std::string head = "scene: " + sceneTitle() + "   technique: " + t.id() + " - " + t.description() +
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
    std::string third = skippedLine(shownPlan());
    glm::vec4 thirdColour = kDim;
    if (!mError.empty() || !mSettingsError.empty()) {
        third = "error: " + firstLine(mError.empty() ? mSettingsError + " (using defaults)" : mError);
        thirdColour = kError;
    } else if (!mNotice.empty()) {
        third = mNotice + "   |   " + third;
    } else if (mHaveOutput && !mOutput.notes.empty()) {
        third = "note: " + mOutput.notes.front() + "   |   " + third;
        thirdColour = kAccent;
    }
    dl.textClipped({pad, pad + 2.0f * line}, third, thirdColour, float(fb.x) - pad);
    const float top = 3.0f * line + 3.0f * pad;

    // Help lines at the bottom, from the key table.
    const bool flying = mode == CameraController::Mode::Fly;
    const std::string help = (flying ? std::string("camera: FLY   ")
                                     : "camera: ORBIT (target " + format("%.2f", mController.targetDistance()) + ")   ") +
                             (mAnimation.path ? "path " + mAnimation.path->text + " frame " +
                                                    std::to_string(mAnimation.pathFrame + 1) + "/" +
                                                    std::to_string(mAnimation.pathFrames) +
                                                    (mAnimation.playing ? " (P pauses)   " : " (P plays)   ")
                                              : std::string()) +
                             helpLine(HelpLine::Frame, flying);
    const float bottom = float(fb.y) - 2.0f * line - pad;
    dl.textClipped({pad, bottom}, help, kDim, float(fb.x) - pad);
    dl.textClipped({pad, bottom + line}, helpLine(HelpLine::Views, flying), kDim, float(fb.x) - pad);

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
        mScreen.place("technique:" + mIds[std::size_t(i)], item);
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
            mScreen.place("view:" + name, item);
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

void GuiApp::beginWidgets(glm::ivec2 fb) {
    viz::ui::Input in = mUiInput;
    in.mouse = mHover;
    mHoverDrawn = mHover;
    in.mouseDown = mSyntheticDown ? *mSyntheticDown
                                  : glfwGetMouseButton(mWindow.handle(), GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    mUiInput = {};
    mUi->setTime(glfwGetTime());
    mUi->beginFrame(in, glm::vec2(fb), mScale);
}

}  // namespace airlight
