// Plot layout on the CPU: tick choice and that a drawn plot stays inside its rectangle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "plot/plot.h"
#include "ui/font.h"

namespace viz::plot {
namespace {

TEST(AxisTicks, LinearTicksAreOneTwoFiveStepsCoveringTheData) {
    const AxisTicks t = axisTicks(0.13, 0.87, false, 5);
    ASSERT_GE(t.values.size(), 3u);
    EXPECT_LE(t.lo, 0.13);
    EXPECT_GE(t.hi, 0.87);
    const double step = t.values[1] - t.values[0];
    EXPECT_NEAR(step, 0.2, 1e-12);
    for (std::size_t i = 1; i < t.values.size(); ++i) EXPECT_NEAR(t.values[i] - t.values[i - 1], step, 1e-12);
    EXPECT_EQ(t.labels.front(), "0");
    EXPECT_EQ(t.labels[1], "0.2");
}

TEST(AxisTicks, LogTicksAreDecadesAroundTheData) {
    const AxisTicks t = axisTicks(0.003, 0.9, true);
    EXPECT_DOUBLE_EQ(t.lo, 1e-3);
    EXPECT_DOUBLE_EQ(t.hi, 1.0);
    for (double v : t.values) {
        const double m = v / std::pow(10.0, std::floor(std::log10(v) + 1e-9));
        EXPECT_TRUE(std::abs(m - 1) < 1e-9 || std::abs(m - 2) < 1e-9 || std::abs(m - 5) < 1e-9) << v;
    }
    EXPECT_TRUE(std::is_sorted(t.values.begin(), t.values.end()));
}

TEST(AxisTicks, TinyAndHugeTicksKeepTheDigitsThatTellThemApart) {
    for (const double scale : {1e-4, 1e-7, 1e6}) {
        const AxisTicks t = axisTicks(0.0, 3.0 * scale, false, 6);  // steps of 0.5 scale
        ASSERT_GE(t.labels.size(), 5u);
        for (std::size_t i = 1; i < t.labels.size(); ++i) {
            EXPECT_NE(t.labels[i], t.labels[i - 1]) << scale;
            // Each label reads back as its tick.
            EXPECT_NEAR(std::stod(t.labels[i]), t.values[i], 1e-9 * t.values[i]) << t.labels[i];
        }
    }
}

TEST(AxisTicks, DegenerateAndInvalidRangesStillGiveAnAxis) {
    const AxisTicks a = axisTicks(3.0, 3.0, false);
    EXPECT_LT(a.lo, 3.0);
    EXPECT_GT(a.hi, 3.0);
    const AxisTicks b = axisTicks(NAN, 1.0, true);
    EXPECT_LT(b.lo, b.hi);
    EXPECT_FALSE(b.values.empty());
}

TEST(DrawPlot, EverythingLandsInsideTheArea) {
    const ui::FontAtlas font = ui::FontAtlas::bake(ui::FontAtlas::kDefaultFontPath, 14.0f);
    ui::DrawList list(font);
    PlotSpec spec;
    spec.title = "error against time";
    spec.xLabel = "ms";
    spec.yLabel = "relative L2";
    spec.logX = spec.logY = true;
    spec.series.push_back({"raymarch", categoricalColour(0), {{10, 1.0}, {40, 0.1}, {160, 0.01}, {-1, 0.5}}, true, true});
    spec.highlighted = {{10, 1.0}};
    spec.highlightName = "front";
    const ui::Rect area{{20, 30}, {500, 330}};
    drawPlot(list, area, spec);
    ASSERT_GT(list.vertices().size(), 100u);
    for (const ui::UiVertex& v : list.vertices()) {
        EXPECT_GE(v.position.x, area.min.x - 1e-3f);
        EXPECT_LE(v.position.x, area.max.x + 1e-3f);
        EXPECT_GE(v.position.y, area.min.y - 1e-3f);
        EXPECT_LE(v.position.y, area.max.y + 1e-3f);
    }
}

TEST(DrawPlot, ARangeIsABarThroughItsPointAndTheAxesMakeRoomForIt) {
    const ui::FontAtlas font = ui::FontAtlas::bake(ui::FontAtlas::kDefaultFontPath, 14.0f);
    const glm::vec4 colour = categoricalColour(2);
    const ui::Rect area{{0, 0}, {400, 300}};
    // The extent (x, y) of what is drawn in the series' colour: its markers, and its bars when it has some.
    auto extent = [&](const std::vector<glm::dvec2>& yRanges, const std::vector<glm::dvec2>& xRanges) {
        ui::DrawList list(font);
        PlotSpec spec;
        spec.logX = spec.logY = true;
        spec.series.push_back({"", colour, {{10.0, 10.0}, {10.0, 12.0}}, false, true, yRanges, xRanges});
        drawPlot(list, area, spec);
        glm::vec2 lo{INFINITY}, hi{-INFINITY};
        for (const ui::UiVertex& v : list.vertices()) {
            EXPECT_TRUE(v.position.x >= area.min.x - 1e-3f && v.position.x <= area.max.x + 1e-3f);
            EXPECT_TRUE(v.position.y >= area.min.y - 1e-3f && v.position.y <= area.max.y + 1e-3f);
            if (v.colour == ui::packColour(colour)) lo = glm::min(lo, v.position), hi = glm::max(hi, v.position);
        }
        return hi - lo;
    };
    const glm::vec2 markers = extent({}, {});
    EXPECT_LT(std::max(markers.x, markers.y), 40.0f);
    // From 1 to 1000 around 10: the axis spans the three decades and the bar runs across them.
    const glm::vec2 vertical = extent({{1.0, 1000.0}, {11.0, 13.0}}, {});
    EXPECT_GT(vertical.y, 0.5f * (area.max.y - area.min.y));
    EXPECT_LT(vertical.x, 40.0f);
    const glm::vec2 horizontal = extent({}, {{1.0, 1000.0}, {9.0, 11.0}});
    EXPECT_GT(horizontal.x, 0.5f * (area.max.x - area.min.x));
    EXPECT_LT(horizontal.y, 40.0f);
}

TEST(DrawPlot, ALegendTooLongForTheAreaIsCutShortAndStaysInside) {
    const ui::FontAtlas font = ui::FontAtlas::bake(ui::FontAtlas::kDefaultFontPath, 14.0f);
    PlotSpec spec;
    spec.logX = spec.logY = true;
    for (int i = 0; i < 12; ++i)
        spec.series.push_back({"technique " + std::to_string(i), categoricalColour(i), {{10.0 * (i + 1), 0.5 / (i + 1)}},
                               false, true});
    const ui::Rect area{{0, 0}, {360, 130}};  // room for a few legend lines only
    ui::DrawList list(font);
    drawPlot(list, area, spec);
    ASSERT_GT(list.vertices().size(), 50u);
    for (const ui::UiVertex& v : list.vertices()) {
        EXPECT_GE(v.position.y, area.min.y - 1e-3f);
        EXPECT_LE(v.position.y, area.max.y + 1e-3f);
    }
    // In a tall area every entry fits: more is drawn than in the short one.
    ui::DrawList tall(font);
    drawPlot(tall, {{0, 0}, {360, 600}}, spec);
    EXPECT_GT(tall.vertices().size(), list.vertices().size());
}

// The glyphs a draw list holds (quads textured from the atlas, not its white texel) and the rectangles
// of these colours (a legend's swatches, the markers), as rectangles.
std::vector<ui::Rect> glyphAndSwatchRects(const ui::DrawList& list, const ui::FontAtlas& font,
                                          const std::vector<glm::vec4>& colours) {
    std::vector<ui::Rect> rects;
    const auto& v = list.vertices();
    for (std::size_t i = 0; i + 5 < v.size(); i += 6) {
        bool keep = v[i].uv != font.whiteUv();
        for (glm::vec4 c : colours) keep = keep || v[i].colour == ui::packColour(c);
        if (keep) rects.push_back({glm::min(v[i].position, v[i + 2].position), glm::max(v[i].position, v[i + 2].position)});
    }
    return rects;
}

// The comparison grid's plot: six techniques in a small cell, the legend taller than the frame, so that
// its last entries stand beside the x axis's labels. No glyph or swatch may overlap another (a label
// centred on the frame's right end once ran under the legend: "10000" under vsv's swatch).
TEST(DrawPlot, TheLastXTickLabelAndTheLegendDoNotOverlap) {
    const ui::FontAtlas font = ui::FontAtlas::bake(ui::FontAtlas::kDefaultFontPath, 15.0f);
    PlotSpec spec;
    spec.xLabel = "run time (ms)";
    spec.yLabel = "relative L2";
    spec.logX = spec.logY = true;
    const char* names[] = {"raymarch", "slices", "polyvol", "minmax", "vsv", "ivsv"};
    const double ms[] = {57.8, 57.6, 2191.8, 303.0, 222.2, 247.8}, error[] = {0.00335, 0.0411, 0.0021, 0.00321, 0.0113, 0.0213};  // apart: markers are not labels
    std::vector<glm::vec4> colours;
    for (int i = 0; i < 6; ++i) {
        spec.series.push_back({names[i], categoricalColour(i), {{ms[i], error[i]}}, false, true});
        colours.push_back(categoricalColour(i));
    }
    for (float width : {300.0f, 356.0f, 420.0f}) {
        SCOPED_TRACE(width);
        ui::DrawList list(font);
        const ui::Rect area{{0, 0}, {width, 130}};
        drawPlot(list, area, spec);
        const std::vector<ui::Rect> glyphs = glyphAndSwatchRects(list, font, colours);
        ASSERT_GT(glyphs.size(), 40u);
        int overlaps = 0;
        for (std::size_t i = 0; i < glyphs.size(); ++i)
            for (std::size_t k = i + 1; k < glyphs.size(); ++k) {
                const glm::vec2 lo = glm::max(glyphs[i].min, glyphs[k].min), hi = glm::min(glyphs[i].max, glyphs[k].max);
                // Neighbouring glyphs of one word may touch by a pixel; a label under another overlaps more.
                if (hi.x - lo.x > 2.0f && hi.y - lo.y > 2.0f) ++overlaps;
            }
        EXPECT_EQ(overlaps, 0);
        for (const ui::UiVertex& v : list.vertices()) {
            EXPECT_LE(v.position.x, area.max.x + 1e-3f);
        }
    }
}

// A short area (a lesson step's grid of four views at 1280x720 gives a plot about 50 px) drops the title and
// the label lines before the plot: the series' markers are drawn inside the area, where it used to say
// "(too small for the plot)". A tall area keeps every line.
TEST(DrawPlot, AShortAreaDropsItsLabelLinesBeforeThePlot) {
    const ui::FontAtlas font = ui::FontAtlas::bake(ui::FontAtlas::kDefaultFontPath, 14.0f);
    PlotSpec spec;
    spec.title = "singular values of I";
    spec.xLabel = "i";
    spec.yLabel = "sigma_i";
    spec.logY = true;
    const glm::vec4 colour = categoricalColour(2);
    spec.series.push_back({"kept", colour, {{1, 1.0}, {2, 0.1}, {3, 0.01}, {4, 0.001}}, false, true});
    for (const float height : {50.0f, 70.0f, 100.0f, 400.0f}) {
        const ui::Rect area{{10, 20}, {370, 20 + height}};
        ui::DrawList list(font);
        drawPlot(list, area, spec);
        int inside = 0;  // untextured quads of the series' colour: its markers and its legend swatch
        const auto& quads = list.vertices();
        for (std::size_t i = 0; i + 5 < quads.size(); i += 6) {
            if (quads[i].uv != font.whiteUv() || quads[i].colour != ui::packColour(colour)) continue;
            const glm::vec2 lo = glm::min(quads[i].position, quads[i + 2].position);
            const glm::vec2 hi = glm::max(quads[i].position, quads[i + 2].position);
            inside += lo.x >= area.min.x && hi.x <= area.max.x && lo.y >= area.min.y && hi.y <= area.max.y;
        }
        EXPECT_GE(inside, 4) << "height " << height << ": the four points (and the legend swatch) are drawn";
        for (const ui::UiVertex& v : list.vertices()) {
            EXPECT_GE(v.position.y, area.min.y - 1e-3f) << height;
            EXPECT_LE(v.position.y, area.max.y + 1e-3f) << height;
        }
    }
}

TEST(KeptTickLabels, LabelsThatWouldTouchTheLastKeptOneAreLeftOut) {
    // 1-2-5 ticks on a narrow log axis: 100, 200, 500, 1000 at 20, 36, 58, 74 px, labels 21-28 px wide.
    const std::vector<bool> kept = keptTickLabels({20, 36, 58, 74}, {21, 21, 21, 28}, 4.0f);
    EXPECT_EQ(kept, (std::vector<bool>{true, false, true, false}));
    // Either direction on screen (a y axis runs upwards), and every label kept where there is room.
    EXPECT_EQ(keptTickLabels({100, 90, 60, 30}, {14, 14, 14, 14}, 0.0f), (std::vector<bool>{true, false, true, true}));
    EXPECT_EQ(keptTickLabels({0, 50, 100}, {20, 20, 20}, 4.0f), (std::vector<bool>{true, true, true}));
    EXPECT_TRUE(keptTickLabels({}, {}, 1.0f).empty());
}

TEST(DrawBarChart, BarsAreScaledToTheLargestValueAndStayInside) {
    const ui::FontAtlas font = ui::FontAtlas::bake(ui::FontAtlas::kDefaultFontPath, 14.0f);
    ui::DrawList list(font);
    BarChart chart{"stage times", {{"shadow_maps", 10.0, "10 ms"}, {"march", 40.0, "40 ms"}, {"compose", 0.0, "0 ms"}}};
    const ui::Rect area{{10, 10}, {310, 200}};
    const float used = drawBarChart(list, area, chart, {1, 1, 1, 1});
    EXPECT_NEAR(used, 4.0f * font.lineHeight(), 1e-3f);  // title + three rows
    // The bar quads are the solid ones (white uv); the longest is four times the first.
    std::vector<float> widths;
    const auto& v = list.vertices();
    for (std::size_t i = 0; i + 5 < v.size(); i += 6)
        if (v[i].uv == font.whiteUv() && v[i + 2].position.x > v[i].position.x)
            widths.push_back(v[i + 2].position.x - v[i].position.x);
    ASSERT_EQ(widths.size(), 2u);  // the zero bar has no width
    EXPECT_NEAR(widths[1] / widths[0], 4.0f, 1e-3f);
    for (const ui::UiVertex& q : v) {
        EXPECT_GE(q.position.x, area.min.x - 1e-3f);
        EXPECT_LE(q.position.x, area.max.x + 1e-3f);
    }
}

}  // namespace
}  // namespace viz::plot
