#include "plot/plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "ui/theme.h"

namespace viz::plot {

namespace {

using ui::theme::kGridLine;
using ui::theme::kInk;
using ui::theme::kPaper;

std::string formatTick(double v, double step) {
    char buffer[32];
    const double magnitude = std::abs(v);
    if (v == 0.0) return "0";
    if (magnitude >= 1e5 || magnitude < 1e-3) {
        // As many significant digits as the step needs (2.5e-04 next to 2.0e-04, not 2e-04 twice).
        const int digits = std::clamp(int(std::ceil(std::log10(magnitude / std::abs(step)) - 1e-9)), 0, 6);
        std::snprintf(buffer, sizeof buffer, "%.*e", digits, v);
    } else {
        // Enough decimals to tell neighbouring ticks apart.
        const int decimals = std::clamp(int(std::ceil(-std::log10(step) - 1e-9)), 0, 6);
        std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
    }
    return buffer;
}

// Maps data to pixels along one axis.
struct AxisMap {
    double lo, hi;
    bool log;
    float p0, p1;  // pixel of lo, pixel of hi
    float operator()(double v) const {
        const double a = log ? std::log10(lo) : lo, b = log ? std::log10(hi) : hi;
        const double x = log ? std::log10(v) : v;
        return float(p0 + (p1 - p0) * (x - a) / (b - a));
    }
};

// The outline of a square of half-size r around c (the highlight marker).
void squareRing(ui::DrawList& list, glm::vec2 c, float r) {
    const glm::vec2 corners[4] = {{c.x - r, c.y - r}, {c.x + r, c.y - r}, {c.x + r, c.y + r}, {c.x - r, c.y + r}};
    for (int i = 0; i < 4; ++i) list.line(corners[i], corners[(i + 1) % 4], 1.5f, kInk);
}

bool usable(double v, bool log) { return std::isfinite(v) && (!log || v > 0.0); }

}  // namespace

AxisTicks axisTicks(double lo, double hi, bool logarithmic, int target) {
    AxisTicks t;
    if (!(lo <= hi) || !std::isfinite(lo) || !std::isfinite(hi)) lo = logarithmic ? 1.0 : 0.0, hi = lo;
    if (logarithmic) {
        lo = std::max(lo, std::numeric_limits<double>::min());
        hi = std::max(hi, lo);
        int first = int(std::floor(std::log10(lo) + 1e-9));
        int last = int(std::ceil(std::log10(hi) - 1e-9));
        if (last <= first) last = first + 1;
        t.lo = std::pow(10.0, first);
        t.hi = std::pow(10.0, last);
        const int decades = last - first;
        const int stride = std::max(1, decades / std::max(1, target));
        for (int e = first; e <= last; e += stride) {
            const double v = std::pow(10.0, e);
            t.values.push_back(v);
            t.labels.push_back(formatTick(v, v));
            if (decades <= 2 && e < last)
                for (double m : {2.0, 5.0}) {
                    t.values.push_back(m * v);
                    t.labels.push_back(formatTick(m * v, m * v));
                }
        }
        std::vector<std::size_t> order(t.values.size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
        std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return t.values[a] < t.values[b]; });
        AxisTicks sorted{t.lo, t.hi, {}, {}};
        for (std::size_t i : order) sorted.values.push_back(t.values[i]), sorted.labels.push_back(t.labels[i]);
        return sorted;
    }
    if (hi - lo <= 0.0) {
        const double pad = lo == 0.0 ? 1.0 : std::abs(lo) * 0.5;
        lo -= pad, hi += pad;
    }
    const double rough = (hi - lo) / std::max(1, target);
    const double decade = std::pow(10.0, std::floor(std::log10(rough)));
    double step = decade;
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * decade >= rough) {
            step = m * decade;
            break;
        }
    t.lo = std::floor(lo / step + 1e-9) * step;
    t.hi = std::ceil(hi / step - 1e-9) * step;
    for (double v = t.lo; v <= t.hi + step * 0.5; v += step) {
        const double snapped = std::abs(v) < step * 1e-9 ? 0.0 : v;
        t.values.push_back(snapped);
        t.labels.push_back(formatTick(snapped, step));
    }
    return t;
}

glm::vec4 categoricalColour(int i) {
    constexpr int n = int(ui::theme::kSeries.size());
    return ui::theme::kSeries[std::size_t(((i % n) + n) % n)];
}

std::vector<bool> keptTickLabels(const std::vector<float>& centres, const std::vector<float>& extents, float gap) {
    std::vector<bool> kept(centres.size(), false);
    bool any = false;
    float lastCentre = 0.0f, lastHalf = 0.0f;
    for (std::size_t i = 0; i < centres.size(); ++i) {
        const float half = 0.5f * extents[i];
        // The axis may run either way on screen (y grows downwards): the distance between centres counts.
        if (any && std::abs(centres[i] - lastCentre) < lastHalf + half + gap) continue;
        kept[i] = any = true;
        lastCentre = centres[i];
        lastHalf = half;
    }
    return kept;
}

void drawPlot(ui::DrawList& list, const ui::Rect& area, const PlotSpec& spec) {
    const ui::FontAtlas& font = list.font();
    const float line = font.lineHeight();
    list.rect(area, kPaper);

    // Data ranges over every usable point.
    double xlo = INFINITY, xhi = -INFINITY, ylo = INFINITY, yhi = -INFINITY;
    auto include = [&](glm::dvec2 p) {
        if (!usable(p.x, spec.logX) || !usable(p.y, spec.logY)) return;
        xlo = std::min(xlo, p.x), xhi = std::max(xhi, p.x), ylo = std::min(ylo, p.y), yhi = std::max(yhi, p.y);
    };
    for (const Series& s : spec.series)
        for (std::size_t i = 0; i < s.points.size(); ++i) {
            include(s.points[i]);
            if (i < s.yRanges.size() && usable(s.points[i].y, spec.logY))
                include({s.points[i].x, s.yRanges[i].x}), include({s.points[i].x, s.yRanges[i].y});
            if (i < s.xRanges.size() && usable(s.points[i].x, spec.logX))
                include({s.xRanges[i].x, s.points[i].y}), include({s.xRanges[i].y, s.points[i].y});
        }
    for (glm::dvec2 p : spec.highlighted) include(p);
    for (const Band& b : spec.bands)
        for (glm::dvec2 span : b.spans)
            if (usable(span.x, spec.logX) && usable(span.y, spec.logX)) xlo = std::min(xlo, span.x), xhi = std::max(xhi, span.y);
    if (!(xlo <= xhi)) xlo = xhi = spec.logX ? 1.0 : 0.0;
    if (!(ylo <= yhi)) ylo = yhi = spec.logY ? 1.0 : 0.0;
    const AxisTicks xt = axisTicks(xlo, xhi, spec.logX);
    const AxisTicks yt = axisTicks(ylo, yhi, spec.logY);

    // Layout: title on top, y tick labels and axis label on the left, x labels below, legend at right.
    float yLabelWidth = 0.0f;
    for (const std::string& l : yt.labels) yLabelWidth = std::max(yLabelWidth, font.measure(l));
    float legendWidth = 0.0f;
    for (const Series& s : spec.series) legendWidth = std::max(legendWidth, font.measure(s.name));  // "" adds 0
    for (const Band& b : spec.bands) legendWidth = std::max(legendWidth, font.measure(b.name));
    if (!spec.highlighted.empty()) legendWidth = std::max(legendWidth, font.measure(spec.highlightName));
    legendWidth += legendWidth > 0.0f ? line * 2.0f : 0.0f;
    const float pad = line * 0.5f;
    // The last x label is centred on the frame's right end: the legend (or the area's edge) starts past
    // its half.
    const float rightGap = std::max(pad, (xt.labels.empty() ? 0.0f : font.measure(xt.labels.back()) * 0.5f) + pad * 0.5f);
    // Lines above and below the frame: the title, the y label (on its own line), the x tick labels and the
    // x label. A short area drops the title, the y label's line, the x label and the x tick labels, in that
    // order, until the frame is a readable height (a view's own title already names the plot), rather than
    // giving up on the plot.
    bool title = !spec.title.empty(), yLabel = !spec.yLabel.empty(), xTicks = true, xLabel = true;
    ui::Rect frame;
    const auto place = [&] {
        frame.min = {area.min.x + pad + line + pad + yLabelWidth + pad,
                     area.min.y + pad + (title ? line + pad : 0.0f) + (yLabel ? line + pad : 0.0f)};
        frame.max = {area.max.x - rightGap - legendWidth,
                     area.max.y - pad - (xTicks ? line + pad : 0.0f) - (xLabel ? line + pad : 0.0f)};
    };
    place();
    for (bool* shown : {&title, &yLabel, &xLabel, &xTicks}) {
        if (frame.max.y - frame.min.y >= 1.5f * line) break;
        *shown = false;
        place();
    }
    // A narrow area drops the legend before the plot; one too small for any plot says so.
    bool legend = true;
    if (frame.max.x - frame.min.x < 10.0f && legendWidth > 0.0f) {
        frame.max.x += legendWidth;
        legend = false;
    }
    if (frame.max.x - frame.min.x < 10.0f || frame.max.y - frame.min.y < 10.0f) {
        list.textClipped(area.min + pad, "(too small for the plot)", kInk, area.max.x - pad);
        return;
    }

    const AxisMap mx{xt.lo, xt.hi, spec.logX, frame.min.x, frame.max.x};
    const AxisMap my{yt.lo, yt.hi, spec.logY, frame.max.y, frame.min.y};

    if (title) list.textClipped({frame.min.x, area.min.y + pad}, spec.title, kInk, area.max.x - pad);
    // Every tick gets its grid line; a label that would touch the one before it is left out (a narrow
    // log axis with 1-2-5 ticks).
    std::vector<float> xs, widths, ys, heights;
    for (std::size_t i = 0; i < xt.values.size(); ++i) xs.push_back(mx(xt.values[i])), widths.push_back(font.measure(xt.labels[i]));
    for (std::size_t i = 0; i < yt.values.size(); ++i) ys.push_back(my(yt.values[i])), heights.push_back(line);
    const std::vector<bool> keepX = keptTickLabels(xs, widths, pad), keepY = keptTickLabels(ys, heights, 0.0f);
    for (std::size_t i = 0; i < xt.values.size(); ++i) {
        const float x = xs[i];
        list.line({x, frame.min.y}, {x, frame.max.y}, 1.0f, kGridLine);
        list.line({x, frame.max.y}, {x, frame.max.y + pad * 0.6f}, 1.0f, kInk);
        if (keepX[i] && xTicks) list.text({x - widths[i] * 0.5f, frame.max.y + pad}, xt.labels[i], kInk);
    }
    for (std::size_t i = 0; i < yt.values.size(); ++i) {
        const float y = ys[i];
        list.line({frame.min.x, y}, {frame.max.x, y}, 1.0f, kGridLine);
        list.line({frame.min.x - pad * 0.6f, y}, {frame.min.x, y}, 1.0f, kInk);
        const float w = font.measure(yt.labels[i]);
        if (keepY[i]) list.text({frame.min.x - pad - w, y - line * 0.5f}, yt.labels[i], kInk);
    }
    // Frame.
    list.line(frame.min, {frame.max.x, frame.min.y}, 1.0f, kInk);
    list.line({frame.max.x, frame.min.y}, frame.max, 1.0f, kInk);
    list.line(frame.max, {frame.min.x, frame.max.y}, 1.0f, kInk);
    list.line({frame.min.x, frame.max.y}, frame.min, 1.0f, kInk);
    // Axis labels: x centred below the tick labels; y horizontal, on its own line above the frame.
    if (!spec.xLabel.empty() && xLabel) {
        const float w = font.measure(spec.xLabel);
        list.text({(frame.min.x + frame.max.x - w) * 0.5f, frame.max.y + pad + line + pad * 0.5f}, spec.xLabel, kInk);
    }
    if (yLabel) list.textClipped({area.min.x + pad, frame.min.y - line - pad}, spec.yLabel, kInk, frame.max.x);

    // Series, clipped to the frame by dropping points outside it (ranges cover every usable point).
    const float marker = std::max(2.0f, line * 0.22f);
    for (const Series& s : spec.series) {
        bool havePrevious = false;
        glm::vec2 previous{0.0f};
        for (std::size_t i = 0; i < s.points.size(); ++i) {
            const glm::dvec2 p = s.points[i];
            if (!usable(p.x, spec.logX) || !usable(p.y, spec.logY)) {
                havePrevious = false;
                continue;
            }
            const glm::vec2 q{mx(p.x), my(p.y)};
            // A range bar: along the axis from `lo` to `hi` (screen), with a cap across each end; `along`
            // is the unit vector of the bar's axis, the caps run along the other.
            const auto bar = [&](float lo, float hi, glm::vec2 along) {
                const glm::vec2 across{along.y, along.x};
                const glm::vec2 a = q + (lo - glm::dot(q, along)) * along, b = q + (hi - glm::dot(q, along)) * along;
                list.line(a, b, 1.0f, s.colour);
                for (glm::vec2 end : {a, b}) list.line(end - marker * across, end + marker * across, 1.0f, s.colour);
            };
            if (i < s.yRanges.size() && usable(s.yRanges[i].x, spec.logY) && usable(s.yRanges[i].y, spec.logY))
                bar(my(s.yRanges[i].x), my(s.yRanges[i].y), {0.0f, 1.0f});
            if (i < s.xRanges.size() && usable(s.xRanges[i].x, spec.logX) && usable(s.xRanges[i].y, spec.logX))
                bar(mx(s.xRanges[i].x), mx(s.xRanges[i].y), {1.0f, 0.0f});
            if (s.lines && havePrevious) list.line(previous, q, 1.6f, s.colour);
            if (s.markers) list.rect({q - marker, q + marker}, s.colour);
            previous = q;
            havePrevious = true;
        }
    }
    for (glm::dvec2 p : spec.highlighted) {
        if (!usable(p.x, spec.logX) || !usable(p.y, spec.logY)) continue;
        const glm::vec2 q{mx(p.x), my(p.y)};
        squareRing(list, q, marker * 2.2f);
    }

    // Bands: strips along the bottom of the frame, the first lowest.
    const float strip = std::max(3.0f, line * 0.3f);
    for (std::size_t k = 0; k < spec.bands.size(); ++k) {
        const float y1 = frame.max.y - 1.0f - float(k) * (strip + 1.0f), y0 = y1 - strip;
        for (glm::dvec2 span : spec.bands[k].spans) {
            if (!usable(span.x, spec.logX) || !usable(span.y, spec.logX)) continue;
            const float x0 = std::max(frame.min.x, mx(span.x)), x1 = std::min(frame.max.x, mx(span.y));
            if (x1 > x0) list.rect({{x0, y0}, {std::max(x1, x0 + 1.0f), y1}}, spec.bands[k].colour);
        }
    }

    // Legend: from the frame's top down; what does not fit above the area's bottom is counted in a last
    // line ("+3 more") instead of running out of the plot.
    float y = frame.min.y;
    const float x = frame.max.x + rightGap;
    int entries = int(spec.bands.size()) + (spec.highlighted.empty() ? 0 : 1);
    for (const Series& s : spec.series) entries += s.name.empty() ? 0 : 1;
    if (!legend) entries = 0;
    const int rows = std::max(1, int((area.max.y - pad - y) / line));
    int room = entries > rows ? rows - 1 : entries;
    const auto fits = [&]() { return room-- > 0; };
    for (const Series& s : spec.series) {
        if (s.name.empty()) continue;  // unnamed series (e.g. a line through another's points) stay out
        if (!fits()) break;
        list.rect({{x, y + line * 0.3f}, {x + line, y + line * 0.7f}}, s.colour);
        list.textClipped({x + line * 1.4f, y}, s.name, kInk, area.max.x - 2.0f);
        y += line;
    }
    for (const Band& b : spec.bands) {
        if (!fits()) break;
        list.rect({{x, y + line * 0.4f}, {x + line, y + line * 0.6f}}, b.colour);
        list.textClipped({x + line * 1.4f, y}, b.name, kInk, area.max.x - 2.0f);
        y += line;
    }
    if (!spec.highlighted.empty() && fits()) {
        const glm::vec2 c{x + line * 0.5f, y + line * 0.5f};
        squareRing(list, c, marker * 2.2f);
        list.textClipped({x + line * 1.4f, y}, spec.highlightName, kInk, area.max.x - 2.0f);
        y += line;
    }
    if (entries > rows) list.textClipped({x, y}, "+" + std::to_string(entries - rows + 1) + " more", kInk, area.max.x - 2.0f);
}

float drawBarChart(ui::DrawList& list, const ui::Rect& area, const BarChart& chart, glm::vec4 textColour) {
    const ui::FontAtlas& font = list.font();
    const float line = font.lineHeight();
    float y = area.min.y;
    if (!chart.title.empty()) {
        list.textClipped({area.min.x, y}, chart.title, textColour, area.max.x);
        y += line;
    }
    double largest = chart.scaleMax;
    float labelWidth = 0.0f, valueWidth = 0.0f;
    for (const Bar& b : chart.bars) {
        if (chart.scaleMax <= 0.0 && std::isfinite(b.value)) largest = std::max(largest, b.value);
        labelWidth = std::max(labelWidth, font.measure(b.label));
        valueWidth = std::max(valueWidth, font.measure(b.valueText));
    }
    const float gap = line * 0.5f;
    labelWidth = std::min(labelWidth, (area.max.x - area.min.x) * 0.45f);
    const float barStart = area.min.x + labelWidth + gap;
    const float barEnd = std::max(barStart, area.max.x - valueWidth - gap);
    for (const Bar& b : chart.bars) {
        if (y + line > area.max.y) break;
        list.textClipped({area.min.x, y}, b.label, textColour, area.min.x + labelWidth);
        const double f = largest > 0.0 && std::isfinite(b.value) ? std::clamp(b.value / largest, 0.0, 1.0) : 0.0;
        list.rect({{barStart, y + line * 0.2f}, {barStart + float(f) * (barEnd - barStart), y + line * 0.8f}}, b.colour);
        list.text({barEnd + gap, y}, b.valueText, textColour);
        y += line;
    }
    return y - area.min.y;
}

}  // namespace viz::plot
