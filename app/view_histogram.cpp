#include "view_histogram.h"

#include <algorithm>
#include <cmath>

namespace airlight {

viz::plot::PlotSpec histogramPlot(const Histogram& h, bool hasValues, const DisplayMapping& shown) {
    viz::plot::PlotSpec spec;
    // Short: the plot is a corner of the display strip, beside the channel picker.
    spec.title = hasValues ? "% of values per bin" : "histogram: no values";
    spec.logX = h.logarithmic;
    const std::size_t n = h.bins.size();
    const auto edge = [&](std::size_t i) {
        const double t = double(i) / double(std::max<std::size_t>(1, n));
        return h.logarithmic ? std::pow(10.0, std::log10(h.lo) + t * (std::log10(h.hi) - std::log10(h.lo)))
                             : h.lo + t * (double(h.hi) - double(h.lo));
    };
    std::size_t total = h.below + h.above;
    for (std::size_t c : h.bins) total += c;
    const double percent = 100.0 / double(std::max<std::size_t>(total, 1));
    viz::plot::Series counts{"", {0.85f, 0.45f, 0.05f, 1.0f}, {}, true, false};
    double top = 1.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double p = double(h.bins[i]) * percent;
        counts.points.push_back({edge(i), p});
        counts.points.push_back({edge(i + 1), p});
        top = std::max(top, p);
    }
    spec.series.push_back(std::move(counts));
    if (shown.mode == DisplayMode::HdrColour || n == 0) return spec;
    // The ends of the shown range, each a vertical line, named by the x axis's label (a legend would take
    // half of a plot this small). An end outside the data is left out: the axis would stretch to reach it.
    for (double x : {double(shown.lo), double(shown.hi)}) {
        if (x < h.lo || x > h.hi) continue;
        spec.series.push_back({"", kShownRangeColour, {{x, 0.0}, {x, top}}, true, false});
        spec.xLabel = "blue: range shown";
    }
    return spec;
}

}  // namespace airlight
