// The images a colour bar is drawn from: its ramp and its legend swatches as one-row textures of the
// bar's values, uploaded into the view's state when they change, and the draws that show them through
// the view's own mapping (the ramp without sentinels or the negative overlay; each swatch as the
// picture would show that value). Needs a current GL context.
#pragma once

#include <vector>

#include "colour_bar_draw.h"
#include "pane_image.h"
#include "view_state.h"

namespace airlight {

struct BarImageDraw {
    viz::ui::Rect rect;
    const PaneImage* pane;
    const viz::ui::ImageViewTransform* view;  // nullptr: the whole image
    DisplayMapping mapping;
};

// `v.colourBar` laid out as `layout`; `mapping`: the view's. The draws point into `v`.
std::vector<BarImageDraw> barImageDraws(ViewState& v, const ColourBarLayout& layout, const DisplayMapping& mapping);

}  // namespace airlight
