#include "view_figure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "colour_bar_images.h"
#include "gl/framebuffer.h"
#include "gl/readback.h"
#include "gl/texture.h"
#include "plot/plot.h"
#include "ui/offscreen.h"

namespace airlight {
namespace {

std::string figure(double v) { return shortNumber(v, 4); }

// What the colour bar says, as one line of text.
std::string captionOf(const ColourBar& bar, const DisplayMapping& m) {
    std::string text;
    if (bar.kind == ColourBar::Kind::Ramp) {
        text = "range [" + figure(bar.lo) + ", " + figure(bar.hi) + "]" + (bar.logarithmic ? " log" : "");
    } else if (bar.kind == ColourBar::Kind::Classes) {
        text = "classes " + figure(bar.lo) + " .. " + figure(bar.hi);
    } else if (bar.kind == ColourBar::Kind::Picture) {
        text = "a picture drawn by the technique (its caption's note explains the colours)";
        for (const LegendSwatch& sw : bar.legend) text += "; " + sw.label + ": " + std::to_string(sw.pixels) + " px";
        return text;
    }
    if (!bar.units.empty()) text += " " + bar.units;
    if (!bar.caption.empty()) text += "; " + bar.caption;
    if (m.mode == DisplayMode::HdrColour || m.mode == DisplayMode::RangeColour) text += "; exposure " + figure(m.exposure) + " EV";
    for (const LegendSwatch& sw : bar.legend) text += "; " + sw.label + ": " + std::to_string(sw.pixels) + " px";
    return text;
}

Figure plotFigure(const PaneImage& pane, const viz::ui::FontAtlas& font) {
    Figure f;
    const int n = int(pane.plots.size());
    const glm::ivec2 size{760, 300 * n};
    viz::ui::DrawList list(font);
    for (int i = 0; i < n; ++i) {
        const viz::plot::PlotSpec spec = plotSpecOf(pane.plots[std::size_t(i)]);
        viz::plot::drawPlot(list, {{0.0f, 300.0f * float(i)}, {float(size.x), 300.0f * float(i + 1) - 6.0f}}, spec);
        f.series += int(spec.series.size());
        f.caption += (f.caption.empty() ? "" : "; ") + pane.plots[std::size_t(i)].title;
    }
    f.plots = n;
    f.image = viz::ui::renderOffscreen(list, size, {1, 1, 1, 1});
    return f;
}

}  // namespace

Figure renderFigure(ViewState& view, float exposureStops, const viz::ui::FontAtlas& font) {
    PaneImage& pane = view.pane;
    if (!pane.plots.empty()) return plotFigure(pane, font);
    Figure f;
    if (pane.texture == 0 || pane.size.x <= 0 || pane.size.y <= 0) {
        f.caption = pane.unavailable;
        return f;
    }
    readBackValues(view);
    const DisplayMapping mapping = resolveMapping(pane, view.display, exposureStops, view.measured);
    view.colourBar = colourBarFor(pane, mapping, view.counts);
    if (const auto pixels = countMaskPixels(mapping, view.values, view.meaningful, pane.sentinels))
        describeMaskPixels(view.colourBar, *pixels);
    f.caption = captionOf(view.colourBar, mapping);

    // Whole texels up to the figure width (nearest-neighbour, as the window shows them), within the height.
    double scale = std::max(1, (kFigureWidth + pane.size.x - 1) / pane.size.x);
    while (scale > 1.0 && pane.size.y * scale > kFigureMaxHeight) scale -= 1.0;
    if (pane.size.y * scale > kFigureMaxHeight) scale = double(kFigureMaxHeight) / pane.size.y;
    f.texelScale = scale >= 1.0 ? int(scale) : 0;
    const glm::vec2 imageSize{float(pane.size.x * scale), float(pane.size.y * scale)};
    const float barHeight = colourBarHeight(font, 1.0f);
    const glm::ivec2 size{std::max(kFigureWidth, int(std::ceil(imageSize.x))), int(std::ceil(imageSize.y + barHeight + 4.0f))};
    const viz::ui::Rect imageRect{{0.5f * (float(size.x) - imageSize.x), 0.0f}, {0.5f * (float(size.x) + imageSize.x), imageSize.y}};
    const viz::ui::Rect barArea{{0.0f, imageSize.y + 4.0f}, glm::vec2(size)};

    viz::ui::DrawList frames(font), text(font);
    const ColourBarColours colours{{0.08f, 0.08f, 0.1f, 1.0f}, {0.3f, 0.3f, 0.34f, 1.0f}, {0.75f, 0.1f, 0.1f, 1.0f},
                                   {0.55f, 0.55f, 0.58f, 1.0f}};
    const ColourBarLayout layout = drawColourBarText(view.colourBar, barArea, font, 1.0f, text, frames, colours);
    const std::vector<BarImageDraw> bars = barImageDraws(view, layout, mapping);

    const viz::gl::Texture target = viz::gl::Texture::create(
        {.target = GL_TEXTURE_2D, .format = GL_RGBA8, .size = {size.x, size.y, 1}, .levels = 1, .label = "figure"});
    viz::gl::Framebuffer framebuffer = viz::gl::Framebuffer::create("figure");
    framebuffer.attachColour(0, target);
    framebuffer.checkComplete();
    framebuffer.bind();
    glViewport(0, 0, size.x, size.y);
    const glm::vec4 white(1.0f);
    glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 0, &white.r);
    viz::ui::TextRenderer renderer(font);
    renderer.draw(frames, size);
    const ImageDisplay display;
    display.draw(pane, imageRect, size, mapping);
    for (const BarImageDraw& d : bars) display.draw(*d.pane, d.rect, size, d.mapping, d.view ? *d.view : viz::ui::ImageViewTransform{});
    renderer.draw(text, size);
    viz::gl::Framebuffer::bindDefault();
    f.image = viz::ui::linearFromDisplay(viz::gl::readTexture(target));
    return f;
}

}  // namespace airlight
