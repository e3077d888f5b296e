// The comparison grid (G) as the window draws it: a heading, one tile per technique (its L_air at the
// reference's exposure, its name and figures under it) and the plot of error against time in the cell
// after the last tile. The text and the layout are plain functions, so tests check them without a window.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "comparison_grid.h"
#include "frame_canvas.h"

namespace airlight {

// The reference's frames along a --path (path_reference.h), as the reference tile counts them while
// playing: ready of total (total 0: no path, or it is not rendered).
struct PathFramesShown {
    int ready = 0, total = 0;
};

// The line over the grid: what the tiles show, still or playing, in full and then in ever shorter forms
// (the window draws the longest that fits its width; each says what the tiles' figures are).
std::vector<std::string> comparisonHeadings(const ComparisonGrid& grid);

// Tile i's figures, the line under its name: still, its warm run's time and error; playing, the last
// frame's time and its flicker against the reference's path frames once known, else the change of its
// L_air; the reference tile says what it stands for; a failed tile, the first line of why; NaN or Inf
// pixels appended. Empty while the tile has no image.
std::string comparisonTileFigures(const ComparisonGrid& grid, std::size_t i, PathFramesShown path);

// Tile i's third line, still and with silhouette pixels in the view: its error without them
// (silhouetteErrorText). Empty otherwise, and for the reference, a failed tile or one not run yet.
std::string comparisonTileSilhouetteLine(const ComparisonGrid& grid, std::size_t i);

// Where things go inside `area`: tile i in the cell at (i % columns, i / columns) of a near-square grid
// with one cell more than tiles; each tile's box leaves room for its `captionLines` lines of height `line`;
// the plot takes the rest of the last row. Cells are `pad` apart from their neighbours' contents.
struct ComparisonLayout {
    int columns = 1;
    glm::vec2 cell{0.0f};
    std::vector<viz::ui::Rect> cells;  // per tile: its cell
    std::vector<viz::ui::Rect> boxes;  // per tile: where its image fits (the captions below)
    viz::ui::Rect plot;
};
ComparisonLayout layOutComparison(const viz::ui::Rect& area, int tiles, float line, float pad, int captionLines = 2);

// Draws the grid: the heading on the line above `area`, the tiles' images (pane draws at the grid's
// exposure), their captions, the plot. Names each tile's image "comparison:ID" (titled with its caption)
// and the plot "comparison.error_vs_time" in the canvas's screen map. Returns the heading it drew.
std::string drawComparison(FrameCanvas& canvas, const viz::ui::Rect& area, const ComparisonGrid& grid,
                    PathFramesShown path);

}  // namespace airlight
