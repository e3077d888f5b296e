// The histogram under an image view's settings strip: the bins as a step curve in per cent of every value
// counted (those below and above the bins included), and the range the view maps to colour marked where
// it falls inside the data.
#pragma once

#include "pane_image.h"
#include "plot/plot.h"
#include "view_stats.h"

namespace airlight {

inline constexpr glm::vec4 kShownRangeColour{0.3f, 0.85f, 1.0f, 1.0f};

// `hasValues`: false when the view has no values to count. `shown`: the view's resolved mapping; an HDR
// colour view maps no range, so nothing is marked.
viz::plot::PlotSpec histogramPlot(const Histogram& h, bool hasValues, const DisplayMapping& shown);

}  // namespace airlight
