// A combo's list opens over everything, so an item that hangs below the combo's panel (a view's short
// display strip) still takes the click.
#include <gtest/gtest.h>

#include "ui/font.h"
#include "ui/immediate.h"

namespace viz::ui {
namespace {

TEST(ComboPopup, AnItemBelowThePanelTakesTheClick) {
    static const FontAtlas font = FontAtlas::bake(FontAtlas::kDefaultFontPath, 14.0f);
    Context ctx(font);
    const std::vector<std::string> items = {"a", "b", "c", "d", "e"};
    int index = 0;
    const Rect panel{{0.0f, 0.0f}, {300.0f, 40.0f}};  // room for one row only
    bool changed = false;
    const auto frame = [&](glm::vec2 mouse, bool down) {
        Input in;
        in.mouse = mouse;
        in.mouseDown = down;
        ctx.beginFrame(in, {400.0f, 400.0f});
        ctx.beginPanel("##strip", panel);
        changed = ctx.combo("map", index, items) || changed;
        ctx.endPanel();
        ctx.endFrame();
    };
    frame({-1.0f, -1.0f}, false);
    const Rect field = ctx.widgetRects().at("map");
    const glm::vec2 centre = (field.min + field.max) * 0.5f;
    frame(centre, true);  // press and release: the list opens
    frame(centre, false);
    ASSERT_TRUE(ctx.widgetRects().count("map/e"));
    const Rect e = ctx.widgetRects().at("map/e");
    ASSERT_GT(e.min.y, panel.max.y);  // the item hangs below the panel
    const glm::vec2 at = (e.min + e.max) * 0.5f;
    frame(at, false);
    frame(at, true);
    frame(at, false);
    EXPECT_TRUE(changed);
    EXPECT_EQ(index, 4);
}

}  // namespace
}  // namespace viz::ui
