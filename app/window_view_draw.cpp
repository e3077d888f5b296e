// Drawing the view grid: its cells (view_cell.h) with what the window adds to each (the linked pixel's
// marks, the ray inspector's mark, the light gizmo, the display strip), and the dividers between views.
#include "gui_app.h"
#include "progress_band.h"
#include "texel_labels.h"
#include "view_cell.h"

namespace airlight {

void GuiApp::drawDividers(const Rect& area) {
    const auto dividers = !mComparison.isOpen() ? mGrid.layout.dividers(area, kPad * mScale) : std::vector<ViewDivider>{};
    std::optional<SplitAxis> over;
    mDividerRects.clear();
    for (const ViewDivider& d : dividers) {
        const std::string name = "divider:" + (d.path.empty() ? std::string("root") : d.path);
        float fraction = d.fraction;
        if (mUi->splitter(name, d.track, d.axis == SplitAxis::X, fraction)) mGrid.layout.setFraction(d.path, fraction);
        if (const auto it = mUi->widgetRects().find(name); it != mUi->widgetRects().end()) {
            mDividerRects.push_back(it->second);
            if (it->second.contains(mHover)) over = d.axis;
        }
    }
    setResizeCursor(over);
}

void GuiApp::setResizeCursor(std::optional<SplitAxis> axis) {
    if (axis == mCursorAxis) return;
    mCursorAxis = axis;
    GLFWcursor*& cursor = !axis ? mArrowCursor : *axis == SplitAxis::X ? mColumnCursor : mRowCursor;
    if (!cursor && axis)
        cursor = glfwCreateStandardCursor(*axis == SplitAxis::X ? GLFW_HRESIZE_CURSOR : GLFW_VRESIZE_CURSOR);
    glfwSetCursor(mWindow.handle(), cursor);  // nullptr: the default arrow
}

void GuiApp::drawViewGrid(const Rect& area) {
    mStripRects.clear();
    // The comparison grid takes the right half; the first view keeps the left.
    const float half = 0.5f * (area.size().x - kPad * mScale);
    if (!mComparison.isOpen()) mCells = mGrid.layout.arrange(area, kPad * mScale);
    else mCells = {{mGrid.layout.views().front(), {area.min, {area.min.x + half, area.max.y}}}};
    drawDividers(area);
    ViewCellFrame frame = cellFrame();  // the same for every view of the frame
    for (const ViewCellRect& c : mCells) layOutViewCell(frame, mGrid.views[c.view], c.rect);
    // The frame pixel under the cursor, if the cursor is over a screen-space view.
    mHoveredView = ViewLayout::hit(mCells, mHover);
    mLinkedPixel.reset();
    if (mHoveredView >= 0) {
        const ViewState& h = mGrid.views.at(mHoveredView);
        if (isScreenSpace(h) && h.image.contains(mHover)) mLinkedPixel = texelUnder(h.pane.size, h.image, h.transform, mHover);
    }
    frame.hovered = mHoveredView;
    frame.linkedPixel = mLinkedPixel;
    // Camera drags are scaled by the tallest frame-shaped view (the last one when none is shown).
    float frameHeight = 0.0f;
    for (const ViewCellRect& c : mCells) {
        ViewState& v = mGrid.views.at(c.view);
        if (isScreenSpace(v)) frameHeight = std::max(frameHeight, v.image.size().y);
        drawView(frame, c.view, v);
    }
    if (frameHeight > 1.0f) mImageHeight = frameHeight;
    if (mComparison.isOpen()) {
        const Rect grid{{area.max.x - half, area.min.y + mFont->lineHeight()}, area.max};
        const std::string heading =
            drawComparison(mCanvas, grid, mComparison, {mAnimation.reference.ready(), mAnimation.reference.total()});
        mCanvas.screen.placeView({"comparison", heading, grid, -1});  // titled with the heading drawn over it
    }
}

ViewCellFrame GuiApp::cellFrame() {
    ViewCellFrame f;
    f.canvas = &mCanvas;
    f.ui = mUi.get();
    f.hover = mHover;
    f.focused = mState.focusedView;
    f.hovered = mHoveredView;
    f.linkedPixel = mLinkedPixel;
    f.frameSize = mState.size;
    f.haveOutput = mHaveOutput;
    f.stoppedEarly = mHaveOutput ? stoppedEarly() : std::string();
    f.exposure = mState.exposure;
    ViewTitleFacts& t = f.title;
    t.haveOutput = mHaveOutput;
    t.gpuTechnique = technique().needsGl();
    t.contentCount = contentCount();
    t.exposure = mState.exposure;
    t.stages = &technique().stages();
    t.temporalChange = mAnimation.temporal.describe();
    t.temporalErrorChange = mAnimation.temporal.describeError();
    t.referenceReady = mAnimation.reference.ready();
    t.referenceTotal = mAnimation.reference.total();
    t.referenceSecondsPerFrame = mAnimation.reference.secondsPerFrame();
    t.referenceError = mAnimation.reference.error();
    // "rendering..." while a slow GPU run blocks, the CPU worker's progress while it computes.
    if (mRendering) f.bands.push_back({renderingText(mHaveOutput, mLastRunSeconds)});
    const CpuProgress progress = cpuWorker().progress();
    if (progress.busy && !technique().needsGl()) f.bands.push_back(cpuProgressBand(progress));
    return f;
}

void GuiApp::drawView(const ViewCellFrame& frame, int id, ViewState& v) {
    ViewCellParts parts;
    parts.screenSpace = isScreenSpace(v);
    parts.markers = [this, &v] { return markersFor(v); };
    parts.overlays = [this, id, &v, screenSpace = parts.screenSpace](DrawList& dl) {
        if (screenSpace) mInspector.mark(dl, v.image, v.transform, mState.size, mScale);
        drawGizmo(dl, id, v);
    };
    parts.toggleStrip = [this, id] {
        ViewState& w = mGrid.views.at(id);
        w.display.stripOpen = !w.display.stripOpen;
        mState.focusedView = id;
    };
    mElidedTitles += drawViewCell(frame, id, v, parts).titleElided ? 1 : 0;
    if (v.display.stripOpen && v.strip.size().y > 0.0f) drawStrip(id, v);
}

std::vector<viz::ViewMarker> GuiApp::markersFor(const ViewState& v) {
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

void GuiApp::drawStrip(int id, ViewState& v) {
    const StripAreas areas = splitDisplayStrip(v.strip, mScale);
    mStripRects.push_back(areas.widgets);
    const std::string tag = "##v" + std::to_string(id);
    mUi->beginPanel(tag, areas.widgets);
    const StripChange change = displayStripWidgets(*mUi, v, mState.exposure, mIds, tag);
    mUi->endPanel();
    if (change == StripChange::Difference) refreshView(v);
    else if (change == StripChange::Statistics) updateStatistics(v);
    drawStripHistogram(*mDrawList, v, mState.exposure, areas.histogram, mScale, mFont->lineHeight());
}

}  // namespace airlight
