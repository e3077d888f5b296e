// Where a view's image goes in its area: as large as fits, centred across, at its own aspect, except a
// data strip (a table of a few rows, such as a picked ray's 128 bits before and after a scan, or one value
// per VPL; or of a few columns, such as slices' planes along the picked ray), which is stretched to at most
// kMaxStripAspect:1 (or 1:kMaxStripAspect) so that its rows or columns can be seen and pointed at.
#pragma once

#include <glm/glm.hpp>

#include "ui/immediate.h"

namespace airlight {

inline constexpr float kMaxStripAspect = 8.0f;
inline constexpr int kStripMaxRows = 16;  // an image this short (or narrow) and longer than kMaxStripAspect: a strip

// Width / height the image is drawn at.
float displayAspect(glm::ivec2 imageSize);
// The image's rectangle in `area` (top-aligned, centred across).
viz::ui::Rect fitImageRect(const viz::ui::Rect& area, glm::ivec2 imageSize);

}  // namespace airlight
