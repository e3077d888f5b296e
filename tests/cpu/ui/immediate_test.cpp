// The immediate-mode widgets driven by synthetic input, no window: clicks, drags, focus and keys, ID
// stability, popups, scrolling and clipping.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <functional>

#include "ui/font.h"
#include "ui/immediate.h"
#include "cpu/ui/synthetic_panel.h"

namespace viz::ui {
namespace {

class ImmediateTest : public ::testing::Test, protected testing::SyntheticPanel {};

TEST_F(ImmediateTest, AButtonClicksOnReleaseOverItAfterAPressOnIt) {
    int clicks = 0;
    const auto ui = [&](Context& c) { clicks += c.button("Render"); };
    frame({}, ui);
    const glm::vec2 p = centreOf("Render");
    frame(at(p), ui);
    EXPECT_NE(ctx.hot(), 0u);  // hovered
    frame(at(p, true), ui);
    EXPECT_EQ(clicks, 0);  // not on press
    EXPECT_NE(ctx.active(), 0u);
    frame(at(p, false), ui);
    EXPECT_EQ(clicks, 1);
    EXPECT_EQ(ctx.active(), 0u);
    // Pressed elsewhere, released over it: no click. Pressed on it, released elsewhere: no click.
    frame(at({5.0f, 290.0f}, true), ui);
    frame(at(p, false), ui);
    frame(at(p, true), ui);
    frame(at({5.0f, 290.0f}, false), ui);
    EXPECT_EQ(clicks, 1);
}

TEST_F(ImmediateTest, IdsAreStableAcrossFramesAndScopedByTheIdStack) {
    Id first = 0, again = 0, a1 = 0, a2 = 0, scoped = 0;
    frame({}, [&](Context& c) {
        first = c.idOf("Size");
        a1 = c.idOf("A##1");
        a2 = c.idOf("A##2");
        c.pushId("light 2");
        scoped = c.idOf("Size");
        c.popId();
    });
    frame({}, [&](Context& c) { again = c.idOf("Size"); });
    EXPECT_EQ(first, again);
    EXPECT_NE(a1, a2);
    EXPECT_NE(first, scoped);
    EXPECT_NE(first, 0u);
}

TEST_F(ImmediateTest, CheckboxAndRadioChangeTheirValues) {
    bool shadows = false;
    int mode = 0;
    const auto ui = [&](Context& c) {
        c.checkbox("Shadows", shadows);
        c.radio("Nearest", mode, 0);
        c.radio("PCF", mode, 1);
    };
    frame({}, ui);
    const glm::vec2 box = centreOf("Shadows"), pcf = centreOf("PCF");
    frame(at(box, true), ui);
    frame(at(box, false), ui);
    EXPECT_TRUE(shadows);
    frame(at(pcf, true), ui);
    frame(at(pcf, false), ui);
    EXPECT_EQ(mode, 1);
}

TEST_F(ImmediateTest, SlidersFollowTheMouseLinearlyOrLogarithmically) {
    float linear = 0.0f, logarithmic = 1.0f;
    int count = 4;
    const auto ui = [&](Context& c) {
        c.sliderFloat("Linear", linear, 0.0f, 10.0f);
        c.sliderFloat("Log", logarithmic, 1e-3f, 1e3f, true);
        c.sliderInt("Count", count, 1, 9);
    };
    frame({}, ui);
    const Rect lin = ctx.widgetRects().at("Linear"), lg = ctx.widgetRects().at("Log"), cnt = ctx.widgetRects().at("Count");
    const auto x = [](const Rect& r, float t) { return r.min.x + t * (r.max.x - r.min.x); };
    frame(at({x(lin, 0.75f), lin.min.y + 2.0f}, true), ui);
    EXPECT_NEAR(linear, 7.5f, 1e-4f);
    frame(at({x(lin, 0.25f), lin.min.y + 2.0f}, true), ui);  // dragging keeps following
    EXPECT_NEAR(linear, 2.5f, 1e-4f);
    frame(at({x(lin, 0.25f), lin.min.y + 2.0f}, false), ui);
    frame(at({x(lg, 0.5f), lg.min.y + 2.0f}, true), ui);
    EXPECT_NEAR(logarithmic, 1.0f, 1e-4f);  // the geometric middle of 1e-3 and 1e3
    frame(at({x(lg, 0.5f), lg.min.y + 2.0f}, false), ui);
    frame(at({x(cnt, 1.0f) - 0.01f, cnt.min.y + 2.0f}, true), ui);
    EXPECT_EQ(count, 9);
    frame(at({x(cnt, 1.0f) - 0.01f, cnt.min.y + 2.0f}, false), ui);
    // Keyboard: the focused integer slider steps by one.
    frame(keys({Key::Left}), ui);
    EXPECT_EQ(count, 8);
}

TEST_F(ImmediateTest, DragChangesByTheSpeedPerPixelAndShiftIsFiner) {
    float g = 0.0f;
    const auto ui = [&](Context& c) { c.dragFloat("g", g, 0.01f, -0.99f, 0.99f); };
    frame({}, ui);
    const glm::vec2 p = centreOf("g");
    frame(at(p, true), ui);
    frame(at(p + glm::vec2(20.0f, 0.0f), true), ui);
    EXPECT_NEAR(g, 0.2f, 1e-5f);
    Input fine = at(p + glm::vec2(20.0f, 0.0f), true);
    fine.shift = true;
    frame(fine, ui);
    EXPECT_NEAR(g, 0.02f, 1e-5f);
    frame(at(p + glm::vec2(500.0f, 0.0f), true), ui);
    EXPECT_FLOAT_EQ(g, 0.99f);  // clamped
}

TEST_F(ImmediateTest, TabCyclesFocusAndEnterPressesTheFocusedButton) {
    int a = 0, b = 0;
    bool flag = false;
    const auto ui = [&](Context& c) {
        a += c.button("A");
        c.checkbox("Flag", flag);
        b += c.button("B");
    };
    frame({}, ui);
    EXPECT_EQ(ctx.focused(), 0u);
    frame(keys({Key::Tab}), ui);  // focus moves at the end of the frame
    frame(keys({Key::Tab}), ui);
    frame(keys({Key::Tab}), ui);
    frame(keys({Key::Enter}), ui);
    EXPECT_EQ(b, 1);
    EXPECT_EQ(a, 0);
    frame(keys({Key::Tab}), ui);  // wraps around to A
    frame(keys({Key::Space}), ui);
    EXPECT_EQ(a, 1);
    frame(keys({Key::Tab}, true), ui);  // Shift+Tab goes back, wrapping to B
    frame(keys({Key::Enter}), ui);
    EXPECT_EQ(b, 2);
    EXPECT_FALSE(flag);
}

TEST_F(ImmediateTest, TextInputEditsUtf8AndHoldsShortcutsWhileFocused) {
    std::string name = "forest";
    bool shortcutSeen = false;
    const auto ui = [&](Context& c) {
        c.textInput("Scene", name);
        shortcutSeen |= c.shortcut(Key::F5);
    };
    frame({}, ui);
    const glm::vec2 p = centreOf("Scene");
    frame(at(p, true), ui);
    frame(at(p, false), ui);
    Input typing;
    typing.text = "-\xC3\xA9t\xC3\xA9";  // "-été"
    frame(typing, ui);
    EXPECT_EQ(name, "forest-\xC3\xA9t\xC3\xA9");
    frame(keys({Key::Backspace, Key::Backspace}), ui);  // two code points, three bytes
    EXPECT_EQ(name, "forest-\xC3\xA9");
    frame(keys({Key::Home, Key::Delete}), ui);
    EXPECT_EQ(name, "orest-\xC3\xA9");
    frame(keys({Key::F5}), ui);
    EXPECT_FALSE(shortcutSeen);  // typing field focused: F5 is not a shortcut
    frame(keys({Key::Enter}), ui);  // done editing
    frame(keys({Key::F5}), ui);
    EXPECT_TRUE(shortcutSeen);
}

// A path longer than its field scrolls so the caret stays in view, and Ctrl+Backspace takes back one
// folder of it (or one word) at a time.
TEST_F(ImmediateTest, ALongTextScrollsToItsCaretAndCtrlBackspaceTakesOneFolder) {
    std::string path;
    const auto ui = [&](Context& c) { c.textInput("open glTF", path); };
    frame({}, ui);
    const glm::vec2 p = centreOf("open glTF");
    frame(at(p, true), ui);
    frame(at(p, false), ui);
    Input typing;
    typing.text = "/home/someone/projects/scenes/a long folder name/another folder/cathedral.gltf";
    frame(typing, ui);
    ASSERT_EQ(path, typing.text);
    // The caret: a quad one pixel wide and a line high, drawn inside the field (clipping drops what lies
    // outside it; without the scroll the caret sat far past the field's right edge).
    const float line = testing::testFont().lineHeight();
    int carets = 0;
    const auto& v = ctx.drawList().vertices();
    for (std::size_t i = 0; i + 5 < v.size(); i += 6) {
        const glm::vec2 size = v[i + 2].position - v[i].position;
        if (std::abs(size.x - 1.0f) < 1e-3f && std::abs(size.y - line) < 1e-3f) ++carets;
    }
    EXPECT_EQ(carets, 1) << "the caret is drawn, inside the field";
    Input ctrlBackspace = keys({Key::Backspace});
    ctrlBackspace.ctrl = true;
    frame(ctrlBackspace, ui);
    EXPECT_EQ(path, "/home/someone/projects/scenes/a long folder name/another folder/");
    frame(ctrlBackspace, ui);
    EXPECT_EQ(path, "/home/someone/projects/scenes/a long folder name/another ");
    frame(keys({Key::Backspace}), ui);
    EXPECT_EQ(path, "/home/someone/projects/scenes/a long folder name/another");
}

TEST_F(ImmediateTest, ComboOpensChoosesAndItsListCoversTheWidgetsBelow) {
    int technique = 0, below = 0;
    const std::vector<std::string> items = {"raymarch", "slices", "polyvol"};
    const auto ui = [&](Context& c) {
        c.combo("Technique", technique, items);
        below += c.button("Below");
    };
    frame({}, ui);
    const glm::vec2 field = centreOf("Technique");
    frame(at(field, true), ui);
    frame(at(field, false), ui);  // open now
    const glm::vec2 choice = centreOf("Technique/polyvol");
    // The list lies over the button below: pressing on the list does not press the button.
    frame(at(choice, true), ui);
    frame(at(choice, false), ui);
    EXPECT_EQ(technique, 2);
    EXPECT_EQ(below, 0);
    frame({}, ui);
    EXPECT_EQ(ctx.widgetRects().count("Technique/polyvol"), 0u);  // closed after the choice
}

TEST_F(ImmediateTest, CollapsingHeaderTogglesAndRemembersItsState) {
    bool open = false;
    const auto ui = [&](Context& c) { open = c.collapsingHeader("Medium", true); };
    frame({}, ui);
    EXPECT_TRUE(open);
    const glm::vec2 p = centreOf("Medium");
    frame(at(p, true), ui);
    frame(at(p, false), ui);
    EXPECT_FALSE(open);
    frame({}, ui);
    EXPECT_FALSE(open);
}

TEST_F(ImmediateTest, TabsAndSplitter) {
    int tab = 0;
    float fraction = 0.5f;
    const Rect area{{0.0f, 200.0f}, {400.0f, 300.0f}};
    const auto ui = [&](Context& c) {
        c.tabs("Views", tab, {"Final", "Shadow map", "L_air"});
        c.splitter("Split", area, true, fraction);
    };
    frame({}, ui);
    const glm::vec2 third = centreOf("Views/L_air");
    frame(at(third, true), ui);
    frame(at(third, false), ui);
    EXPECT_EQ(tab, 2);
    frame(at({200.0f, 250.0f}, true), ui);
    frame(at({300.0f, 250.0f}, true), ui);
    EXPECT_NEAR(fraction, 0.75f, 1e-5f);
    frame(at({399.0f, 250.0f}, true), ui);
    EXPECT_NEAR(fraction, 0.95f, 1e-5f);  // kept inside the area
}

TEST_F(ImmediateTest, PanelsScrollAndHiddenWidgetsCannotBeClicked) {
    std::vector<int> clicks(40, 0);
    const auto ui = [&](Context& c) {
        for (int i = 0; i < 40; ++i) clicks[std::size_t(i)] += c.button("Row " + std::to_string(i));
    };
    frame({}, ui);
    const Rect last = ctx.widgetRects().at("Row 39");
    EXPECT_GT(last.min.y, 300.0f);  // below the panel
    // Pressing where row 39 would be (outside the panel) does nothing.
    frame(at({200.0f, 299.0f}, true), ui);
    frame(at({200.0f, 299.0f}, false), ui);
    for (int i = 0; i < 40; ++i) EXPECT_LE(clicks[std::size_t(i)], 1);
    clicks.assign(40, 0);
    // Scroll to the end: row 39 comes into view and takes clicks.
    Input wheel = at({200.0f, 150.0f});
    wheel.wheel = -100.0f;
    frame(wheel, ui);
    frame({}, ui);
    const Rect shown = ctx.widgetRects().at("Row 39");
    EXPECT_LE(shown.max.y, 300.0f);
    const glm::vec2 p = (shown.min + shown.max) * 0.5f;
    frame(at(p, true), ui);
    frame(at(p, false), ui);
    EXPECT_EQ(clicks[39], 1);
    // Nothing drawn leaves the panel's content area (clipping).
    for (const UiVertex& v : ctx.drawList().vertices()) EXPECT_LE(v.position.y, 300.0f + 1e-3f);
}

TEST_F(ImmediateTest, TooltipAppearsAfterTheHoverDelay) {
    const auto ui = [&](Context& c) {
        c.button("Help");
        c.tooltip("Opens the lesson");
    };
    frame({}, ui);
    const glm::vec2 p = centreOf("Help");
    ctx.setTime(0.0);
    frame(at(p), ui);
    const std::size_t without = ctx.drawList().vertices().size();
    ctx.setTime(0.6);
    frame(at(p), ui);
    EXPECT_GT(ctx.drawList().vertices().size(), without);  // tooltip box and text added
}

TEST_F(ImmediateTest, DISABLED_FrameCostWithManyWidgets) {
    // Benchmark (not a test): CPU time of a frame with 300 widgets of every kind.
    float f = 0.5f;
    bool b = false;
    int k = 0;
    std::string text = "airlight";
    const auto ui = [&](Context& c) {
        for (int i = 0; i < 50; ++i) {
            c.pushId(i);
            c.collapsingHeader("Section", true);
            c.button("Button");
            c.checkbox("Check", b);
            c.sliderFloat("Slider", f, 0.0f, 1.0f);
            c.combo("Combo", k, {"a", "b", "c"});
            c.textInput("Text", text);
            c.popId();
        }
    };
    std::vector<double> ms;
    for (int i = 0; i < 200; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        // A panel tall enough that every widget is laid out, drawn and hit-tested (none clipped away).
        ctx.beginFrame(at({100.0f, 100.0f}), {1200.0f, 20000.0f});
        ctx.beginPanel("All", {{0.0f, 0.0f}, {1200.0f, 20000.0f}});
        ui(ctx);
        ctx.endPanel();
        ctx.endFrame();
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    std::sort(ms.begin(), ms.end());
    std::printf("300 widgets: median %.3f ms per frame, %zu vertices\n", ms[ms.size() / 2],
                ctx.drawList().vertices().size());
}

}  // namespace
}  // namespace viz::ui
