// Line and scatter plots with axes, ticks and a legend, drawn into a ui::DrawList: the same code draws
// plots in the window and in files (report pages, handouts) through ui::renderOffscreen.
// Data coordinates are doubles; an axis may be logarithmic (base 10), which drops non-positive values.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "ui/text_renderer.h"

namespace viz::plot {

struct Series {
    std::string name;                 // legend entry; empty: not listed
    glm::vec4 colour{0, 0, 0, 1};      // display colour
    std::vector<glm::dvec2> points;   // drawn in the given order
    bool lines = true;                // join consecutive points
    bool markers = true;              // a square at each point
    // Optional, one per point: [low, high] on the y (or x) axis drawn as a bar through the point (the
    // spread of the measurements behind it); empty: no bars.
    std::vector<glm::dvec2> yRanges{}, xRanges{};
};

// Spans along the x axis (e.g. the lit intervals of a light along a ray), drawn as a strip along the
// bottom of the frame, one strip per band, listed in the legend.
struct Band {
    std::string name;
    glm::vec4 colour{0, 0, 0, 1};
    std::vector<glm::dvec2> spans;  // [x0, x1] in data units
};

struct PlotSpec {
    std::string title, xLabel, yLabel;
    bool logX = false, logY = false;
    std::vector<Series> series;
    std::vector<Band> bands;
    // Points drawn as hollow rings over the series (e.g. the Pareto front), with their own legend entry.
    std::vector<glm::dvec2> highlighted;
    std::string highlightName;
};

struct AxisTicks {
    double lo = 0.0, hi = 1.0;       // the axis range (data units), covering every tick
    std::vector<double> values;      // tick positions (data units), increasing
    std::vector<std::string> labels; // one per value
};

// Ticks for data in [lo, hi]: linear axes get 1-2-5 steps (about `target` ticks) and a range rounded out
// to whole steps; log axes get the decades around the data (and 2, 5 in between when they are few).
// A degenerate range is widened around its value.
AxisTicks axisTicks(double lo, double hi, bool logarithmic, int target = 6);

// Which tick labels to draw along an axis: centres[i] and extents[i] (label width along x, line height
// along y) in pixels, in tick order; a label that would come within `gap` of the last one kept is left
// out (its tick and grid line stay). The first label is always kept.
std::vector<bool> keptTickLabels(const std::vector<float>& centres, const std::vector<float>& extents, float gap);

// A distinct colour for series i (a fixed categorical palette that cycles).
glm::vec4 categoricalColour(int i);

// Draws the plot (background, frame, grid, ticks, labels, series, legend) inside `area`.
void drawPlot(ui::DrawList& list, const ui::Rect& area, const PlotSpec& spec);

// Horizontal bars, one row each: label, bar scaled to the largest value (or `scaleMax` when > 0), value
// text. Used for per-stage timings.
struct Bar {
    std::string label;
    double value = 0.0;
    std::string valueText;  // e.g. "12.3 ms"
    glm::vec4 colour{0.33f, 0.62f, 0.95f, 1.0f};
};
struct BarChart {
    std::string title;  // e.g. "stage times (glFinish+steady_clock)"
    std::vector<Bar> bars;
    double scaleMax = 0.0;
};
// Returns the height used (title + one row per bar), so callers can stack things below.
float drawBarChart(ui::DrawList& list, const ui::Rect& area, const BarChart& chart, glm::vec4 textColour);

}  // namespace viz::plot
