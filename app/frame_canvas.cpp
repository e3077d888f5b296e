// The frame's canvas helpers (frame_canvas.h).
#include "frame_canvas.h"

#include "ui/theme.h"

namespace airlight {

void listEntry(FrameCanvas& canvas, glm::vec2 hover, const viz::ui::Rect& r, const std::string& text, bool selected,
               std::function<void()> onClick) {
    namespace theme = viz::ui::theme;
    const float s = canvas.scale;
    if (selected) canvas.overlay->rect(r, theme::kHighlight);
    else if (r.contains(hover)) canvas.overlay->rect(r, theme::kHover);
    canvas.overlay->textClipped({r.min.x + 6.0f * s, r.min.y + 1.0f * s}, text, selected ? theme::kText : theme::kDim,
                                r.max.x - 4.0f * s);
    canvas.hits.push_back({r, std::move(onClick)});
}

}  // namespace airlight
