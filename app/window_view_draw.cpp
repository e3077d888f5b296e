// Drawing the view grid: each view's title, image, texel values, markers, plots, display strip and
// histogram, and the dividers between views.
#include "gui_app.h"
#include "progress_band.h"
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

glm::ivec2 GuiApp::texelAt(const PaneImage& pane, const Rect& image, const viz::ui::ImageViewTransform& view,
                          glm::vec2 p) {
    const glm::dvec2 uv = view.paneToUv(glm::dvec2((p - image.min) / image.size()));
    return glm::clamp(glm::ivec2(glm::floor(uv * glm::dvec2(pane.size))), glm::ivec2(0), pane.size - 1);
}

void GuiApp::texelValues(const PaneImage& pane, const Rect& image, const viz::ui::ImageViewTransform& view) {
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
    const ViewTitleFacts facts = viewTitleFacts();  // the same for every view of the frame
    for (const ViewCellRect& c : mCells) {
        ViewState& v = mViews.at(c.view);
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
    // Not the complete algorithm: every view says where the run stopped, in the warning colour.
    const std::string why = mHaveOutput ? stoppedEarly() : std::string();
    std::string early = why.empty() ? why : "   [" + why + "]";
    if (!v.standIn.empty()) early += "   [" + v.standIn + "]";
    const SpecialCounts& n = v.counts;
    // Negative values are a warning where the view would mark them (radiance, or asked for): in data such
    // as a plane's signed distance they are values, as the legend under the image treats them.
    const int negative = resolveMapping(v.pane, v.display, mState.exposure, v.measured).markNegative ? n.negative : 0;
    std::string counts;
    if (n.nan + n.inf + negative > 0) {
        counts = " ";
        if (negative) counts += " " + std::to_string(negative) + " negative";
        if (n.nan) counts += " " + std::to_string(n.nan) + " NaN";
        if (n.inf) counts += " " + std::to_string(n.inf) + " Inf";
        counts += " px";
    }
    // Too long for the bar (a small view, a large UI scale): each part shortened in the middle, the
    // warnings first kept whole, and the full text shown while the title is hovered.
    const float left = v.title.min.x + 4.0f * s, width = toggleRect.min.x - 4.0f * s - left;
    const float warnings = mFont->measure(early + counts);
    const std::string shownTitle = elideMiddle(*mFont, title, std::max(0.35f * width, width - warnings));
    const float rest = width - mFont->measure(shownTitle);
    const std::string shownEarly = elideMiddle(*mFont, early, std::max(0.0f, rest - mFont->measure(counts)));
    const std::string shownNote = elideMiddle(*mFont, note, v.title.max.x - 4.0f * s - left);
    float x = dl.textClipped({left, v.title.min.y + 2.0f * s}, shownTitle, kAccent, toggleRect.min.x - 4.0f * s);
    if (!shownEarly.empty()) x = dl.textClipped({x, v.title.min.y + 2.0f * s}, shownEarly, kError, toggleRect.min.x - 4.0f * s);
    if (!counts.empty()) dl.textClipped({x, v.title.min.y + 2.0f * s}, counts, kError, toggleRect.min.x - 4.0f * s);
    dl.textClipped({left, v.title.min.y + 2.0f * s + line}, shownNote, kDim, v.title.max.x - 4.0f * s);
    v.titleElided = shownTitle != title || shownEarly != early;
    v.noteElided = shownNote != note;
    const bool elided = v.titleElided || v.noteElided;
    if (elided && v.title.contains(mHover) && !toggleRect.contains(mHover))
        mUi->tooltipNow({title + early + counts, note});
    mElidedTitles += v.titleElided ? 1 : 0;
    listItem(toggleRect, toggle, v.display.stripOpen, [this, id] {
        ViewState& w = mViews.at(id);
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
