// One view cell, laid out and drawn (view_cell.h).
#include "view_cell.h"

#include <epoxy/gl.h>

#include <algorithm>

#include "colour_bar.h"
#include "colour_bar_draw.h"
#include "colour_bar_images.h"
#include "display_strip.h"
#include "image_fit.h"
#include "texel_labels.h"
#include "view_markers.h"
#include "window_common.h"
#include "plot/plot.h"

namespace airlight {

namespace {

// Zoomed in until a texel holds its value: the value written in every visible texel (texel_labels.h),
// from the view's CPU copy (what its readout and statistics use); while there is none (during an
// interaction), a read of the visible block. GL rows: flipped textures keep row 0 at the bottom.
void drawCellTexelValues(const ViewCellFrame& f, const ViewState& v) {
    const PaneImage& pane = v.pane;
    const viz::ui::FontAtlas& font = *f.canvas->font;
    DrawList& dl = *f.canvas->overlay;
    const std::optional<TexelBlock> block = labelledTexels(pane.size, v.image, v.transform, font.lineHeight());
    if (!block) return;
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
    const float line = font.lineHeight();
    for (const TexelLabel& l : texelLabels(*block, pane.size, v.image, v.transform, pane.channels, value, font, f.canvas->scale)) {
        dl.rect({l.at - 1.0f, l.at + glm::vec2(font.measure(l.text) + 1.0f, line)}, {0.0f, 0.0f, 0.0f, 0.55f});
        dl.textClipped(l.at, l.text, kText, l.clipX);
    }
}

// The colour bar under an image view: what its mapping means, the special values' and a mask's counts.
void drawCellColourBar(const ViewCellFrame& f, int id, ViewState& v) {
    FrameCanvas& canvas = *f.canvas;
    v.colourBar = {};
    if (v.bar.size().y <= 0.0f) return;
    const DisplayMapping mapping = resolveMapping(v.pane, v.display, f.exposure, v.measured);
    v.colourBar = colourBarFor(v.pane, mapping, v.counts);
    // A mask's count, once per values and mapping (a large image costs milliseconds to count).
    const auto& memo = v.maskMemo;
    if (mapping.mode == DisplayMode::Mask &&
        !(memo && memo->lo == mapping.lo && memo->hi == mapping.hi && memo->channel == mapping.channel &&
          memo->log == mapping.logScale))
        if (const auto pixels = countMaskPixels(mapping, v.values, v.meaningful, v.pane.sentinels))
            v.maskMemo = ViewState::MaskMemo{mapping.lo, mapping.hi, mapping.channel, mapping.logScale, *pixels};
    if (mapping.mode == DisplayMode::Mask && v.maskMemo) describeMaskPixels(v.colourBar, v.maskMemo->pixels);
    if (v.colourBar.kind == ColourBar::Kind::None) return;
    const ColourBarLayout layout = drawColourBarText(v.colourBar, v.bar, *canvas.font, canvas.scale, *canvas.overlay,
                                                     *canvas.background, {kText, kDim, kError, kDim});
    v.ramp = layout.ramp;
    for (const BarImageDraw& d : barImageDraws(v, layout, mapping)) canvas.panes.push_back({d.rect, d.pane, d.view, d.mapping});
    canvas.screen.place("colour_bar:" + std::to_string(id), v.bar);
    if (v.bar.contains(f.hover)) f.ui->tooltipNow({layout.heading, layout.legend});
}

// The technique's plots of this intermediate, stacked in the image area.
void drawCellPlots(const ViewCellFrame& f, const ViewState& v) {
    const float gap = 4.0f * f.canvas->scale;
    const int n = int(v.pane.plots.size());
    const float h = (v.image.size().y - gap * float(n - 1)) / float(n);
    for (int i = 0; i < n; ++i) {
        const float top = v.image.min.y + float(i) * (h + gap);
        viz::plot::drawPlot(*f.canvas->overlay, {{v.image.min.x, top}, {v.image.max.x, top + h}},
                            plotSpecOf(v.pane.plots[std::size_t(i)]));
    }
}

// "rendering..." while a slow GPU run blocks, the CPU worker's progress while it computes.
void drawCellBands(const ViewCellFrame& f, const Rect& image) {
    const float s = f.canvas->scale;
    DrawList& dl = *f.canvas->overlay;
    for (const ProgressBand& b : f.bands) {
        const Rect r{{image.min.x, image.max.y - f.canvas->line() - 10.0f * s}, image.max};
        dl.rect(r, {0.0f, 0.0f, 0.0f, 0.65f});
        if (b.fraction >= 0.0f) dl.rect({{r.min.x, r.max.y - 3.0f * s}, {r.min.x + b.fraction * r.size().x, r.max.y}}, kAccent);
        dl.textClipped({r.min.x + 6.0f * s, r.min.y + 3.0f * s}, b.text, kText, r.max.x);
    }
}

// The title bar: highlighted when focused (keys and the views list act on it). Not the complete
// algorithm: every view says where the run stopped, in the warning colour; then its negative, NaN and
// Inf pixels. Too long for the bar (a small view, a large UI scale): the warnings kept whole first, then
// the title's first sections, the full text shown while the title is hovered. Returns the whole title.
std::string drawCellTitle(const ViewCellFrame& f, int id, ViewState& v, const ViewCellParts& parts) {
    FrameCanvas& canvas = *f.canvas;
    DrawList& dl = *canvas.overlay;
    const viz::ui::FontAtlas& font = *canvas.font;
    const float line = font.lineHeight(), s = canvas.scale;
    const bool focused = id == f.focused;
    const auto [title, note] = viewTitle(v, f.title);
    canvas.background->rect(v.title, focused ? kHighlight : kPanel);
    const std::string toggle = v.display.stripOpen ? "display -" : "display +";
    const float toggleWidth = font.measure(toggle) + 16.0f * s;
    const Rect toggleRect{{v.title.max.x - toggleWidth, v.title.min.y + 1.0f * s},
                          {v.title.max.x - 2.0f * s, v.title.min.y + line + 2.0f * s}};
    const TitleWarnings warn = titleWarnings(v, f.haveOutput ? f.stoppedEarly : std::string(), f.exposure);
    const float left = v.title.min.x + 4.0f * s;
    const FittedTitle fit =
        fitTitleBar(font, title, warn, note, toggleRect.min.x - 4.0f * s - left, v.title.max.x - 4.0f * s - left);
    float x = dl.textClipped({left, v.title.min.y + 2.0f * s}, fit.title, kAccent, toggleRect.min.x - 4.0f * s);
    if (!fit.early.empty()) x = dl.textClipped({x, v.title.min.y + 2.0f * s}, fit.early, kError, toggleRect.min.x - 4.0f * s);
    if (!warn.counts.empty()) dl.textClipped({x, v.title.min.y + 2.0f * s}, warn.counts, kError, toggleRect.min.x - 4.0f * s);
    dl.textClipped({left, v.title.min.y + 2.0f * s + line}, fit.note, kDim, v.title.max.x - 4.0f * s);
    v.titleElided = fit.titleElided;
    v.noteElided = fit.noteElided;
    if ((v.titleElided || v.noteElided) && v.title.contains(f.hover) && !toggleRect.contains(f.hover))
        f.ui->tooltipNow({title + warn.early + warn.counts, note});
    listEntry(canvas, f.hover, toggleRect, toggle, v.display.stripOpen,
              parts.toggleStrip ? parts.toggleStrip : std::function<void()>([] {}));  // a click never calls an empty function
    canvas.screen.place("strip:" + std::to_string(id), toggleRect);
    canvas.screen.place("title:" + std::to_string(id), v.title);
    canvas.screen.place("cell:" + std::to_string(id), v.image);
    return title + warn.early + warn.counts;
}

// The colour bar's height for this view: none for plots, an empty pane or before any run.
float viewColourBarHeight(const ViewCellFrame& f, const ViewState& v) {
    if (!v.pane.plots.empty() || v.pane.texture == 0 || !f.haveOutput) return 0.0f;
    return colourBarHeight(*f.canvas->font, f.canvas->scale);
}

}  // namespace


void layOutViewCell(const ViewCellFrame& f, ViewState& v, const Rect& cell) {
    const float line = f.canvas->line(), s = f.canvas->scale;
    v.cell = cell;
    v.title = {cell.min, {cell.max.x, cell.min.y + 2.0f * line + 4.0f * s}};
    const float readout = line + 6.0f * s;
    float stripHeight = 0.0f;
    if (v.display.stripOpen)
        stripHeight = std::min(displayStripHeight(v.display, cell.size().x, f.ui->rowHeight(), s),
                               0.6f * (cell.size().y - v.title.size().y - readout));
    // The colour bar goes under the image when the cell leaves the image most of its height.
    float barHeight = viewColourBarHeight(f, v);
    if (barHeight > 0.25f * (cell.size().y - v.title.size().y - readout - stripHeight)) barHeight = 0.0f;
    const Rect imageArea{{cell.min.x, v.title.max.y}, {cell.max.x, cell.max.y - readout - stripHeight - barHeight}};
    const glm::ivec2 aspect = v.pane.size.x > 0 && v.pane.size.y > 0 ? v.pane.size : f.frameSize;
    v.image = v.pane.plots.empty() ? fitImageRect(imageArea, aspect) : imageArea;  // plots take the whole area
    v.bar = barHeight > 0.0f ? Rect{{cell.min.x, v.image.max.y + 2.0f * s}, {cell.max.x, v.image.max.y + barHeight}} : Rect{};
    v.strip = stripHeight > 0.0f ? Rect{{cell.min.x, cell.max.y - stripHeight}, cell.max} : Rect{};
}

ViewCellDrawn drawViewCell(const ViewCellFrame& f, int id, ViewState& v, const ViewCellParts& parts) {
    FrameCanvas& canvas = *f.canvas;
    DrawList& dl = *canvas.overlay;
    const float s = canvas.scale;
    ViewCellDrawn drawn;
    const std::string title = drawCellTitle(f, id, v, parts);
    drawn.titleElided = v.titleElided;

    // The image, framed; the background batch is drawn before the images.
    canvas.background->rect({v.image.min - 1.0f, v.image.max + 1.0f}, id == f.focused ? kHighlight : kPanel);
    if (!v.pane.plots.empty()) {
        // The technique's plots of this intermediate (its image is what `render --layer` writes). No
        // colour bar: the one the view had when it showed an image is gone with it.
        v.colourBar = {};
        drawCellPlots(f, v);
        canvas.screen.placeView({v.pane.id, title, v.image, id});
        drawCellBands(f, v.image);
        return drawn;
    }
    canvas.panes.push_back({v.image, &v.pane, &v.transform, resolveMapping(v.pane, v.display, f.exposure, v.measured)});
    canvas.screen.placeView({f.haveOutput ? (v.pane.id.empty() ? v.content : v.pane.id) : std::string("none"), title,
                             v.image, id});
    if (!v.pane.unavailable.empty())
        dl.textClipped({v.image.min.x + 8.0f * s, v.image.min.y + 8.0f * s}, v.pane.unavailable, kDim, v.image.max.x);
    if (v.pane.texture != 0) drawCellTexelValues(f, v);

    // Linked cursors: the hovered frame pixel in every other screen-space view; what the technique
    // can map of it in algorithm-space views (the epipolar row in minmax's rectified map, ...).
    std::optional<glm::ivec2> readAt;
    const bool hovered = id == f.hovered;
    if (v.pane.texture != 0 && hovered && v.image.contains(f.hover))
        readAt = texelUnder(v.pane.size, v.image, v.transform, f.hover);
    if (f.linkedPixel && parts.screenSpace) {
        // The hovered view marks its own pixel too (the cross leaves the pixel's centre free), so
        // that screenshots and a projector show which pixel the others follow.
        if (!hovered) readAt = *f.linkedPixel;
        const glm::dvec2 uv = (glm::dvec2(*f.linkedPixel) + 0.5) / glm::dvec2(v.pane.size);
        drawCrosshair(dl, v.image.min + glm::vec2(v.transform.uvToPane(uv)) * v.image.size(), v.image, s);
    }
    if (f.linkedPixel && !parts.screenSpace && v.pane.texture != 0 && parts.markers)
        drawViewMarkers(dl, *canvas.font, s, v, parts.markers());
    if (parts.overlays) parts.overlays(dl);
    drawCellColourBar(f, id, v);

    // The value under the cursor (or at the linked pixel), from the view's CPU copy.
    if (readAt) {
        glm::vec4 value(0.0f);
        if (!valueAt(v, *readAt, value)) {
            const int glRow = v.pane.flipY ? v.pane.size.y - 1 - readAt->y : readAt->y;
            glGetTextureSubImage(v.pane.texture, 0, readAt->x, glRow, 0, 1, 1, 1, GL_RGBA, GL_FLOAT, sizeof value, &value);
        }
        drawn.readout = (hovered ? "pixel (" : "linked (") + std::to_string(readAt->x) + ", " + std::to_string(readAt->y) +
                        ")  =";
        for (int c = 0; c < std::clamp(v.pane.channels, 1, 3); ++c) drawn.readout += format("  %.4g", value[c]);
        const glm::vec2 readoutAt{v.image.min.x, std::max(v.image.max.y, v.bar.max.y) + 3.0f * s};
        dl.textClipped(readoutAt, drawn.readout, kText, v.cell.max.x);
    }
    drawCellBands(f, v.image);
    return drawn;
}

}  // namespace airlight
