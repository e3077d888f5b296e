// Laying out and drawing a view's colour bar (colour_bar.h) into a DrawList: the window draws it under
// each image view, a handout under each figure. The ramp and the legend swatches are left to the caller,
// who fills their rectangles with images of the bar's values through the view's own shader
// (ImageDisplay), so that the bar shows exactly the picture's colours.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "colour_bar.h"
#include "ui/font.h"
#include "ui/text_renderer.h"

namespace airlight {

struct ColourBarColours {
    glm::vec4 text, dim, alarm, frame;
};

struct ColourBarLayout {
    viz::ui::Rect ramp;                                        // filled with the bar's values, left to right
    std::vector<std::pair<viz::ui::Rect, std::size_t>> swatches;  // each filled with legend value [index]
    std::string heading;  // units and caption, as drawn (maybe shortened)
    std::string legend;   // every legend entry with its count (the window's tooltip)
};

// Height of a bar for `font` at `scale`: two text lines and margins.
float colourBarHeight(const viz::ui::FontAtlas& font, float scale);

// Draws the bar's text and frames inside `area`: ramp frame and tick labels (or class labels) on the
// left, units and caption then the legend on the right (entries that do not fit are left to `legend`).
ColourBarLayout drawColourBarText(const ColourBar& bar, const viz::ui::Rect& area, const viz::ui::FontAtlas& font,
                                  float scale, viz::ui::DrawList& text, viz::ui::DrawList& frames,
                                  const ColourBarColours& colours);

}  // namespace airlight
