// A view's display strip (app/display_strip.h) driven by synthetic input, no window: where its widgets
// and histogram go, the height it asks for, which widgets it offers, and what each change asks the window
// to re-do.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "display_strip.h"
#include "cpu/ui/synthetic_panel.h"

namespace airlight {
namespace {

using viz::ui::Context;
using viz::ui::Rect;
using Panel = viz::ui::testing::SyntheticPanel;

const std::vector<std::string> kTechniques = {"raymarch", "slices", "reference"};

// A range-coloured intermediate whose measured range is -1 .. 7, shown by its min and max.
ViewState rangeView(const std::string& content) {
    ViewState v;
    v.content = content;
    v.pane.mode = DisplayMode::RangeColour;
    v.pane.rangeMin = 0.0f, v.pane.rangeMax = 1.0f;
    v.pane.size = {8, 8};
    v.display.range = RangeMode::MinMax;
    v.measured = ValueRange{-1.0f, 7.0f, true};
    v.finite = *v.measured;
    return v;
}

// Clicks the item `item` of the combo named `combo` (opening it first); returns what the strip changed on
// the click's frames.
StripChange pick(Panel& panel, ViewState& v, const std::string& combo, const std::string& item) {
    StripChange change = StripChange::None;
    const auto ui = [&](Context& c) {
        const StripChange k = displayStripWidgets(c, v, 0.0f, kTechniques, "##v1");
        if (k != StripChange::None) change = k;
    };
    panel.frame({}, ui);
    const glm::vec2 at = panel.centreOf(combo);
    panel.frame(Panel::at(at, true), ui);
    panel.frame(Panel::at(at, false), ui);
    const glm::vec2 entry = panel.centreOf(combo + "/" + item);
    panel.frame(Panel::at(entry, false), ui);
    panel.frame(Panel::at(entry, true), ui);
    panel.frame(Panel::at(entry, false), ui);
    return change;
}

TEST(DisplayStrip, AWideStripPutsTheHistogramBesideTheWidgetsAndANarrowOneUnderThem) {
    for (float scale : {1.0f, 2.0f}) {
        const Rect wide{{10.0f, 100.0f}, {10.0f + 900.0f * scale, 100.0f + 200.0f * scale}};
        const StripAreas a = splitDisplayStrip(wide, scale);
        EXPECT_LT(a.widgets.max.x, a.histogram.min.x);  // side by side, apart
        EXPECT_EQ(a.widgets.min, wide.min);
        EXPECT_EQ(a.histogram.max, wide.max);
        EXPECT_EQ(a.widgets.size().y, wide.size().y);
        EXPECT_GE(a.widgets.size().x, 0.5f * wide.size().x - 2.0f * scale);  // the widgets keep half or more

        const Rect narrow{{0.0f, 0.0f}, {300.0f * scale, 400.0f * scale}};
        const StripAreas b = splitDisplayStrip(narrow, scale);
        EXPECT_LT(b.widgets.max.y, b.histogram.min.y);  // stacked, apart
        EXPECT_EQ(b.widgets.size().x, narrow.size().x);
        EXPECT_EQ(b.histogram.max, narrow.max);
        EXPECT_LE(b.histogram.size().y, 0.45f * narrow.size().y + 1e-3f);
        EXPECT_GT(b.histogram.size().y, 0.0f);
        // A short strip gives the histogram at most 45 % of its height.
        const StripAreas c = splitDisplayStrip({{0.0f, 0.0f}, {300.0f * scale, 100.0f * scale}}, scale);
        EXPECT_NEAR(c.histogram.size().y, 45.0f * scale, 1e-3f);
    }
}

TEST(DisplayStrip, ItAsksForTwoRowsMoreForAManualRangeOneForADifferenceAndTheHistogramWhenNarrow) {
    const float row = 20.0f, wide = 1000.0f;
    DisplaySettings d;
    const float base = displayStripHeight(d, wide, row, 1.0f);
    EXPECT_NEAR(base, 6.0f * (row + 4.0f) + 8.0f, 1e-3f);
    d.range = RangeMode::Manual;
    EXPECT_NEAR(displayStripHeight(d, wide, row, 1.0f) - base, 2.0f * (row + 4.0f), 1e-3f);
    d.difference = DifferenceMode::Signed;
    EXPECT_NEAR(displayStripHeight(d, wide, row, 1.0f) - base, 3.0f * (row + 4.0f), 1e-3f);
    // Narrow: the histogram's own height on top; it goes under the widgets.
    const float narrowWidth = 200.0f;
    EXPECT_GT(displayStripHeight(d, narrowWidth, row, 1.0f), displayStripHeight(d, wide, row, 1.0f) + 50.0f);
    const StripAreas a = splitDisplayStrip({{0.0f, 0.0f}, {narrowWidth, displayStripHeight(d, narrowWidth, row, 1.0f)}}, 1.0f);
    EXPECT_GE(a.widgets.size().y, 9.0f * (row + 4.0f));  // the nine rows still fit above the histogram
}

TEST(DisplayStrip, OnlyTheFrameImagesOfferADifferenceAndOnlyAnOpenDifferenceAsksAgainstWhat) {
    for (const std::string content : {"final", "airlight", "minmax.tree"}) {
        SCOPED_TRACE(content);
        ViewState v = rangeView(content);
        Panel panel;
        panel.frame({}, [&](Context& c) { displayStripWidgets(c, v, 0.0f, kTechniques, "##v1"); });
        const bool frameImage = content != "minmax.tree";
        EXPECT_EQ(panel.ctx.widgetRects().count("difference##v1"), frameImage ? 1u : 0u);
        EXPECT_EQ(panel.ctx.widgetRects().count("against##v1"), 0u);
        for (const char* name : {"channel##v1", "range##v1", "log scale##v1", "colour map##v1"})
            EXPECT_EQ(panel.ctx.widgetRects().count(name), 1u) << name;
        EXPECT_EQ(panel.ctx.widgetRects().count("min##v1"), 0u);  // no manual range yet
        if (frameImage) {
            EXPECT_EQ(pick(panel, v, "difference##v1", "a - b"), StripChange::Difference);
            EXPECT_EQ(v.display.difference, DifferenceMode::Signed);
            EXPECT_EQ(panel.ctx.widgetRects().count("against##v1"), 1u);
            EXPECT_EQ(pick(panel, v, "against##v1", "slices"), StripChange::Difference);
            EXPECT_EQ(v.display.against, "slices");
        }
    }
}

TEST(DisplayStrip, AManualRangeStartsFromTheRangeShownAndEachChangeSaysWhatToRedo) {
    ViewState v = rangeView("minmax.tree");
    Panel panel;
    EXPECT_EQ(pick(panel, v, "range##v1", rangeModeNames()[int(RangeMode::Manual)]), StripChange::Statistics);
    EXPECT_EQ(v.display.range, RangeMode::Manual);
    EXPECT_EQ(v.display.manualMin, -1.0f);  // the measured range shown until then
    EXPECT_EQ(v.display.manualMax, 7.0f);
    EXPECT_EQ(panel.ctx.widgetRects().count("min##v1"), 1u);
    EXPECT_EQ(panel.ctx.widgetRects().count("max##v1"), 1u);
    // A colour map changes only the mapping: nothing to re-do.
    EXPECT_EQ(pick(panel, v, "colour map##v1", colourMapNames()[int(ColourMap::Grey)]), StripChange::None);
    EXPECT_EQ(v.display.colourMap, ColourMap::Grey);
    // The log scale changes the statistics' bins.
    StripChange change = StripChange::None;
    const auto ui = [&](Context& c) {
        const StripChange k = displayStripWidgets(c, v, 0.0f, kTechniques, "##v1");
        if (k != StripChange::None) change = k;
    };
    panel.frame({}, ui);
    const glm::vec2 box = panel.centreOf("log scale##v1");
    panel.frame(Panel::at(box, true), ui);
    panel.frame(Panel::at(box, false), ui);
    EXPECT_TRUE(v.display.logScale);
    EXPECT_EQ(change, StripChange::Statistics);
}

}  // namespace
}  // namespace airlight
