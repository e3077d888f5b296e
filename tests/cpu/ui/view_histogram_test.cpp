// The histogram under an image view: per-cent heights, bin edges, the marked range, the title.
#include <gtest/gtest.h>

#include "view_histogram.h"

namespace airlight {
namespace {

DisplayMapping greyRange(float lo, float hi) {
    DisplayMapping m;
    m.mode = DisplayMode::Grey;
    m.lo = lo;
    m.hi = hi;
    return m;
}

TEST(ViewHistogram, HeightsArePerCentOfEveryCountedValueAsSteps) {
    // 8 values: 2 below the bins, 1 and 3 in them, 2 above: 12.5 % and 37.5 %.
    Histogram h;
    h.bins = {1, 3};
    h.below = 2;
    h.above = 2;
    h.lo = 0.0f;
    h.hi = 1.0f;
    const viz::plot::PlotSpec spec = histogramPlot(h, true, DisplayMapping{});
    ASSERT_EQ(spec.series.size(), 1u);  // HDR colour maps no range: nothing marked
    const std::vector<glm::dvec2> expected = {{0.0, 12.5}, {0.5, 12.5}, {0.5, 37.5}, {1.0, 37.5}};
    EXPECT_EQ(spec.series[0].points, expected);
    EXPECT_FALSE(spec.logX);
    EXPECT_EQ(spec.title, "% of values per bin");
}

TEST(ViewHistogram, LogarithmicBinsHaveDecadeEdges) {
    Histogram h;
    h.bins = {1, 1};
    h.lo = 1.0f;
    h.hi = 100.0f;
    h.logarithmic = true;
    const viz::plot::PlotSpec spec = histogramPlot(h, true, DisplayMapping{});
    EXPECT_TRUE(spec.logX);
    ASSERT_EQ(spec.series[0].points.size(), 4u);
    const double xs[] = {1.0, 10.0, 10.0, 100.0};
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(spec.series[0].points[std::size_t(i)].x, xs[i], 1e-9 * xs[i]) << i;
}

TEST(ViewHistogram, TheShownRangeIsMarkedInsideTheDataAndNamedByTheAxis) {
    Histogram h;
    h.bins = {2, 6};
    h.lo = 0.0f;
    h.hi = 1.0f;
    // Both ends inside: two lines from 0 to the tallest bar (75 %), in the colour the axis label names.
    viz::plot::PlotSpec spec = histogramPlot(h, true, greyRange(0.25f, 0.75f));
    ASSERT_EQ(spec.series.size(), 3u);
    const std::vector<glm::dvec2> low = {{0.25, 0.0}, {0.25, 75.0}}, high = {{0.75, 0.0}, {0.75, 75.0}};
    EXPECT_EQ(spec.series[1].points, low);
    EXPECT_EQ(spec.series[2].points, high);
    EXPECT_EQ(spec.series[1].colour, kShownRangeColour);
    EXPECT_EQ(spec.xLabel, "blue: range shown");
    // The upper end beyond the data: only the lower one.
    spec = histogramPlot(h, true, greyRange(0.25f, 4.0f));
    ASSERT_EQ(spec.series.size(), 2u);
    EXPECT_EQ(spec.series[1].points[0].x, 0.25);
    EXPECT_EQ(spec.xLabel, "blue: range shown");
    // Both outside: nothing marked, nothing named.
    spec = histogramPlot(h, true, greyRange(-2.0f, 4.0f));
    EXPECT_EQ(spec.series.size(), 1u);
    EXPECT_EQ(spec.xLabel, "");
}

TEST(ViewHistogram, AViewWithoutValuesSaysSo) {
    const viz::plot::PlotSpec spec = histogramPlot(Histogram{}, false, greyRange(0.0f, 1.0f));
    EXPECT_EQ(spec.title, "histogram: no values");
    ASSERT_EQ(spec.series.size(), 1u);
    EXPECT_TRUE(spec.series[0].points.empty());
}

}  // namespace
}  // namespace airlight
