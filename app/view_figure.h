// A window view written to a file, for handouts (`lesson --export`): the picture the window draws.
//   An image: through the window's own shader (ImageDisplay) with the window's mapping, scaled up
//   nearest-neighbour to at least kFigureWidth pixels wide (no taller than kFigureMaxHeight), over its
//   colour bar (ticks in the quantity's units, overlays and sentinels with their counts).
//   An intermediate with plots: its plots as the window draws them (viz/plot: axes, ticks, legends).
// Needs a current GL context.
#pragma once

#include <string>

#include "core/image.h"
#include "ui/font.h"
#include "view_state.h"

namespace airlight {

inline constexpr int kFigureWidth = 480;
inline constexpr int kFigureMaxHeight = 720;

struct Figure {
    viz::Image image;     // linear RGB (writeImage encodes it as the display showed it); empty: nothing to show
    std::string caption;  // one line: what the colour bar says (range, units, exposure, counts), or the plots' titles
    int plots = 0;        // plots drawn (0: an image)
    int series = 0;       // curves drawn over all plots
    int texelScale = 0;   // screen pixels per texel of an image (0: scaled down to fit)
};

// `view.pane` built from the run (makePane or a radiance image); `exposureStops` as the window's.
Figure renderFigure(ViewState& view, float exposureStops, const viz::ui::FontAtlas& font);

}  // namespace airlight
