#include "colour_bar_draw.h"

#include <algorithm>

#include "plot/plot.h"
#include "window_common.h"

namespace airlight {

float colourBarHeight(const viz::ui::FontAtlas& font, float scale) { return 2.0f * font.lineHeight() + 8.0f * scale; }

ColourBarLayout drawColourBarText(const ColourBar& bar, const Rect& area, const viz::ui::FontAtlas& font, float scale,
                                  DrawList& text, DrawList& frames, const ColourBarColours& colours) {
    ColourBarLayout out;
    const float line = font.lineHeight(), s = scale;
    // Left: the ramp over about half the width (at least 120 px), ticks under it; right: the legend
    // under the units and caption.
    const bool picture = bar.kind == ColourBar::Kind::Picture;  // no map: the caption and legend alone
    const float rampWidth = picture ? 0.0f : std::min(area.size().x - 8.0f * s, std::max(120.0f * s, 0.5f * area.size().x));
    out.ramp = {{area.min.x + 4.0f * s, area.min.y + 3.0f * s},
                {area.min.x + 4.0f * s + rampWidth, area.min.y + 3.0f * s + 0.8f * line}};
    const Rect& ramp = out.ramp;
    if (!picture) frames.rect({ramp.min - 1.0f, ramp.max + 1.0f}, colours.frame);
    const float labelY = ramp.max.y + 2.0f * s;
    if (bar.kind == ColourBar::Kind::Ramp) {
        // Tick marks at the values; labels centred under them but kept inside the bar, and dropped where
        // they would touch a neighbour where they are drawn (the last one is pushed left at the end).
        std::vector<float> centres, widths, placed;
        for (std::size_t i = 0; i < bar.ticks.size(); ++i) {
            centres.push_back(ramp.min.x + bar.tickAt[i] * ramp.size().x);
            widths.push_back(font.measure(bar.tickLabels[i]));
            const float x = std::clamp(centres[i] - 0.5f * widths[i], area.min.x, ramp.max.x - widths[i]);
            placed.push_back(x + 0.5f * widths[i]);
        }
        const std::vector<bool> kept = viz::plot::keptTickLabels(placed, widths, 6.0f * s);
        for (std::size_t i = 0; i < bar.ticks.size(); ++i) {
            text.line({centres[i], ramp.max.y - 3.0f * s}, {centres[i], ramp.max.y + 1.0f * s}, 1.0f * s, colours.text);
            if (!kept[i]) continue;
            text.textClipped({placed[i] - 0.5f * widths[i], labelY}, bar.tickLabels[i], colours.text, area.max.x);
        }
    } else if (bar.kind == ColourBar::Kind::Classes) {
        // One segment per class, its label centred under it.
        const float segment = ramp.size().x / float(std::max<std::size_t>(1, bar.values.size()));
        for (std::size_t i = 0; i < bar.classLabels.size(); ++i) {
            const float w = font.measure(bar.classLabels[i]);
            if (w > segment) continue;
            text.textClipped({ramp.min.x + (float(i) + 0.5f) * segment - 0.5f * w, labelY}, bar.classLabels[i],
                             colours.text, area.max.x);
        }
    }
    const float right = picture ? area.min.x + 4.0f * s : ramp.max.x + 10.0f * s;
    const auto headingWith = [&](const std::string& caption) {
        std::string h = bar.units.empty() ? caption : (caption.empty() ? bar.units : bar.units + "   " + caption);
        return bar.logarithmic ? h + "   (log)" : h;
    };
    const float headingRoom = area.max.x - right - 2.0f * s;
    std::string heading = headingWith(bar.caption);
    if (font.measure(heading) > headingRoom && !bar.shortCaption.empty()) heading = headingWith(bar.shortCaption);
    out.heading = elideMiddle(font, heading, headingRoom);
    text.textClipped({right, area.min.y + 1.0f * s}, out.heading, colours.dim, area.max.x);
    float x = right;
    const float box = line - 4.0f * s;
    const auto entryOf = [](const LegendSwatch& sw) { return sw.label + " " + std::to_string(sw.pixels); };
    const auto width = [&](const std::string& entry) { return box + 3.0f * s + font.measure(entry) + 10.0f * s; };
    // The overlays (NaN, Inf, negative) are short and must show; a sentinel's meaning is long, so it gets
    // what they leave, cut at its end (the full entry is in the tooltip), rather than being dropped where it
    // does not fit whole.
    float overlays = 0.0f;
    for (const LegendSwatch& sw : bar.legend)
        if (!sw.sentinel) overlays += width(entryOf(sw));
    for (std::size_t i = 0; i < bar.legend.size(); ++i) {
        const LegendSwatch& sw = bar.legend[i];
        std::string entry = entryOf(sw);
        out.legend += (out.legend.empty() ? "" : "   ") + entry + " px";
        if (sw.sentinel && x + width(entry) + overlays > area.max.x) {
            const std::string count = " " + std::to_string(sw.pixels);
            const float room = area.max.x - overlays - x - width(count);
            if (room >= font.measure("0: ...")) entry = elideEnd(font, sw.label, room) + count;
        }
        if (x + box + font.measure(entry) > area.max.x) continue;
        const Rect swatch{{x, labelY + 2.0f * s}, {x + box, labelY + 2.0f * s + box}};
        frames.rect({swatch.min - 1.0f, swatch.max + 1.0f}, colours.frame);
        out.swatches.push_back({swatch, i});
        x += box + 3.0f * s;
        const bool alarming = !sw.sentinel && sw.pixels > 0;
        x = text.textClipped({x, labelY}, entry, alarming ? colours.alarm : colours.dim, area.max.x) + 10.0f * s;
    }
    return out;
}

}  // namespace airlight
