// The comparison grid's text and layout (app/comparison_panel.h): every tile and the plot inside the
// area, none overlapping another (checked pair by pair), the plot in the cell after the last tile and
// to the row's end; and what each tile's caption says, written out by hand for each case.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "comparison_panel.h"

namespace airlight {
namespace {

using viz::ui::Rect;

bool inside(const Rect& inner, const Rect& outer) {
    const float e = 1e-3f;
    return inner.min.x >= outer.min.x - e && inner.min.y >= outer.min.y - e && inner.max.x <= outer.max.x + e &&
           inner.max.y <= outer.max.y + e;
}

bool overlap(const Rect& a, const Rect& b) {
    return a.min.x < b.max.x && b.min.x < a.max.x && a.min.y < b.max.y && b.min.y < a.max.y;
}

TEST(ComparisonPanel, TilesAndThePlotFillTheAreaWithoutOverlapping) {
    const Rect area{{640.0f, 80.0f}, {1270.0f, 510.0f}};
    const float line = 15.0f, pad = 4.0f;
    for (int lines = 2; lines <= 3; ++lines)
    for (int n = 1; n <= 16; ++n) {
        SCOPED_TRACE(std::to_string(n) + " tiles, " + std::to_string(lines) + " caption lines");
        const ComparisonLayout l = layOutComparison(area, n, line, pad, lines);
        ASSERT_EQ(int(l.boxes.size()), n);
        ASSERT_EQ(int(l.cells.size()), n);
        // Near square: the fewest columns whose square holds the tiles and the plot.
        EXPECT_GE(l.columns * l.columns, n + 1);
        EXPECT_LT((l.columns - 1) * (l.columns - 1), n + 1);
        EXPECT_TRUE(inside(l.plot, area));
        for (int i = 0; i < n; ++i) {
            EXPECT_TRUE(inside(l.cells[std::size_t(i)], area)) << i;
            EXPECT_TRUE(inside(l.boxes[std::size_t(i)], l.cells[std::size_t(i)])) << i;
            // Room under the box for the name, the figures and the error without silhouettes.
            EXPECT_GE(l.cells[std::size_t(i)].max.y - l.boxes[std::size_t(i)].max.y, float(lines) * line) << i;
            EXPECT_FALSE(overlap(l.boxes[std::size_t(i)], l.plot)) << i;
            for (int k = 0; k < i; ++k) EXPECT_FALSE(overlap(l.cells[std::size_t(i)], l.cells[std::size_t(k)])) << i << " " << k;
        }
        // Row-major: tile i's cell is column i % columns of row i / columns.
        for (int i = 0; i < n; ++i) {
            EXPECT_NEAR(l.cells[std::size_t(i)].min.x, area.min.x + float(i % l.columns) * l.cell.x, 1e-3f);
            EXPECT_NEAR(l.cells[std::size_t(i)].min.y, area.min.y + float(i / l.columns) * l.cell.y, 1e-3f);
        }
        // The plot starts in the cell after the last tile and takes the rest of its row.
        EXPECT_NEAR(l.plot.min.x, area.min.x + float(n % l.columns) * l.cell.x + pad, 1e-3f);
        EXPECT_NEAR(l.plot.min.y, area.min.y + float(n / l.columns) * l.cell.y + pad, 1e-3f);
        EXPECT_NEAR(l.plot.max.x, area.max.x - pad, 1e-2f);
    }
}

// A tile as the window has it once the reference is in (no GL: a texture name stands for its image).
ComparisonTile tile(const std::string& id, double ms, double relativeL2, bool shown = true) {
    ComparisonTile t;
    t.technique = id;
    t.milliseconds = ms;
    t.error.relativeL2 = relativeL2;
    t.pane.texture = shown ? 1u : 0u;
    return t;
}

TEST(ComparisonPanel, StillTilesSayTheirTimeAndErrorAndTheReferenceIsTheGroundTruth) {
    ComparisonTile black = tile("vsv", 3.0, std::numeric_limits<double>::quiet_NaN());
    black.error.maxAbsolute = 0.25;
    ComparisonTile nan = tile("ivsv", 4.0, std::numeric_limits<double>::quiet_NaN());
    nan.error.nanPixels = 3;
    nan.error.infPixels = 1;
    ComparisonTile failed = tile("polyvol", 0.0, 0.0, false);
    failed.failure = "shader did not compile\n0:12: syntax error";
    RunPool pool;
    ComparisonGrid grid(pool);
    grid.tiles().push_back(tile("reference", 0.0, 0.0));
    grid.tiles().push_back(tile("minmax", 12.345, 0.01234));
    grid.tiles().push_back(tile("slices", 1.0, 0.5, false));
    grid.tiles().push_back(std::move(black));
    grid.tiles().push_back(std::move(nan));
    grid.tiles().push_back(std::move(failed));
    EXPECT_FALSE(grid.playing());
    EXPECT_EQ(comparisonTileFigures(grid, 0, {}), "ground truth");
    EXPECT_EQ(comparisonTileFigures(grid, 1, {}), "12.3 ms   error 0.0123");
    EXPECT_EQ(comparisonTileFigures(grid, 2, {}), "") << "not run yet";
    EXPECT_EQ(comparisonTileFigures(grid, 3, {}), "3.0 ms   reference black: max |a - b| 0.25");
    EXPECT_EQ(comparisonTileFigures(grid, 4, {}), "4.0 ms   error undefined   4 NaN/Inf px");
    EXPECT_EQ(comparisonTileFigures(grid, 5, {}), "failed: shader did not compile");
    // A run of a second or more in seconds, so that its caption is no longer than a fast one's.
    grid.tiles().push_back(tile("polyvol", 2412.94, 0.01234));
    grid.tiles().push_back(tile("ivsv", 999.94, 0.01234));
    grid.tiles().push_back(tile("vsv", 999.96, 0.01234));
    EXPECT_EQ(comparisonTileFigures(grid, 6, {}), "2.41 s   error 0.0123");
    EXPECT_EQ(comparisonTileFigures(grid, 7, {}), "999.9 ms   error 0.0123");
    EXPECT_EQ(comparisonTileFigures(grid, 8, {}), "1.00 s   error 0.0123") << "not \"1000.0 ms\"";
    const std::vector<std::string> headings = comparisonHeadings(grid);
    ASSERT_GE(headings.size(), 2u);
    EXPECT_NE(headings.front().find("time of a warm run and relative L2"), std::string::npos) << headings.front();
    // No silhouette pixel in this view (the grid has not run): no third line, nothing in the heading.
    for (std::size_t i = 0; i < grid.tiles().size(); ++i) EXPECT_EQ(comparisonTileSilhouetteLine(grid, i), "") << i;
    for (const std::string& h : headings) EXPECT_EQ(h.find("silhouette"), std::string::npos) << h;
    // Shorter forms for a narrow grid, each shorter than the one before and each still naming the error.
    for (std::size_t i = 1; i < headings.size(); ++i) {
        EXPECT_LT(headings[i].size(), headings[i - 1].size()) << headings[i];
        EXPECT_NE(headings[i].find("relative L2"), std::string::npos) << headings[i];
    }
    EXPECT_LE(headings.back().size(), 40u) << headings.back();
}

TEST(ComparisonPanel, TheErrorWithoutSilhouettePixelsIsShortAndSaysHowManyWereLeftOut) {
    EXPECT_EQ(silhouetteErrorText(0.0123, 0), "");
    EXPECT_EQ(silhouetteErrorText(0.023514, 4), "0.0235 w/o 4 silhouettes");
    EXPECT_EQ(silhouetteErrorText(0.5, 1), "0.5 w/o 1 silhouette");
    EXPECT_EQ(silhouetteErrorText(std::numeric_limits<double>::quiet_NaN(), 21), "undefined w/o 21 silhouettes");
    // It fits a small tile's line: no longer than the figures line "12.3 ms   error 0.0123" and a little.
    EXPECT_LE(silhouetteErrorText(0.0123456, 99999).size(), 30u);
}

}  // namespace
}  // namespace airlight
