#include "display_strip.h"

#include <algorithm>

#include "plot/plot.h"
#include "view_histogram.h"

namespace airlight {

namespace {

constexpr float kStripSideBySide = 460.0f;  // a view at least this wide has its histogram beside the widgets
constexpr float kHistogramHeight = 110.0f;

}  // namespace

float displayStripHeight(const DisplaySettings& d, float cellWidth, float rowHeight, float scale) {
    const float rows = (d.range == RangeMode::Manual ? 8.0f : 6.0f) + (d.difference != DifferenceMode::Off ? 1.0f : 0.0f);
    float wanted = rows * (rowHeight + 4.0f * scale) + 8.0f * scale;
    if (cellWidth < kStripSideBySide * scale) wanted += kHistogramHeight * scale;
    return wanted;
}

StripAreas splitDisplayStrip(const viz::ui::Rect& strip, float scale) {
    StripAreas a{strip, strip};
    if (strip.size().x >= kStripSideBySide * scale) {
        const float split = strip.min.x + std::max(0.5f * strip.size().x, std::min(0.62f * strip.size().x, 360.0f * scale));
        a.widgets.max.x = split - 2.0f * scale;
        a.histogram.min.x = split + 2.0f * scale;
    } else {
        const float h = std::min(kHistogramHeight * scale, 0.45f * strip.size().y);
        a.widgets.max.y = strip.max.y - h - 2.0f * scale;
        a.histogram.min.y = strip.max.y - h;
    }
    return a;
}

StripChange displayStripWidgets(viz::ui::Context& ui, ViewState& v, float exposure,
                                const std::vector<std::string>& techniques, const std::string& tag) {
    DisplaySettings& d = v.display;
    const DisplaySettings before = d;
    int channel = int(d.channel), range = int(d.range), map = int(d.colourMap), difference = int(d.difference);
    if (ui.combo("channel" + tag, channel, channelChoices(v.pane))) d.channel = Channel(channel);
    if (ui.combo("range" + tag, range, rangeModeNames())) {
        if (RangeMode(range) == RangeMode::Manual) {
            const DisplayMapping m = resolveMapping(v.pane, d, exposure, v.measured);
            d.manualMin = m.lo;
            d.manualMax = m.hi;
        }
        d.range = RangeMode(range);
    }
    if (d.range == RangeMode::Manual) {
        const float span = v.finite.valid ? std::max(v.finite.hi - v.finite.lo, 1e-6f) : 1.0f;
        ui.dragFloat("min" + tag, d.manualMin, 0.004f * span, -1e30f, 1e30f);
        ui.dragFloat("max" + tag, d.manualMax, 0.004f * span, -1e30f, 1e30f);
    }
    ui.checkbox("log scale" + tag, d.logScale);
    if (ui.combo("colour map" + tag, map, colourMapNames())) d.colourMap = ColourMap(map);
    bool negative = resolveMapping(v.pane, d, exposure, v.measured).markNegative;
    if (ui.checkbox("mark negative (green)" + tag, negative)) d.markNegative = negative ? 1 : 0;
    ui.tooltip("NaN shows magenta and Inf cyan always; negative values green unless the map is diverging");
    const bool frameImage = v.content == "final" || v.content == "airlight";
    if (frameImage && ui.combo("difference" + tag, difference, differenceModeNames()))
        d.difference = DifferenceMode(difference);
    if (frameImage && d.difference != DifferenceMode::Off && !techniques.empty()) {
        int against = int(std::find(techniques.begin(), techniques.end(), d.against) - techniques.begin());
        if (against >= int(techniques.size())) against = 0;
        if (ui.combo("against" + tag, against, techniques)) d.against = techniques[std::size_t(against)];
    }
    if (d.difference != before.difference || d.against != before.against) return StripChange::Difference;
    if (d.channel != before.channel || d.range != before.range || d.logScale != before.logScale)
        return StripChange::Statistics;
    return StripChange::None;
}

void drawStripHistogram(viz::ui::DrawList& dl, const ViewState& v, float exposure, const viz::ui::Rect& area,
                        float scale, float lineHeight) {
    if (area.size().x < 80.0f * scale || area.size().y < 4.0f * lineHeight) return;
    const DisplayMapping shown = resolveMapping(v.pane, v.display, exposure, v.measured);
    viz::plot::drawPlot(dl, area, histogramPlot(v.histogram, !v.values.empty(), shown));
}

}  // namespace airlight
