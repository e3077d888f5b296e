// Zoomed in until a texel is large enough to hold its value, a view writes the value into every texel it
// shows ("%.3g", one line per channel where the texel has room for them, else the first). A plain function
// of the view's geometry and a source of values, so the window can draw the labels from the view's CPU
// copy (or, before that exists, a read of the visible block) and tests can check them without a window.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "ui/font.h"
#include "ui/image_view.h"
#include "ui/immediate.h"

namespace airlight {

// The texels of a view's image that can be labelled, inclusive, in image rows (row 0 at the top); none
// when a texel is under 4.2 text lines wide or more than 4096 texels are visible.
struct TexelBlock {
    glm::ivec2 lo{0}, hi{-1};
    glm::ivec2 count() const { return hi - lo + 1; }
};
std::optional<TexelBlock> labelledTexels(glm::ivec2 paneSize, const viz::ui::Rect& image,
                                         const viz::ui::ImageViewTransform& view, float lineHeight);

struct TexelLabel {
    glm::vec2 at;  // the text's top-left corner, window pixels
    std::string text;
    float clipX = 0.0f;  // where the text must end: the texel's shown right edge
};
// The labels of `block`, `value(x, y)` giving texel (x, y) (image rows), `channels` (1 to 3) written when
// there is room for all of them. A texel shown too little (cut by the view's edge) gets none.
std::vector<TexelLabel> texelLabels(const TexelBlock& block, glm::ivec2 paneSize, const viz::ui::Rect& image,
                                    const viz::ui::ImageViewTransform& view, int channels,
                                    const std::function<glm::vec4(int, int)>& value,
                                    const viz::ui::FontAtlas& font, float scale);

// The texel of a pane under a window point, through the view's pan and zoom (row 0 at the top), clamped
// to the pane.
glm::ivec2 texelUnder(glm::ivec2 paneSize, const viz::ui::Rect& image, const viz::ui::ImageViewTransform& view,
                      glm::vec2 p);

}  // namespace airlight
