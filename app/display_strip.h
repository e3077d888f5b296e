// A view's display strip, opened by the toggle under its title: how the view's values become colours
// (channel, range automatic or manual, log scale, colour map, negatives marked, and for the final frame
// and L_air a difference against another technique) as widgets, and the histogram of the shown channel
// with the display range marked, beside the widgets in a wide view and under them in a narrow one.
// Plain functions of the view and the toolkit: the window lays the strip out, opens the panel the widgets
// go in, and re-does what a change asks for.
#pragma once

#include <string>
#include <vector>

#include "ui/immediate.h"
#include "view_state.h"

namespace airlight {

// The height the strip asks for in a cell `cellWidth` wide (the window caps it by the cell's height):
// its rows of widgets (two more for a manual range, one for the difference's "against"), and the
// histogram's height when the cell is too narrow to put it beside them.
float displayStripHeight(const DisplaySettings& d, float cellWidth, float rowHeight, float scale);

// Where the widgets and the histogram go inside the strip.
struct StripAreas {
    viz::ui::Rect widgets, histogram;
};
StripAreas splitDisplayStrip(const viz::ui::Rect& strip, float scale);

// What a frame of the widgets changed, so the window knows what to re-do: the statistics (channel,
// range, log scale) or the difference image (its mode or the technique it is against).
enum class StripChange { None, Statistics, Difference };

// The widgets, drawn into the panel the caller opened; `tag` ("##vN") keeps the names of one view's
// widgets apart from another's; `techniques` are the difference's "against" choices. A range switched to
// manual starts from the range shown until then.
StripChange displayStripWidgets(viz::ui::Context& ui, ViewState& v, float exposure,
                                const std::vector<std::string>& techniques, const std::string& tag);

// The histogram of the shown channel's finite values with the display range marked; nothing in an area
// too small to read.
void drawStripHistogram(viz::ui::DrawList& dl, const ViewState& v, float exposure, const viz::ui::Rect& area,
                        float scale, float lineHeight);

}  // namespace airlight
