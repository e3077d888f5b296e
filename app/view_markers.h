// A technique's marks for the linked pixel (viz::ViewMarker: a ray's crossings, the texels it reads, its
// walk) drawn over a view: data uv (row 0 = the first row stored; a GL texture's row 0, shown at the
// bottom, also when the pane shows a layer read back) -> the view's image uv -> window. Marks of another
// layer (cube face, array layer) than the one shown are left out; the key names their layers. The first mark is thin cyan, the others
// yellow; an unlabelled mark continues the previous one (a polyline). Labels stay inside the image and off
// each other; more than two labelled points get numbers beside them (clear of each other) and their
// labels, after the lines' labels, go into a key at the image's bottom left.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "debug/technique.h"
#include "ui/text_renderer.h"
#include "view_state.h"

namespace airlight {

// A small cross with a dark outline, so that it shows on bright and dark images alike; nothing when `c`
// is outside `clip`. `scale`: the window's size factor.
void drawCrosshair(viz::ui::DrawList& dl, glm::vec2 c, const viz::ui::Rect& clip, float scale);

// Where the marks not drawn on `layer` lie, for the key: "marks on layers 2 and 5 of 6 (, / . to
// step)" (layers counted from 1, as the view's title counts them); empty when every mark is on `layer` or
// on all layers.
std::string otherLayersNote(const std::vector<viz::ViewMarker>& marks, int layer, int layers);

// Draws `marks` over `v`'s image (clipped to it). Returns the rectangles of the labels and numbers placed
// beside the marks (not the key's), for tests.
std::vector<viz::ui::Rect> drawViewMarkers(viz::ui::DrawList& dl, const viz::ui::FontAtlas& font, float scale,
                                           const ViewState& v, const std::vector<viz::ViewMarker>& marks);

}  // namespace airlight
