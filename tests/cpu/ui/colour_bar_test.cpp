// The colour bar a view draws (app/colour_bar.h): a ramp whose values the view's mapping takes evenly
// from one end of the map to the other (checked through mapToUnit and signedUnit, the CPU mirrors of
// the shader's mapping), ticks inside the range at the places that mapping gives them, classes for the
// discrete maps, and a legend that names the sentinels with their counts.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "colour_bar.h"
#include "colour_bar_draw.h"
#include "view_state.h"

namespace airlight {
namespace {

PaneImage paneOf(viz::ViewKind kind, float lo, float hi, std::string units = "scene units") {
    PaneImage p;
    p.id = "test.pane";
    p.kind = kind;
    p.mode = displayModeFor(kind);
    p.rangeMin = lo, p.rangeMax = hi;
    p.units = std::move(units);
    p.texture = 1;  // any texture: the bar only needs to know there is an image
    p.size = {8, 8};
    return p;
}

// The ramp's texels land evenly across [0, 1] under `unit` (texel centres at (i + 0.5) / n).
template <class Unit>
void expectEvenRamp(const ColourBar& bar, Unit unit) {
    ASSERT_EQ(bar.kind, ColourBar::Kind::Ramp);
    ASSERT_EQ(int(bar.values.size()), kRampTexels);
    for (int i = 0; i < kRampTexels; i += 17)
        EXPECT_NEAR(unit(bar.values[std::size_t(i)]), (i + 0.5) / kRampTexels, 1e-4) << "texel " << i;
}

TEST(ColourBar, ALinearRampSpansTheMappedRangeWithTicksWhereTheMappingPutsThem) {
    const PaneImage pane = paneOf(viz::ViewKind::Depth, 0.0f, 40.0f);
    const DisplayMapping m = resolveMapping(pane, {}, 0.0f, std::nullopt);
    const ColourBar bar = colourBarFor(pane, m, {});
    expectEvenRamp(bar, [&](float v) { return mapToUnit(v, m.lo, m.hi, false); });
    EXPECT_EQ(bar.lo, 0.0);
    EXPECT_EQ(bar.hi, 40.0);
    EXPECT_EQ(bar.units, "scene units");
    ASSERT_GE(bar.ticks.size(), 3u);
    for (std::size_t i = 0; i < bar.ticks.size(); ++i) {
        EXPECT_GE(bar.ticks[i], 0.0);
        EXPECT_LE(bar.ticks[i], 40.0);
        EXPECT_NEAR(bar.tickAt[i], mapToUnit(float(bar.ticks[i]), 0.0f, 40.0f, false), 1e-6);
        EXPECT_EQ(std::stod(bar.tickLabels[i]), bar.ticks[i]);
    }
}

TEST(ColourBar, ALogRampHasDecadeTicksAndALogSafeLowEnd) {
    const PaneImage pane = paneOf(viz::ViewKind::Scalar, 0.0f, 100.0f);
    DisplaySettings d;
    d.logScale = true;
    const DisplayMapping m = resolveMapping(pane, d, 0.0f, std::nullopt);
    const ColourBar bar = colourBarFor(pane, m, {});
    expectEvenRamp(bar, [&](float v) { return mapToUnit(v, m.lo, m.hi, true); });
    EXPECT_TRUE(bar.logarithmic);
    EXPECT_NEAR(bar.lo, 1e-4, 1e-9);  // 0 is replaced by hi * 1e-6, as the shader does
    for (std::size_t i = 0; i < bar.ticks.size(); ++i) {
        const double decade = std::log10(bar.ticks[i]);
        EXPECT_NEAR(decade, std::round(decade), 1e-9) << bar.ticks[i];
        EXPECT_NEAR(bar.tickAt[i], mapToUnit(float(bar.ticks[i]), m.lo, m.hi, true), 1e-5);
    }
}

TEST(ColourBar, TheDivergingRampIsSymmetricAndInvertsTheSymmetricLog) {
    const PaneImage pane = paneOf(viz::ViewKind::Signed, -0.5f, 2.0f, "radiance");
    for (bool log : {false, true}) {
        DisplaySettings d;
        d.logScale = log;
        const DisplayMapping m = resolveMapping(pane, d, 0.0f, std::nullopt);
        const ColourBar bar = colourBarFor(pane, m, {});
        expectEvenRamp(bar, [&](float v) { return 0.5f * (signedUnit(v, m.lo, m.hi, log) + 1.0f); });
        EXPECT_EQ(bar.lo, -2.0);
        EXPECT_EQ(bar.hi, 2.0);
        bool zero = false;
        for (std::size_t i = 0; i < bar.ticks.size(); ++i) {
            zero = zero || bar.ticks[i] == 0.0;
            if (bar.ticks[i] == 0.0) {
                EXPECT_FLOAT_EQ(bar.tickAt[i], 0.5f);
            }
        }
        EXPECT_TRUE(zero) << "0 is always a tick of a diverging bar";
    }
}

// A diverging bar's ticks lie inside its ends, each where the map puts it: the map clamps, so a tick
// beyond an end used to land on it ("-1.0" at the left end of a [-0.526, 0.526] bar, polyvol's signed
// total with its range from the data).
TEST(ColourBar, ADivergingBarsTicksLieInsideItsEnds) {
    for (const auto& [lo, hi] : {std::pair{0.0f, 0.5258f}, {-0.5f, 2.0f}, {0.0f, 0.07f}, {-3e-4f, 1e-4f}}) {
        const PaneImage pane = paneOf(viz::ViewKind::Signed, lo, hi, "radiance");
        const DisplayMapping m = resolveMapping(pane, {}, 0.0f, std::nullopt);
        const ColourBar bar = colourBarFor(pane, m, {});
        ASSERT_GE(bar.ticks.size(), 2u) << lo << " " << hi;
        for (std::size_t i = 0; i < bar.ticks.size(); ++i) {
            EXPECT_GE(bar.ticks[i], bar.lo * (1.0 + 1e-6)) << bar.tickLabels[i];
            EXPECT_LE(bar.ticks[i], bar.hi * (1.0 + 1e-6)) << bar.tickLabels[i];
            EXPECT_NEAR(bar.tickAt[i], 0.5f * (signedUnit(float(bar.ticks[i]), m.lo, m.hi, false) + 1.0f), 1e-5f);
        }
    }
}

// A view whose range comes from its data (Intermediate::rangeFromData: polyvol's signed total) maps from
// its own 2nd to 98th percentile, not the declared range and not its peak: 9,900 values spread over
// [0, 0.1) and 100 at a peak of 10 give a top near 0.1 (the declared 1 or the peak washed the shafts out).
TEST(ColourBar, ARangeFromTheDataLeavesThePeakOut) {
    ViewState view;
    view.pane = paneOf(viz::ViewKind::Signed, -1.0f, 1.0f, "radiance");
    view.pane.rangeFromData = true;
    view.values = viz::Image(100, 100, 1);
    for (int i = 0; i < 10000; ++i) view.values.pixels[std::size_t(i)] = i < 9900 ? 0.1f * float(i) / 9900.0f : 10.0f;
    view.meaningful = 1;
    updateStatistics(view);
    ASSERT_TRUE(view.measured && view.measured->valid);
    const DisplayMapping m = resolveMapping(view.pane, view.display, 0.0f, view.measured);
    EXPECT_NEAR(m.hi, 0.1f, 0.005f);
    EXPECT_NEAR(m.lo, 0.002f, 0.002f);
    // Without the flag the declared range stands.
    view.pane.rangeFromData = false;
    updateStatistics(view);
    const DisplayMapping declared = resolveMapping(view.pane, view.display, 0.0f, view.measured);
    EXPECT_EQ(declared.lo, -1.0f);
    EXPECT_EQ(declared.hi, 1.0f);
}

// A count whose declared range the data can exceed (Intermediate::rangeGrowsToData: polyvol's crossings,
// declared [0, 16]): the range stays as declared while the data fits it, a few outlying pixels included,
// and widens to the data's 99th percentile when most of it lies beyond (tv-room's overlapping volumes);
// a diverging channel widens symmetrically about 0.
TEST(ColourBar, ARangeThatGrowsToTheDataKeepsTheDeclaredOneWhileTheDataFits) {
    ViewState view;
    view.pane = paneOf(viz::ViewKind::Scalar, 0.0f, 16.0f, "faces");
    view.pane.rangeGrowsToData = true;
    view.values = viz::Image(100, 100, 1);
    view.meaningful = 1;
    auto mapped = [&] {
        updateStatistics(view);
        return resolveMapping(view.pane, view.display, 0.0f, view.measured);
    };
    // 9,950 values in 0..15 and 50 at 52 (grate's jagged bars): the declared range stands.
    for (int i = 0; i < 10000; ++i) view.values.pixels[std::size_t(i)] = i < 9950 ? float(i % 16) : 52.0f;
    DisplayMapping m = mapped();
    EXPECT_EQ(m.lo, 0.0f);
    EXPECT_EQ(m.hi, 16.0f);
    // Every value from 20 to 119, equally often: the top is the 99th percentile, 119 at nearest rank.
    for (int i = 0; i < 10000; ++i) view.values.pixels[std::size_t(i)] = float(20 + i % 100);
    m = mapped();
    EXPECT_EQ(m.lo, 0.0f) << "a count keeps 0 at the bottom";
    EXPECT_NEAR(m.hi, 119.0f, 1.0f);
    // Diverging: values from -30 to 10 give [-30, 30] (the 1st percentile, -30 at nearest rank).
    view.pane = paneOf(viz::ViewKind::Signed, -4.0f, 4.0f, "faces");
    view.pane.rangeGrowsToData = true;
    for (int i = 0; i < 10000; ++i) view.values.pixels[std::size_t(i)] = float(-30 + i % 41);
    m = mapped();
    EXPECT_NEAR(m.hi, 30.0f, 1.0f);
    EXPECT_EQ(m.lo, -m.hi);
    // Without the flag the declared range stands.
    view.pane.rangeGrowsToData = false;
    m = mapped();
    EXPECT_EQ(m.lo, -4.0f);
    EXPECT_EQ(m.hi, 4.0f);
}

TEST(ColourBar, AnHdrImagesBarEndsWhereTheExposureReachesWhite) {
    PaneImage pane = paneOf(viz::ViewKind::Colour, 0.0f, 1.0f, "radiance");
    pane.mode = DisplayMode::HdrColour;
    const DisplayMapping m = resolveMapping(pane, {}, 2.0f, std::nullopt);  // +2 EV: white at 0.25
    const ColourBar bar = colourBarFor(pane, m, {});
    EXPECT_EQ(bar.lo, 0.0);
    EXPECT_DOUBLE_EQ(bar.hi, 0.25);
    EXPECT_NE(bar.caption.find("0.25"), std::string::npos) << bar.caption;
}

// A mask's bar counts its white pixels as the shader classes them (the shown value above the middle of the
// range), leaving out NaN, Inf and sentinel pixels; each pixel's class written out by hand.
TEST(ColourBar, AMaskSaysHowManyPixelsAreWhite) {
    PaneImage mask = paneOf(viz::ViewKind::Mask, 0.0f, 1.0f, "");
    mask.sentinels = {{0.25f, "not read"}};
    const DisplayMapping m = resolveMapping(mask, {}, 0.0f, std::nullopt);
    ASSERT_EQ(m.mode, DisplayMode::Mask);
    viz::Image values(3, 2, 1);
    values.pixels = {1.0f, 0.0f, 0.75f,                                  // white, black, white
                     0.25f, std::nanf(""), std::numeric_limits<float>::infinity()};  // sentinel, NaN, Inf: not counted
    const auto pixels = countMaskPixels(m, values, 1, mask.sentinels);
    ASSERT_TRUE(pixels);
    EXPECT_EQ(pixels->white, 2u);
    EXPECT_EQ(pixels->counted, 3u);
    ColourBar bar = colourBarFor(mask, m, {});
    describeMaskPixels(bar, *pixels);
    EXPECT_NE(bar.caption.find(": 2 of 3 pixels"), std::string::npos) << bar.caption;
    // All black: it says so.
    viz::Image black(4, 4, 1);
    ColourBar none = colourBarFor(mask, m, {});
    describeMaskPixels(none, *countMaskPixels(m, black, 1, {}));
    EXPECT_NE(none.caption.find(": 0 of 16 pixels"), std::string::npos) << none.caption;
    // The green channel chosen: its values decide.
    viz::Image rgb(2, 1, 3);
    rgb.pixels = {1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f};
    DisplaySettings green;
    green.channel = Channel::G;
    const auto g = countMaskPixels(resolveMapping(mask, green, 0.0f, std::nullopt), rgb, 3, {});
    ASSERT_TRUE(g);
    EXPECT_EQ(g->white, 1u);
    EXPECT_EQ(g->counted, 2u);
    // Another mode, or no values: nothing counted.
    EXPECT_FALSE(countMaskPixels(m, viz::Image{}, 1, {}));
    PaneImage grey = paneOf(viz::ViewKind::Scalar, 0.0f, 1.0f, "");
    EXPECT_FALSE(countMaskPixels(resolveMapping(grey, {}, 0.0f, std::nullopt), values, 1, {}));
}

TEST(ColourBar, DiscreteMapsGetClassesAndSentinelsLeadTheLegend) {
    PaneImage mask = paneOf(viz::ViewKind::Mask, 0.0f, 1.0f, "");
    EXPECT_EQ(colourBarFor(mask, resolveMapping(mask, {}, 0.0f, std::nullopt), {}).values, (std::vector<float>{0, 1}));
    PaneImage map = paneOf(viz::ViewKind::Scalar, 0.0f, 3.14f, "radians");
    map.sentinels = {{-1.0f, "outside the cone"}, {4.0f, "unblocked"}};
    SpecialCounts counts;
    counts.nan = 2;
    counts.sentinel = {10, 0};
    const ColourBar bar = colourBarFor(map, resolveMapping(map, {}, 0.0f, std::nullopt), counts);
    ASSERT_GE(bar.legend.size(), 4u);
    EXPECT_TRUE(bar.legend[0].sentinel);
    EXPECT_EQ(bar.legend[0].value, -1.0f);
    EXPECT_EQ(bar.legend[0].pixels, 10u);
    EXPECT_NE(bar.legend[0].label.find("outside the cone"), std::string::npos);
    EXPECT_EQ(bar.legend[2].label, "NaN");
    EXPECT_EQ(bar.legend[2].pixels, 2u);
    // No image, or a plot: no bar.
    PaneImage none = paneOf(viz::ViewKind::Scalar, 0.0f, 1.0f);
    none.texture = 0;
    EXPECT_EQ(colourBarFor(none, resolveMapping(none, {}, 0.0f, std::nullopt), {}).kind, ColourBar::Kind::None);
}

TEST(ColourBar, APictureHasNoMapUnlessTheUserPicksOne) {
    PaneImage chart = paneOf(viz::ViewKind::Colour, 0.0f, 1.0f, "");
    chart.picture = true;
    const ColourBar bar = colourBarFor(chart, resolveMapping(chart, {}, 0.0f, std::nullopt), {});
    EXPECT_EQ(bar.kind, ColourBar::Kind::Picture);
    EXPECT_TRUE(bar.values.empty());
    EXPECT_NE(bar.caption.find("note"), std::string::npos);
    DisplaySettings grey;
    grey.colourMap = ColourMap::Grey;
    EXPECT_EQ(colourBarFor(chart, resolveMapping(chart, grey, 0.0f, std::nullopt), {}).kind, ColourBar::Kind::Ramp);
}

TEST(ColourBar, ADeclaredChannelBringsItsOwnRangeUnitsAndMap) {
    PaneImage pane = paneOf(viz::ViewKind::Scalar, 0.0f, 16.0f, "");
    pane.channelInfo = {{"faces crossed", "faces", viz::ViewKind::Scalar, 0.0f, 16.0f},
                        {"signed count", "faces", viz::ViewKind::Signed, -4.0f, 4.0f}};
    EXPECT_EQ(defaultChannel(pane), Channel::R);
    EXPECT_EQ(channelChoices(pane)[2], "g: signed count");
    DisplaySettings d;
    d.channel = Channel::G;
    const DisplayMapping m = resolveMapping(pane, d, 0.0f, std::nullopt);
    EXPECT_EQ(m.mode, DisplayMode::Signed);
    const ColourBar bar = colourBarFor(pane, m, {});
    EXPECT_EQ(bar.lo, -4.0);
    EXPECT_EQ(bar.units, "faces");
    EXPECT_EQ(bar.caption, "signed count");
}

// The window's font, and a grey ramp bar in `units` with nothing else set: what the drawing tests lay out.
const viz::ui::FontAtlas& barFont() {
    static const viz::ui::FontAtlas font = viz::ui::FontAtlas::bake(viz::ui::FontAtlas::kDefaultFontPath, 14.0f);
    return font;
}

ColourBar rampBar(const std::string& units) {
    ColourBar bar;
    bar.kind = ColourBar::Kind::Ramp;
    bar.values = {0.0f, 1.0f};
    bar.units = units;
    return bar;
}

}  // namespace
// A narrow bar keeps every legend entry: the overlays (NaN, Inf) whole, a sentinel's long meaning cut to
// what they leave instead of dropped (a shadow map's "no occluder" sentinel vanished from half-width
// views); each swatch lies inside the bar, after the one before it.
TEST(ColourBar, ANarrowBarShortensASentinelInsteadOfDroppingIt) {
    const viz::ui::FontAtlas& font = barFont();
    ColourBar bar = rampBar("scene units");
    bar.legend = {{"1e+30: no occluder (cleared far away)", 1e30f, 938034, true},
                  {"NaN", std::nanf(""), 0, false},
                  {"Inf", std::numeric_limits<float>::infinity(), 0, false}};
    for (const float width : {540.0f, 900.0f, 1400.0f}) {
        viz::ui::DrawList text(font), frames(font);
        const viz::ui::Rect area{{0.0f, 0.0f}, {width, 36.0f}};
        const ColourBarLayout layout = drawColourBarText(bar, area, font, 1.0f, text, frames, {});
        ASSERT_EQ(layout.swatches.size(), 3u) << "width " << width;
        float previous = -1.0f;
        for (std::size_t k = 0; k < 3; ++k) {
            EXPECT_EQ(layout.swatches[k].second, k);
            EXPECT_GT(layout.swatches[k].first.min.x, previous);
            EXPECT_LE(layout.swatches[k].first.max.x, area.max.x);
            previous = layout.swatches[k].first.max.x;
        }
        EXPECT_NE(layout.legend.find("no occluder (cleared far away) 938034 px"), std::string::npos) << layout.legend;
    }
}

// A colour image's bar says which exposure maps to white. Where "radiance   each colour channel, exposure
// 2.5 EV" does not fit, the bar gives the exposure alone ("radiance   +2.5 EV") instead of cutting the
// sentence in the middle ("radiance   each co ..., exposure 2.5 EV"); a wide bar keeps the sentence.
TEST(ColourBar, ANarrowColourBarKeepsItsExposureWhole) {
    const viz::ui::FontAtlas& font = barFont();
    ColourBar bar = rampBar("radiance");
    bar.caption = "each colour channel, exposure 2.5 EV";
    bar.shortCaption = "+2.5 EV";
    const std::string full = "radiance   each colour channel, exposure 2.5 EV", brief = "radiance   +2.5 EV";
    bool sawFull = false, sawBrief = false;
    for (float width = 100.0f; width <= 1400.0f; width += 1.0f) {
        viz::ui::DrawList text(font), frames(font);
        const ColourBarLayout layout = drawColourBarText(bar, {{0.0f, 0.0f}, {width, 36.0f}}, font, 1.0f, text, frames, {});
        sawFull |= layout.heading == full;
        sawBrief |= layout.heading == brief;
        // Narrower than the brief form, that is shortened; the sentence never is.
        if (layout.heading != full) {
            EXPECT_EQ(layout.heading.find("colour"), std::string::npos) << width << ": " << layout.heading;
        }
        if (layout.heading == brief) {
            EXPECT_FALSE(sawFull) << "the sentence at a narrower width than the brief form";
        }
    }
    EXPECT_TRUE(sawFull);
    EXPECT_TRUE(sawBrief);
}

}  // namespace airlight
