// The view grid's arrangements (app/view_grid.h), no window: the default pair, a lesson step's layout, a
// session's grid (and a broken one left alone), split, close and swap, each checked against the layout
// and views written out by hand.
#include <gtest/gtest.h>

#include <stdexcept>

#include "cpu/ui/session_fixture.h"
#include "view_grid.h"

namespace airlight {
namespace {

std::vector<std::string> contents(const ViewGrid& g) {
    std::vector<std::string> out;
    for (int id : g.layout.views()) out.push_back(g.views.at(id).content);
    return out;
}

// Every view of the layout has a state and no state is left without a view; new numbers are free.
void expectConsistent(const ViewGrid& g) {
    const std::vector<int> ids = g.layout.views();
    EXPECT_EQ(ids.size(), g.views.size());
    for (int id : ids) {
        EXPECT_TRUE(g.views.count(id)) << id;
        EXPECT_LT(id, g.nextView) << id;
    }
}

TEST(ViewGrid, TheDefaultPairIsTheFinalFrameBesideTheChosenView) {
    ViewGrid g;
    EXPECT_EQ(g.reset(""), 1);
    EXPECT_EQ(g.layout.toText(), "x(0.5,0,1)");
    EXPECT_EQ(contents(g), (std::vector<std::string>{"final", "airlight"}));
    EXPECT_EQ(g.reset("minmax.tree"), 1);
    EXPECT_EQ(contents(g), (std::vector<std::string>{"final", "minmax.tree"}));
    EXPECT_FALSE(g.lessonGrid);
    expectConsistent(g);
}

TEST(ViewGrid, ALessonStepPutsTwoViewsInThreeColumnsAndThreeInTwoByTwo) {
    ViewGrid g;
    EXPECT_EQ(g.lesson({"minmax.rectified", "minmax.tree"}), 1);
    EXPECT_EQ(g.layout.toText(), "x(0.3333,0,x(0.5,1,2))");
    EXPECT_EQ(contents(g), (std::vector<std::string>{"final", "minmax.rectified", "minmax.tree"}));
    EXPECT_TRUE(g.lessonGrid);
    expectConsistent(g);
    EXPECT_EQ(g.lesson({"a", "b", "c", "d"}), 1);
    EXPECT_EQ(g.layout.toText(), "y(0.5,x(0.5,0,1),x(0.5,2,3))");
    EXPECT_EQ(contents(g), (std::vector<std::string>{"final", "a", "b", "c"})) << "a fourth view is left out";
    expectConsistent(g);
    g.reset("");
    EXPECT_FALSE(g.lessonGrid);
}

TEST(ViewGrid, ASessionsGridComesBackWithItsDisplaySettingsAndABrokenOneChangesNothing) {
    SessionState s = sessionWithGrid();
    SessionState::GridView stray;  // a view the layout does not have: ignored
    stray.id = 9;
    stray.content = "vsv.voxels";
    s.gridViews.push_back(stray);
    ViewGrid g;
    EXPECT_EQ(g.restore(s), 3);
    EXPECT_EQ(g.layout.toText(), "x(0.4,0,y(0.5,3,1))");
    EXPECT_EQ(g.layout.maximised(), 1);
    EXPECT_EQ(contents(g), (std::vector<std::string>{"final", "minmax.rectified", "airlight"}));
    EXPECT_EQ(g.views.at(1).display.difference, DifferenceMode::Relative);
    EXPECT_EQ(g.views.at(1).display.against, "raymarch");
    EXPECT_EQ(g.views.at(1).display.markNegative, 0);
    const ViewState& v = g.views.at(3);
    EXPECT_EQ(v.layer, 2);
    EXPECT_EQ(v.transform.zoom, 8.0);
    EXPECT_EQ(v.transform.center, glm::dvec2(0.25, 0.625));
    EXPECT_EQ(v.display.range, RangeMode::Manual);
    EXPECT_EQ(v.display.manualMin, -0.5f);
    EXPECT_EQ(v.display.manualMax, 2.25f);
    EXPECT_TRUE(v.display.logScale && v.display.stripOpen);
    EXPECT_EQ(v.display.colourMap, ColourMap(2));
    EXPECT_EQ(v.display.difference, DifferenceMode::Off);
    EXPECT_EQ(g.nextView, 4);
    expectConsistent(g);

    // The focus falls back to the first view when the session's is not in its layout.
    s.focusedView = 7;
    EXPECT_EQ(g.restore(s), 0);

    // A layout that does not parse: an error, and the grid as it was.
    SessionState broken = s;
    broken.layout = "x(0.4,0,";
    EXPECT_THROW(g.restore(broken), std::runtime_error);
    EXPECT_EQ(g.layout.toText(), "x(0.4,0,y(0.5,3,1))");
    EXPECT_EQ(g.views.size(), 3u);

    // A session without a grid (older files): the default pair around its view, with its pan and zoom.
    SessionState old;
    old.view = "slices.accumulation";
    old.viewZoom = 4.0;
    old.viewCenter = {0.4, 0.6};
    EXPECT_EQ(g.restore(old), 1);
    EXPECT_EQ(contents(g), (std::vector<std::string>{"final", "slices.accumulation"}));
    EXPECT_EQ(g.views.at(1).transform.zoom, 4.0);
    EXPECT_EQ(g.views.at(1).transform.center, glm::dvec2(0.4, 0.6));
}

TEST(ViewGrid, SplitCloseAndSwapKeepEveryViewAndTheLastViewStays) {
    ViewGrid g;
    int focus = g.reset("");
    const int added = g.split(focus, SplitAxis::Y);
    EXPECT_EQ(added, 2);
    EXPECT_EQ(g.layout.toText(), "x(0.5,0,y(0.5,1,2))");
    expectConsistent(g);
    EXPECT_EQ(g.split(42, SplitAxis::X), -1) << "no such view";
    EXPECT_EQ(g.nextView, 3) << "a refused split takes no number";
    // A split leaves a maximised view first.
    g.layout.toggleMaximise(0);
    EXPECT_EQ(g.split(0, SplitAxis::X), 3);
    EXPECT_EQ(g.layout.maximised(), -1);
    expectConsistent(g);
    g.swap(0, 1);  // view 0 trades places with the next in reading order (3)
    EXPECT_EQ(g.layout.views(), (std::vector<int>{3, 0, 1, 2}));
    focus = g.close(3);
    EXPECT_EQ(focus, 0);
    EXPECT_FALSE(g.views.count(3));
    g.close(1);
    g.close(2);
    expectConsistent(g);
    EXPECT_EQ(g.close(0), -1) << "the last view stays";
    EXPECT_EQ(g.views.size(), 1u);
}

}  // namespace
}  // namespace airlight
