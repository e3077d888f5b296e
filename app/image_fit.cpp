#include "image_fit.h"

#include <algorithm>

namespace airlight {

float displayAspect(glm::ivec2 size) {
    const float aspect = float(std::max(1, size.x)) / float(std::max(1, size.y));
    if (size.y <= kStripMaxRows) return std::min(aspect, kMaxStripAspect);
    if (size.x <= kStripMaxRows) return std::max(aspect, 1.0f / kMaxStripAspect);
    return aspect;
}

viz::ui::Rect fitImageRect(const viz::ui::Rect& area, glm::ivec2 imageSize) {
    const float aspect = displayAspect(imageSize);
    float w = area.size().x, h = w / aspect;
    if (h > area.size().y) {
        h = area.size().y;
        w = h * aspect;
    }
    const float x = area.min.x + 0.5f * (area.size().x - w);
    return {{x, area.min.y}, {x + w, area.min.y + h}};
}

}  // namespace airlight
