// The pane a difference view shows (app/difference_pane.h), no window: its name, note, units, kind and
// colour map per mode, and a suggested range that a few outliers do not stretch (the 99.9th percentile,
// worked out here by sorting).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "difference_pane.h"

namespace airlight {
namespace {

PaneImage lair() {
    PaneImage p;
    p.id = "airlight";
    p.label = "Airlight L_air";
    return p;
}

// 2000 differences: 1999 spread over [-0.5, 0.75] and one outlier of 100.
viz::Image spread() {
    viz::Image d(2000, 1, 1);
    for (int i = 0; i < 1999; ++i) d.pixels[std::size_t(i)] = -0.5f + 1.25f * float(i) / 1998.0f;
    d.pixels[1999] = 100.0f;
    return d;
}

TEST(DifferencePane, EachModeSaysWhatItSubtractsAndShowsItInItsOwnMap) {
    const viz::Image d = spread();
    const PaneImage a = differencePane(lair(), d, DifferenceMode::Absolute, "reference", false, "slices");
    EXPECT_EQ(a.id, "airlight");
    EXPECT_EQ(a.label, "Airlight L_air: |a - b|, b = reference");
    EXPECT_EQ(a.note, "sum over RGB of |a - b|, a = slices");
    EXPECT_EQ(a.units, "radiance");
    EXPECT_EQ(a.kind, viz::ViewKind::Scalar);
    EXPECT_EQ(a.mode, DisplayMode::Heat);
    EXPECT_EQ(a.rangeMin, 0.0f);
    EXPECT_EQ(a.texture, 0u) << "the window uploads the image";

    const PaneImage s = differencePane(lair(), d, DifferenceMode::Signed, "raymarch", true, "slices");
    EXPECT_EQ(s.label, "Airlight L_air: a - b, b = raymarch (held while playing)");
    EXPECT_NE(s.note.find("blue where a is darker"), std::string::npos);
    EXPECT_EQ(s.kind, viz::ViewKind::Signed);
    EXPECT_EQ(s.mode, DisplayMode::Signed);
    EXPECT_EQ(s.rangeMin, -s.rangeMax) << "symmetric about zero";

    const PaneImage r = differencePane(lair(), d, DifferenceMode::Relative, "reference", false, "slices");
    EXPECT_EQ(r.units, "") << "a ratio";
    EXPECT_NE(r.note.find("relative error"), std::string::npos);
}

TEST(DifferencePane, TheSuggestedRangeEndsAtThe999thPercentileNotAtAnOutlier) {
    const viz::Image d = spread();
    std::vector<float> sorted = d.pixels;
    std::sort(sorted.begin(), sorted.end());
    // Nearest rank: the 99.9th percentile of 2000 values is the 1998th (index 1997), below the outlier.
    const float p999 = sorted[std::size_t(std::ceil(0.999 * 2000.0)) - 1];
    const float p001 = sorted[std::size_t(std::ceil(0.001 * 2000.0)) - 1];
    ASSERT_LT(p999, 1.0f);
    const PaneImage a = differencePane(lair(), d, DifferenceMode::Absolute, "reference", false, "slices");
    EXPECT_NEAR(a.rangeMax, std::max(std::abs(p001), std::abs(p999)), 2e-3f);
    EXPECT_LT(a.rangeMax, 1.0f) << "the outlier of 100 does not stretch the map";
    // All differences zero (a technique against itself): a tiny positive range, never an empty one.
    const viz::Image zero(4, 4, 1);
    const PaneImage z = differencePane(lair(), zero, DifferenceMode::Signed, "slices", false, "slices");
    EXPECT_GT(z.rangeMax, 0.0f);
    EXPECT_LT(z.rangeMin, 0.0f);
}

}  // namespace
}  // namespace airlight
