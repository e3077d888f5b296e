// The immediate-mode UI driven by synthetic input, no window: one panel over a 400x300 display, a frame
// at a time, for the widget tests (the toolkit's and the window's parameter widgets).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ui/font.h"
#include "ui/immediate.h"

namespace viz::ui::testing {

inline const FontAtlas& testFont() {
    static const FontAtlas atlas = FontAtlas::bake(FontAtlas::kDefaultFontPath, 14.0f);
    return atlas;
}

struct SyntheticPanel {
    // Runs one frame: the UI is one panel over the whole 400x300 display.
    void frame(const Input& in, const std::function<void(Context&)>& ui) {
        ctx.beginFrame(in, {400.0f, 300.0f});
        ctx.beginPanel("Panel", {{0.0f, 0.0f}, {400.0f, 300.0f}});
        ui(ctx);
        ctx.endPanel();
        ctx.endFrame();
    }
    static Input at(glm::vec2 p, bool down = false) {
        Input in;
        in.mouse = p;
        in.mouseDown = down;
        return in;
    }
    static Input keys(std::vector<Key> k, bool shift = false) {
        Input in;
        in.keys = std::move(k);
        in.shift = shift;
        return in;
    }
    // The centre of the widget drawn last frame under this name (a failure when there is none).
    glm::vec2 centreOf(const std::string& name) const { return widgetCentre(ctx, name); }
    static glm::vec2 widgetCentre(const Context& ui, const std::string& name) {
        const auto it = ui.widgetRects().find(name);
        EXPECT_NE(it, ui.widgetRects().end()) << name;
        return it == ui.widgetRects().end() ? glm::vec2(-1.0f) : (it->second.min + it->second.max) * 0.5f;
    }
    Context ctx{testFont()};
};

}  // namespace viz::ui::testing
