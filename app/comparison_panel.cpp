#include "comparison_panel.h"

#include <cmath>
#include <string>
#include <vector>

#include "core/text.h"
#include "image_fit.h"
#include "plot/plot.h"
#include "ui/theme.h"

namespace airlight {

using viz::ui::Rect;

std::vector<std::string> comparisonHeadings(const ComparisonGrid& grid) {
    if (grid.playing()) {
        const std::string frame = std::to_string(grid.playedFrames());
        return {"comparison (G), playing (P): frame " + frame +
                    ", run time and the change of L_air per frame (along a --path, its error's flicker against the "
                    "reference's frames; the plot: the still frame; P stops)",
                "comparison (G), playing: frame " + frame + ", run time and change (or flicker) per frame; P stops",
                "playing: frame " + frame + "; P stops"};
    }
    const std::size_t n = grid.silhouettePixels();
    std::string full = "comparison (G): L_air at the reference's exposure, time of a warm run and relative L2 "
                       "against the reference";
    if (n == 0) return {full, "comparison (G): time of a warm run, relative L2 against the reference",
                        "comparison (G): time, relative L2"};
    const std::string pixels = std::to_string(n) + " silhouette pixel" + (n == 1 ? "" : "s");
    full += ", and without the " + pixels + " whose rasterised and traced first hits differ";
    return {full, "comparison (G): warm-run time, relative L2 against the reference, and w/o " + pixels,
            "comparison (G): time, relative L2, and w/o " + pixels, "time, relative L2, w/o " + pixels};
}

namespace {

// The longest heading that fits `width` pixels.
std::string fittingHeading(const ComparisonGrid& grid, const viz::ui::FontAtlas& font, float width) {
    const std::vector<std::string> headings = comparisonHeadings(grid);
    for (const std::string& h : headings)
        if (font.measure(h) <= width) return h;
    return headings.back();  // clipped where even the shortest does not fit
}

}  // namespace

std::string comparisonTileFigures(const ComparisonGrid& grid, std::size_t i, PathFramesShown path) {
    const ComparisonTile& tile = grid.tiles().at(i);
    const bool playing = grid.playing();
    std::string figures;
    if (!tile.failure.empty()) {
        figures = "failed: " + viz::firstLine(tile.failure);
    } else if (tile.pane.texture == 0) {
        figures = "";  // not run yet
    } else if (tile.technique == "reference") {
        figures = !playing          ? "ground truth"
                  : path.total > 0  ? "still frame; path frames " + std::to_string(path.ready) + "/" +
                                         std::to_string(path.total)
                                    : "ground truth, still frame";
    } else if (playing) {
        // The flicker against the reference's path frames once known (the figure to rank by, where a tile
        // has room for one), else the change of L_air.
        figures = tile.temporal.errorPairs() > 0
                      ? tileTimeText(tile.playMilliseconds, 0) + viz::format("  flicker %.3g", tile.temporal.errorScore())
                      : tileTimeText(tile.playMilliseconds) + viz::format("   change %.3g", tile.temporal.score());
    } else {
        figures = tileTimeText(tile.milliseconds) + "   " + tileErrorText(tile.error);
    }
    if (tile.error.nanPixels + tile.error.infPixels > 0)
        figures += "   " + std::to_string(tile.error.nanPixels + tile.error.infPixels) + " NaN/Inf px";
    return figures;
}

std::string comparisonTileSilhouetteLine(const ComparisonGrid& grid, std::size_t i) {
    const ComparisonTile& tile = grid.tiles().at(i);
    if (grid.playing() || !tile.failure.empty() || tile.pane.texture == 0 || tile.technique == "reference") return "";
    return silhouetteErrorText(tile.relativeL2Agreeing, grid.silhouettePixels());
}

ComparisonLayout layOutComparison(const Rect& area, int tiles, float line, float pad, int captionLines) {
    ComparisonLayout layout;
    const int cells = std::max(tiles, 0) + 1;  // one more cell for the plot of error against time
    layout.columns = int(std::ceil(std::sqrt(double(cells))));
    const int rows = (cells + layout.columns - 1) / layout.columns;
    layout.cell = {area.size().x / float(layout.columns), area.size().y / float(rows)};
    auto cellAt = [&](int i) { return area.min + glm::vec2(float(i % layout.columns), float(i / layout.columns)) * layout.cell; };
    for (int i = 0; i < tiles; ++i) {
        const glm::vec2 at = cellAt(i);
        layout.cells.push_back({at, at + layout.cell});
        layout.boxes.push_back({at + pad, at + layout.cell - glm::vec2(pad, pad + float(captionLines) * line)});
    }
    const glm::vec2 at = cellAt(std::max(tiles, 0));
    const int left = layout.columns - std::max(tiles, 0) % layout.columns;
    layout.plot = {at + pad, at + glm::vec2(float(left), 1.0f) * layout.cell - pad};
    return layout;
}

std::string drawComparison(FrameCanvas& canvas, const Rect& area, const ComparisonGrid& grid, PathFramesShown path) {
    namespace theme = viz::ui::theme;
    viz::ui::DrawList& dl = *canvas.overlay;
    const float line = canvas.line(), pad = 4.0f * canvas.scale;
    const int n = int(grid.tiles().size());
    const bool silhouettes = grid.silhouettePixels() > 0 && !grid.playing();
    const ComparisonLayout layout = layOutComparison(area, n, line, pad, silhouettes ? 3 : 2);
    const std::string heading = fittingHeading(grid, dl.font(), area.size().x);
    dl.textClipped({area.min.x, area.min.y - line}, heading, theme::kAccent, area.max.x);
    viz::plot::drawPlot(dl, layout.plot, grid.errorAgainstTime());
    canvas.screen.placeView({"comparison.error_vs_time", "relative L2 against time", layout.plot, -1});
    for (int i = 0; i < n; ++i) {
        const ComparisonTile& tile = grid.tiles()[std::size_t(i)];
        const Rect& box = layout.boxes[std::size_t(i)];
        const float right = layout.cells[std::size_t(i)].max.x - pad;  // captions are clipped to the cell
        // An empty pane fits the grid's image size (the tile's image, once it is in).
        const Rect image = fitImageRect(box, tile.pane.size.x > 0 && tile.pane.size.y > 0 ? tile.pane.size : grid.size());
        if (tile.pane.texture != 0) {
            DisplayMapping shared;
            shared.exposure = grid.exposure();
            canvas.panes.push_back({image, &tile.pane, nullptr, shared});
        } else if (tile.failure.empty()) {
            dl.textClipped({box.min.x + 4.0f * canvas.scale, box.min.y + 4.0f * canvas.scale}, grid.waitingText(),
                           theme::kDim, box.max.x);
        }
        const std::string figures = comparisonTileFigures(grid, std::size_t(i), path);
        const std::string withoutSilhouettes = comparisonTileSilhouetteLine(grid, std::size_t(i));
        canvas.screen.placeView({"comparison:" + tile.technique,
                                 tile.technique + "  " + figures +
                                     (withoutSilhouettes.empty() ? "" : "; " + withoutSilhouettes),
                                 image, -1});
        float captionX = box.min.x;
        if (tile.technique != "reference") {
            // The colour of its point in the error-against-time plot (whose legend a small cell leaves out).
            const float mark = line - 6.0f * canvas.scale;
            dl.rect({{captionX, box.max.y + 5.0f * canvas.scale}, {captionX + mark, box.max.y + 5.0f * canvas.scale + mark}},
                    viz::plot::categoricalColour(i));
            captionX += mark + 4.0f * canvas.scale;
        }
        dl.textClipped({captionX, box.max.y + 2.0f}, tile.technique, theme::kText, right);
        dl.textClipped({box.min.x, box.max.y + 2.0f + line}, figures, theme::kDim, right);
        if (!withoutSilhouettes.empty())
            dl.textClipped({box.min.x, box.max.y + 2.0f + 2.0f * line}, withoutSilhouettes, theme::kDim, right);
    }
    return heading;
}

}  // namespace airlight
