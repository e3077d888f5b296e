// One view cell drawn without a window (app/view_cell.h): where its parts go, what it names for scripts,
// what the readout says under the mouse and at the linked pixel (checked against texels placed by hand),
// which of the window's parts it asks for, and the display toggle's click. Cells here are short enough
// that the colour bar (which uploads its ramp as a texture) is left out (under 11 lines of text plus 42
// pixels); its place is a layout test.
#include <gtest/gtest.h>

#include <memory>

#include "synthetic_panel.h"
#include "view_cell.h"

namespace airlight {
namespace {

using viz::ui::Rect;
using viz::ui::testing::SyntheticPanel;
using viz::ui::testing::testFont;

struct ViewCell : ::testing::Test {
    viz::ui::DrawList overlay{testFont()}, background{testFont()};
    FrameCanvas canvas;
    SyntheticPanel panel;
    ViewCellFrame frame;

    ViewCell() {
        canvas.overlay = &overlay;
        canvas.background = &background;
        canvas.font = &testFont();
        canvas.begin({400, 300});
        frame.canvas = &canvas;
        frame.ui = &panel.ctx;
        frame.haveOutput = true;
        frame.frameSize = {8, 6};
        frame.title.haveOutput = true;
        frame.title.contentCount = 2;
    }
    // An 8x6 L_air view whose CPU copy holds (x + 10 y, 1, 2) at texel (x, y), row 0 at the top. The
    // texture name stands for an upload: no GL is called while the CPU copy answers.
    static ViewState airlightView() {
        ViewState v;
        v.content = "airlight";
        v.pane.id = "airlight";
        v.pane.texture = 1;
        v.pane.size = {8, 6};
        v.pane.channels = 3;
        v.values = viz::Image(8, 6, 3);
        for (int y = 0; y < 6; ++y)
            for (int x = 0; x < 8; ++x) {
                v.values.at(x, y, 0) = float(x + 10 * y);
                v.values.at(x, y, 1) = 1.0f;
                v.values.at(x, y, 2) = 2.0f;
            }
        v.meaningful = 3;
        return v;
    }
    // Draws one cell in one UI frame with the mouse at `hover`.
    ViewCellDrawn draw(int id, ViewState& v, const Rect& cell, const ViewCellParts& parts, glm::vec2 hover = glm::vec2(-1.0f)) {
        ViewCellDrawn drawn;
        frame.hover = hover;
        panel.frame(SyntheticPanel::at(hover), [&](viz::ui::Context&) {
            layOutViewCell(frame, v, cell);
            drawn = drawViewCell(frame, id, v, parts);
        });
        return drawn;
    }
    // The window point over the centre of texel (x, y) of the view's image as laid out (whole image shown).
    static glm::vec2 over(const ViewState& v, int x, int y) {
        return v.image.min + glm::vec2((float(x) + 0.5f) / 8.0f, (float(y) + 0.5f) / 6.0f) * v.image.size();
    }
};

bool cellInside(const Rect& inner, const Rect& outer) {
    return inner.min.x >= outer.min.x - 1e-3f && inner.min.y >= outer.min.y - 1e-3f && inner.max.x <= outer.max.x + 1e-3f &&
           inner.max.y <= outer.max.y + 1e-3f;
}

TEST_F(ViewCell, TheCellNamesItsPartsForScriptsAndTheToggleCallsTheWindow) {
    ViewState v = airlightView();
    const Rect cell{{10.0f, 20.0f}, {330.0f, 180.0f}};
    int toggled = 0;
    ViewCellParts parts;
    parts.screenSpace = true;
    parts.toggleStrip = [&] { ++toggled; };
    frame.stoppedEarly = "stopped after stage 2 of 5";
    draw(3, v, cell, parts);
    const std::map<std::string, Rect> noWidgets;
    for (const char* name : {"title:3", "strip:3", "cell:3"}) {
        const std::optional<Rect> r = canvas.screen.find(name, noWidgets);
        ASSERT_TRUE(r) << name;
        EXPECT_TRUE(cellInside(*r, cell)) << name;
    }
    EXPECT_TRUE(cellInside(*canvas.screen.find("strip:3", noWidgets), *canvas.screen.find("title:3", noWidgets)));
    ASSERT_EQ(canvas.screen.views().size(), 1u);
    const ScreenMap::View& shown = canvas.screen.views()[0];
    EXPECT_EQ(shown.name, "airlight");
    EXPECT_EQ(shown.cell, 3);
    // The title the sidecar reads carries where the run stopped.
    EXPECT_NE(shown.title.find("[stopped after stage 2 of 5]"), std::string::npos) << shown.title;
    EXPECT_EQ(canvas.panes.size(), 1u);
    // The toggle is the one clickable rectangle; a click on it is the window's.
    ASSERT_EQ(canvas.hits.size(), 1u);
    EXPECT_EQ(canvas.hits[0].first.min, canvas.screen.find("strip:3", noWidgets)->min);
    canvas.hits[0].second();
    EXPECT_EQ(toggled, 1);

    // Before any run the view is named "none" and says nothing of a stop.
    canvas.begin({400, 300});
    frame.haveOutput = false;
    frame.title.haveOutput = false;
    draw(3, v, cell, parts);
    ASSERT_EQ(canvas.screen.views().size(), 1u);
    EXPECT_EQ(canvas.screen.views()[0].name, "none");
    EXPECT_EQ(canvas.screen.views()[0].title.find("stopped"), std::string::npos);
}

TEST_F(ViewCell, TheReadoutIsTheHoveredTexelsValueFromTheCpuCopy) {
    ViewState v = airlightView();
    const Rect cell{{0.0f, 0.0f}, {320.0f, 150.0f}};
    ViewCellParts parts;
    parts.screenSpace = true;
    draw(1, v, cell, parts);  // lays the cell out
    frame.hovered = 1;
    const ViewCellDrawn drawn = draw(1, v, cell, parts, over(v, 5, 2));
    EXPECT_EQ(drawn.readout, "pixel (5, 2)  =  25  1  2");
    // The mouse outside the image: no readout.
    frame.hovered = -1;
    EXPECT_EQ(draw(1, v, cell, parts, {1.0f, 1.0f}).readout, "");
}

TEST_F(ViewCell, OtherViewsFollowTheLinkedPixelAndOnlyAlgorithmViewsAskForTheTechniquesMarks) {
    ViewState frameView = airlightView(), algorithmView = airlightView();
    algorithmView.content = algorithmView.pane.id = "rectified";
    const Rect cell{{0.0f, 0.0f}, {320.0f, 150.0f}};
    int markersAsked = 0, overlaysDrawn = 0;
    ViewCellParts screen, algorithm;
    screen.screenSpace = true;
    algorithm.screenSpace = false;
    for (ViewCellParts* p : {&screen, &algorithm}) {
        p->markers = [&] {
            ++markersAsked;
            return std::vector<viz::ViewMarker>{};
        };
        p->overlays = [&](viz::ui::DrawList&) { ++overlaysDrawn; };
    }
    frame.hovered = 7;  // a view elsewhere holds the mouse over frame pixel (2, 4)
    frame.linkedPixel = glm::ivec2(2, 4);
    EXPECT_EQ(draw(1, frameView, cell, screen).readout, "linked (2, 4)  =  42  1  2");
    EXPECT_EQ(markersAsked, 0);
    // An algorithm-space view has no pixel of the frame to read: the technique marks what it can.
    EXPECT_EQ(draw(2, algorithmView, cell, algorithm).readout, "");
    EXPECT_EQ(markersAsked, 1);
    EXPECT_EQ(overlaysDrawn, 2);
    // No linked pixel: nothing asked.
    frame.linkedPixel.reset();
    draw(2, algorithmView, cell, algorithm);
    EXPECT_EQ(markersAsked, 1);
}

TEST_F(ViewCell, PlotsTakeTheWholeImageAreaWithoutOverlaysOrAColourBar) {
    ViewState v;
    v.content = v.pane.id = "profile";
    viz::PlotData plot;
    plot.title = "profile";
    v.pane.plots = {plot, plot};
    v.colourBar.kind = ColourBar::Kind::Ramp;  // left from when the view showed an image
    const Rect cell{{0.0f, 0.0f}, {300.0f, 400.0f}};
    int overlaysDrawn = 0;
    ViewCellParts parts;
    parts.overlays = [&](viz::ui::DrawList&) { ++overlaysDrawn; };
    draw(4, v, cell, parts);
    EXPECT_EQ(overlaysDrawn, 0);
    EXPECT_EQ(v.colourBar.kind, ColourBar::Kind::None);
    EXPECT_FLOAT_EQ(v.image.min.y, v.title.max.y);
    EXPECT_FLOAT_EQ(v.image.min.x, cell.min.x);
    EXPECT_FLOAT_EQ(v.image.max.x, cell.max.x);
    EXPECT_EQ(v.bar.size().y, 0.0f);
    ASSERT_EQ(canvas.screen.views().size(), 1u);
    EXPECT_EQ(canvas.screen.views()[0].name, "profile");
    EXPECT_TRUE(canvas.panes.empty());
}

TEST_F(ViewCell, LayoutKeepsTheImagesAspectPutsTheBarUnderItAndTheOpenStripAtTheBottom) {
    ViewState v = airlightView();
    const Rect tall{{0.0f, 0.0f}, {400.0f, 600.0f}};
    panel.frame({}, [&](viz::ui::Context&) { layOutViewCell(frame, v, tall); });
    EXPECT_NEAR(v.image.size().x / v.image.size().y, 8.0f / 6.0f, 0.01f);
    EXPECT_TRUE(cellInside(v.image, tall));
    EXPECT_GE(v.image.min.y, v.title.max.y);
    // Room enough: the colour bar under the image, across the cell.
    ASSERT_GT(v.bar.size().y, 0.0f);
    EXPECT_GE(v.bar.min.y, v.image.max.y);
    EXPECT_TRUE(cellInside(v.bar, tall));
    EXPECT_EQ(v.strip.size().y, 0.0f);

    v.display.stripOpen = true;
    panel.frame({}, [&](viz::ui::Context&) { layOutViewCell(frame, v, tall); });
    ASSERT_GT(v.strip.size().y, 0.0f);
    EXPECT_FLOAT_EQ(v.strip.max.y, tall.max.y);
    EXPECT_GE(v.strip.min.y, std::max(v.image.max.y, v.bar.max.y));
    // At most 60 % of what the title and the readout line leave.
    const float readout = testFont().lineHeight() + 6.0f;
    EXPECT_LE(v.strip.size().y, 0.6f * (tall.size().y - v.title.size().y - readout) + 1e-3f);

    // A short cell drops the bar rather than squeeze the image; an empty pane keeps the frame's aspect.
    ViewState empty;
    frame.frameSize = {16, 4};
    const Rect shortCell{{0.0f, 0.0f}, {400.0f, 150.0f}};
    panel.frame({}, [&](viz::ui::Context&) {
        layOutViewCell(frame, v, shortCell);
        layOutViewCell(frame, empty, shortCell);
    });
    EXPECT_EQ(v.bar.size().y, 0.0f);
    EXPECT_NEAR(empty.image.size().x / empty.image.size().y, 4.0f, 0.05f);
}

TEST_F(ViewCell, ANarrowCellShortensItsTitleAndSaysSo) {
    ViewState v = airlightView();
    ViewCellParts parts;
    frame.stoppedEarly = "stopped after stage 2 of 5 (the rectified shadow map, before the min-max walk)";
    EXPECT_TRUE(draw(1, v, {{0.0f, 0.0f}, {120.0f, 150.0f}}, parts).titleElided);
    EXPECT_TRUE(v.titleElided);
    canvas.begin({400, 300});
    frame.stoppedEarly.clear();
    EXPECT_FALSE(draw(1, v, {{0.0f, 0.0f}, {400.0f, 150.0f}}, parts).titleElided);
}

}  // namespace
}  // namespace airlight
