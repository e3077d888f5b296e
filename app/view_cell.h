// One cell of the view grid, laid out and drawn: its two-line title bar (with where the run stopped and
// the display strip's toggle), its image or plots, the values written into zoomed-in texels, the linked
// cursor and the technique's marks for it, the colour bar, the value readout and the progress bands.
// Plain functions over the frame's canvas: what they need of the window comes in one value per frame
// (ViewCellFrame) and one per cell (ViewCellParts), so tests draw cells without a window. The display
// strip's widgets (display_strip.h) are drawn after the cell by its caller, which acts on their changes.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "frame_canvas.h"
#include "progress_band.h"
#include "view_state.h"
#include "view_title.h"
#include "debug/technique.h"
#include "ui/immediate.h"

namespace airlight {

// The window as every cell of one frame sees it.
struct ViewCellFrame {
    FrameCanvas* canvas = nullptr;
    viz::ui::Context* ui = nullptr;          // tooltips; its row height sizes the display strip
    glm::vec2 hover{-1.0f};                  // the mouse, in window pixels
    int focused = -1, hovered = -1;          // view ids: the focused view, the one under the mouse
    std::optional<glm::ivec2> linkedPixel;   // the frame pixel under the mouse (over a screen-space view)
    glm::ivec2 frameSize{0};                 // the render's size (an empty pane's image keeps its aspect)
    bool haveOutput = false;
    std::string stoppedEarly;                // where the run stopped short of the complete algorithm ("" when it did not)
    float exposure = 0.0f;
    ViewTitleFacts title;
    std::vector<ProgressBand> bands;         // over the bottom of every image: "rendering...", the CPU pass
};

// What the window adds to one cell.
struct ViewCellParts {
    bool screenSpace = false;  // one texel per frame pixel: the linked cursor is drawn and read here
    // The technique's marks for the linked pixel, asked only for an algorithm-space image view while there is one.
    std::function<std::vector<viz::ViewMarker>()> markers;
    // Drawn over the image before the colour bar (the ray inspector's mark, the light gizmo); image views only.
    std::function<void(viz::ui::DrawList&)> overlays;
    // The title bar's "display +" / "display -" was clicked.
    std::function<void()> toggleStrip;
};

struct ViewCellDrawn {
    std::string readout;       // the value line under the image ("pixel (x, y)  =  r  g  b"); empty: none
    bool titleElided = false;  // the title was shortened to fit
};

// Where the parts of a cell go: the title bar (two lines), the image (the pane's aspect, centred at the
// top; plots take the whole area), the colour bar under it (dropped when it would take over a quarter of
// the room), the readout line and, when open, the display strip at the bottom (at most 60 % of the room).
void layOutViewCell(const ViewCellFrame& f, ViewState& v, const viz::ui::Rect& cell);

// Draws cell `id` (laid out by layOutViewCell) into the frame's canvas and names its rectangles in the
// canvas's screen map: "title:ID", "strip:ID" (the toggle), "cell:ID" (the image), "colour_bar:ID", and
// the view itself (by its pane's id, "none" before any run) for scripts and the sidecar.
ViewCellDrawn drawViewCell(const ViewCellFrame& f, int id, ViewState& v, const ViewCellParts& parts);

}  // namespace airlight
