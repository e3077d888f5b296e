// Drawing the view grid: each view's title, image, texel values, markers, plots, display strip and
// histogram, and the dividers between views.
#include "gui_app.h"
#include "progress_band.h"
#include "texel_labels.h"
#include "view_histogram.h"
#include "view_title.h"
#include "view_markers.h"

namespace airlight {

Rect GuiApp::fitImage(const Rect& area, glm::ivec2 imageSize) const {
    if (imageSize.x <= 0 || imageSize.y <= 0) imageSize = mState.size;
    return fitImageRect(area, imageSize);
}

void GuiApp::listItem(const Rect& r, const std::string& text, bool selected, std::function<void()> onClick) {
    DrawList& dl = *mDrawList;
    if (selected) dl.rect(r, kHighlight);
    else if (r.contains(mHover)) dl.rect(r, kHover);
    dl.textClipped({r.min.x + 6.0f * mScale, r.min.y + 1.0f * mScale}, text, selected ? kText : kDim, r.max.x - 4.0f * mScale);
    mCanvas.hits.push_back({r, std::move(onClick)});
}

void GuiApp::texelValues(const ViewState& v) {
    const PaneImage& pane = v.pane;
    const std::optional<TexelBlock> block = labelledTexels(pane.size, v.image, v.transform, mFont->lineHeight());
    if (!block) return;
    // From the view's CPU copy (what its readout and statistics use); while there is none (during an
    // interaction), a read of the visible block. GL rows: flipped textures keep row 0 at the bottom.
    const glm::ivec2 count = block->count();
    std::vector<glm::vec4> read;
    if (v.values.width != pane.size.x || v.values.height != pane.size.y) {
        read.resize(std::size_t(count.x * count.y));
        const int glRow0 = pane.flipY ? pane.size.y - 1 - block->hi.y : block->lo.y;
        glGetTextureSubImage(pane.texture, 0, block->lo.x, glRow0, 0, count.x, count.y, 1, GL_RGBA, GL_FLOAT,
                             GLsizei(read.size() * sizeof(glm::vec4)), read.data());
    }
    const auto value = [&](int x, int y) {
        glm::vec4 out(0.0f);
        if (read.empty()) (void)valueAt(v, {x, y}, out);
        else out = read[std::size_t((pane.flipY ? block->hi.y - y : y - block->lo.y) * count.x + (x - block->lo.x))];
        return out;
    };
    const float line = mFont->lineHeight();
    for (const TexelLabel& l : texelLabels(*block, pane.size, v.image, v.transform, pane.channels, value, *mFont, mScale)) {
        mDrawList->rect({l.at - 1.0f, l.at + glm::vec2(mFont->measure(l.text) + 1.0f, line)}, {0.0f, 0.0f, 0.0f, 0.55f});
        mDrawList->textClipped(l.at, l.text, kText, l.clipX);
    }
}

void GuiApp::layoutCell(ViewState& v, const Rect& cell) {
    const float line = mFont->lineHeight(), s = mScale;
    v.cell = cell;
    v.title = {cell.min, {cell.max.x, cell.min.y + 2.0f * line + 4.0f * s}};
    const float readout = line + 6.0f * s;
    float stripHeight = 0.0f;
    if (v.display.stripOpen)
        stripHeight = std::min(displayStripHeight(v.display, cell.size().x, mUi->rowHeight(), s),
                               0.6f * (cell.size().y - v.title.size().y - readout));
    // The colour bar goes under the image when the cell leaves the image most of its height.
    float barHeight = colourBarHeight(v);
    if (barHeight > 0.25f * (cell.size().y - v.title.size().y - readout - stripHeight)) barHeight = 0.0f;
    const Rect imageArea{{cell.min.x, v.title.max.y}, {cell.max.x, cell.max.y - readout - stripHeight - barHeight}};
    v.image = v.pane.plots.empty() ? fitImage(imageArea, v.pane.size) : imageArea;  // plots take the whole area
    v.bar = barHeight > 0.0f ? Rect{{cell.min.x, v.image.max.y + 2.0f * s}, {cell.max.x, v.image.max.y + barHeight}} : Rect{};
    v.strip = stripHeight > 0.0f ? Rect{{cell.min.x, cell.max.y - stripHeight}, cell.max} : Rect{};
}

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
    for (const ViewCellRect& c : mCells) layoutCell(mGrid.views[c.view], c.rect);
    // The frame pixel under the cursor, if the cursor is over a screen-space view.
    mHoveredView = ViewLayout::hit(mCells, mHover);
    mLinkedPixel.reset();
    if (mHoveredView >= 0) {
        const ViewState& h = mGrid.views.at(mHoveredView);
        if (isScreenSpace(h) && h.image.contains(mHover)) mLinkedPixel = texelUnder(h.pane.size, h.image, h.transform, mHover);
    }
    // Camera drags are scaled by the tallest frame-shaped view (the last one when none is shown).
    float frameHeight = 0.0f;
    const ViewTitleFacts facts = viewTitleFacts();  // the same for every view of the frame
    for (const ViewCellRect& c : mCells) {
        ViewState& v = mGrid.views.at(c.view);
        if (isScreenSpace(v)) frameHeight = std::max(frameHeight, v.image.size().y);
        drawView(c.view, v, facts);
    }
    if (frameHeight > 1.0f) mImageHeight = frameHeight;
    if (mComparison.isOpen()) {
        const Rect grid{{area.max.x - half, area.min.y + mFont->lineHeight()}, area.max};
        drawComparison(mCanvas, grid, mComparison, {mAnimation.reference.ready(), mAnimation.reference.total()});
        mCanvas.screen.placeView({"comparison", "comparison grid", grid, -1});
    }
}

ViewTitleFacts GuiApp::viewTitleFacts() const {
    ViewTitleFacts f;
    f.haveOutput = mHaveOutput;
    f.gpuTechnique = technique().needsGl();
    f.contentCount = contentCount();
    f.exposure = mState.exposure;
    f.stages = &technique().stages();
    f.temporalChange = mAnimation.temporal.describe();
    f.temporalErrorChange = mAnimation.temporal.describeError();
    f.referenceReady = mAnimation.reference.ready();
    f.referenceTotal = mAnimation.reference.total();
    f.referenceSecondsPerFrame = mAnimation.reference.secondsPerFrame();
    f.referenceError = mAnimation.reference.error();
    return f;
}

void GuiApp::drawView(int id, ViewState& v, const ViewTitleFacts& facts) {
    DrawList& dl = *mDrawList;
    const float line = mFont->lineHeight(), s = mScale;
    const bool focused = id == mState.focusedView;
    const auto [title, note] = viewTitle(v, facts);
    // Title bar: highlighted when focused (keys and the views list act on it); drag it onto another
    // view to swap the two.
    mBackground->rect(v.title, focused ? kHighlight : kPanel);
    const std::string toggle = v.display.stripOpen ? "display -" : "display +";
    const float toggleWidth = mFont->measure(toggle) + 16.0f * s;
    const Rect toggleRect{{v.title.max.x - toggleWidth, v.title.min.y + 1.0f * s},
                          {v.title.max.x - 2.0f * s, v.title.min.y + line + 2.0f * s}};
    // Not the complete algorithm: every view says where the run stopped, in the warning colour; then its
    // negative, NaN and Inf pixels. Too long for the bar (a small view, a large UI scale): each part
    // shortened in the middle, the warnings first kept whole, the full text shown while the title is hovered.
    const TitleWarnings warn = titleWarnings(v, mHaveOutput ? stoppedEarly() : std::string(), mState.exposure);
    const std::string& early = warn.early;
    const std::string& counts = warn.counts;
    const float left = v.title.min.x + 4.0f * s;
    const FittedTitle fit = fitTitleBar(*mFont, title, warn, note, toggleRect.min.x - 4.0f * s - left,
                                        v.title.max.x - 4.0f * s - left);
    float x = dl.textClipped({left, v.title.min.y + 2.0f * s}, fit.title, kAccent, toggleRect.min.x - 4.0f * s);
    if (!fit.early.empty()) x = dl.textClipped({x, v.title.min.y + 2.0f * s}, fit.early, kError, toggleRect.min.x - 4.0f * s);
    if (!counts.empty()) dl.textClipped({x, v.title.min.y + 2.0f * s}, counts, kError, toggleRect.min.x - 4.0f * s);
    dl.textClipped({left, v.title.min.y + 2.0f * s + line}, fit.note, kDim, v.title.max.x - 4.0f * s);
    v.titleElided = fit.titleElided;
    v.noteElided = fit.noteElided;
    const bool elided = v.titleElided || v.noteElided;
    if (elided && v.title.contains(mHover) && !toggleRect.contains(mHover))
        mUi->tooltipNow({title + early + counts, note});
    mElidedTitles += v.titleElided ? 1 : 0;
    listItem(toggleRect, toggle, v.display.stripOpen, [this, id] {
        ViewState& w = mGrid.views.at(id);
        w.display.stripOpen = !w.display.stripOpen;
        mState.focusedView = id;
    });
    mCanvas.screen.place("strip:" + std::to_string(id), toggleRect);
    mCanvas.screen.place("title:" + std::to_string(id), v.title);
    mCanvas.screen.place("cell:" + std::to_string(id), v.image);

    // The image, framed; the background batch is drawn before the images.
    mBackground->rect({v.image.min - 1.0f, v.image.max + 1.0f}, focused ? kHighlight : kPanel);
    if (!v.pane.plots.empty()) {
        // The technique's plots of this intermediate, stacked (its image is what `render --layer` writes).
        // No colour bar: the one the view had when it showed an image is gone with it.
        v.colourBar = {};
        drawPlots(v);
        mCanvas.screen.placeView({v.pane.id, title + early + counts, v.image, id});
        drawStatusBands(dl, v.image);
        if (v.display.stripOpen && v.strip.size().y > 0.0f) drawStrip(id, v);
        return;
    }
    mCanvas.panes.push_back({v.image, &v.pane, &v.transform, resolveMapping(v.pane, v.display, mState.exposure, v.measured)});
    mCanvas.screen.placeView({mHaveOutput ? (v.pane.id.empty() ? v.content : v.pane.id) : std::string("none"),
                       title + early + counts, v.image, id});
    if (!v.pane.unavailable.empty())
        dl.textClipped({v.image.min.x + 8.0f * s, v.image.min.y + 8.0f * s}, v.pane.unavailable, kDim, v.image.max.x);
    if (v.pane.texture != 0) texelValues(v);

    // Linked cursors: the hovered frame pixel in every other screen-space view; what the technique
    // can map of it in algorithm-space views (the epipolar row in minmax's rectified map, ...).
    std::optional<glm::ivec2> readAt;
    if (v.pane.texture != 0 && id == mHoveredView && v.image.contains(mHover))
        readAt = texelUnder(v.pane.size, v.image, v.transform, mHover);
    if (mLinkedPixel && isScreenSpace(v)) {
        // The hovered view marks its own pixel too (the cross leaves the pixel's centre free), so
        // that screenshots and a projector show which pixel the others follow.
        if (id != mHoveredView) readAt = *mLinkedPixel;
        const glm::dvec2 uv = (glm::dvec2(*mLinkedPixel) + 0.5) / glm::dvec2(v.pane.size);
        drawCrosshair(dl, v.image.min + glm::vec2(v.transform.uvToPane(uv)) * v.image.size(), v.image, mScale);
    }
    if (mLinkedPixel && !isScreenSpace(v) && v.pane.texture != 0) drawViewMarkers(dl, *mFont, mScale, v, markersFor(v));
    if (isScreenSpace(v)) mInspector.mark(dl, v.image, v.transform, mState.size, mScale);
    drawGizmo(dl, id, v);

    drawColourBar(id, v);
    // The value under the cursor (or at the linked pixel), from the view's CPU copy.
    const glm::vec2 readoutAt{v.image.min.x, std::max(v.image.max.y, v.bar.max.y) + 3.0f * s};
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

void GuiApp::drawPlots(const ViewState& v) {
    const float gap = 4.0f * mScale;
    const int n = int(v.pane.plots.size());
    const float h = (v.image.size().y - gap * float(n - 1)) / float(n);
    for (int i = 0; i < n; ++i) {
        const float top = v.image.min.y + float(i) * (h + gap);
        viz::plot::drawPlot(*mDrawList, {{v.image.min.x, top}, {v.image.max.x, top + h}},
                            plotSpecOf(v.pane.plots[std::size_t(i)]));
    }
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

void GuiApp::drawStatusBands(DrawList& dl, const Rect& image) {
    const auto band = [&](const ProgressBand& b) {
        const Rect r{{image.min.x, image.max.y - mFont->lineHeight() - 10.0f * mScale}, image.max};
        dl.rect(r, {0.0f, 0.0f, 0.0f, 0.65f});
        if (b.fraction >= 0.0f)
            dl.rect({{r.min.x, r.max.y - 3.0f * mScale}, {r.min.x + b.fraction * r.size().x, r.max.y}}, kAccent);
        dl.textClipped({r.min.x + 6.0f * mScale, r.min.y + 3.0f * mScale}, b.text, kText, r.max.x);
    };
    if (mRendering) band({renderingText(mHaveOutput, mLastRunSeconds)});
    const CpuProgress progress = cpuWorker().progress();
    if (progress.busy && !technique().needsGl()) band(cpuProgressBand(progress));
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
