// What one frame of the window is drawn into, handed to each part that draws (the view grid, the
// comparison grid, the timeline, ...): the two draw lists, the font and scale, the images to draw with
// their display mappings, the clickable rectangles and the named rectangles scripts and the sidecar read.
// The window clears it at the start of every frame (begin) and draws the images and lists after the
// parts have filled it.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "pane_image.h"
#include "screen_map.h"
#include "ui/font.h"
#include "ui/immediate.h"
#include "ui/text_renderer.h"

namespace airlight {

// An image to draw this frame: a pane's texture in `rect`, through a view's pan and zoom (null: the
// whole image) and a display mapping.
struct PaneDraw {
    viz::ui::Rect rect;
    const PaneImage* pane = nullptr;
    const viz::ui::ImageViewTransform* view = nullptr;
    DisplayMapping mapping{};
};

struct FrameCanvas {
    viz::ui::DrawList* overlay = nullptr;     // text and overlays, drawn last in one call
    viz::ui::DrawList* background = nullptr;  // panels behind the images
    const viz::ui::FontAtlas* font = nullptr;
    float scale = 1.0f;  // sizes' factor: the display's content scale times the UI scale

    std::vector<PaneDraw> panes;
    std::vector<std::pair<viz::ui::Rect, std::function<void()>>> hits;  // clickable rectangles, in drawing order
    // What was drawn where, by name (scripts, sidecar): sidebar items "technique:ID", "view:LABEL"; per
    // grid view N "cell:N" (image), "title:N", "strip:N" (its display strip's toggle); the views' images;
    // the comparison grid's tiles "comparison:ID".
    ScreenMap screen;

    // A new frame of size `fb`: empties the lists; "window" names the whole framebuffer.
    void begin(glm::ivec2 fb) {
        overlay->clear();
        background->clear();
        panes.clear();
        hits.clear();
        screen.clear();
        screen.place("window", viz::ui::Rect{{0.0f, 0.0f}, glm::vec2(fb)});
    }
    float line() const { return font->lineHeight(); }
};

// A clickable list entry (the sidebar's techniques and views, a view's display toggle): highlighted when
// selected, lighter under the mouse at `hover`; a click on it calls `onClick`.
void listEntry(FrameCanvas& canvas, glm::vec2 hover, const viz::ui::Rect& r, const std::string& text, bool selected,
               std::function<void()> onClick);

}  // namespace airlight
