// The view grid's layout model (app/view_layout.h): split, close, swap, maximise, arrangement, hit
// testing and the text form kept in session files.
#include <gtest/gtest.h>

#include <stdexcept>

#include "view_layout.h"

namespace airlight {
namespace {

using viz::ui::Rect;

const Rect kArea{{0.0f, 0.0f}, {200.0f, 100.0f}};

TEST(ViewLayout, SplittingPutsTheNewViewBesideOrBelow) {
    ViewLayout layout(0);
    ASSERT_TRUE(layout.split(0, SplitAxis::X, 1));
    ASSERT_TRUE(layout.split(1, SplitAxis::Y, 2));
    EXPECT_EQ(layout.views(), (std::vector<int>{0, 1, 2}));
    const auto cells = layout.arrange(kArea, 0.0f);
    ASSERT_EQ(cells.size(), 3u);
    // 0 on the left half; 1 over 2 on the right half.
    EXPECT_EQ(cells[0].rect.max.x, 100.0f);
    EXPECT_EQ(cells[1].rect.min.x, 100.0f);
    EXPECT_EQ(cells[1].rect.max.y, 50.0f);
    EXPECT_EQ(cells[2].rect.min.y, 50.0f);
    EXPECT_EQ(cells[2].rect.max, glm::vec2(200.0f, 100.0f));
}

TEST(ViewLayout, SplittingRefusesUnknownAndRepeatedViews) {
    ViewLayout layout(0);
    EXPECT_FALSE(layout.split(7, SplitAxis::X, 1));  // no view 7
    EXPECT_FALSE(layout.split(0, SplitAxis::X, 0));  // 0 is already there
    EXPECT_EQ(layout.count(), 1);
}

TEST(ViewLayout, TheGapSeparatesCellsAndTheyFillTheArea) {
    ViewLayout layout(0);
    layout.split(0, SplitAxis::X, 1, 0.25f);
    const auto cells = layout.arrange(kArea, 10.0f);
    ASSERT_EQ(cells.size(), 2u);
    EXPECT_FLOAT_EQ(cells[0].rect.max.x, 0.25f * 190.0f);
    EXPECT_FLOAT_EQ(cells[1].rect.min.x - cells[0].rect.max.x, 10.0f);
    EXPECT_FLOAT_EQ(cells[1].rect.max.x, 200.0f);
}

TEST(ViewLayout, ClosingGivesTheSpaceToTheSiblingAndKeepsTheLastView) {
    ViewLayout layout(0);
    layout.split(0, SplitAxis::X, 1);
    layout.split(1, SplitAxis::Y, 2);
    ASSERT_TRUE(layout.close(1));
    EXPECT_EQ(layout.views(), (std::vector<int>{0, 2}));
    const auto cells = layout.arrange(kArea, 0.0f);
    EXPECT_EQ(cells[1].view, 2);
    EXPECT_EQ(cells[1].rect.min, glm::vec2(100.0f, 0.0f));  // 2 now has the whole right half
    EXPECT_EQ(cells[1].rect.max, glm::vec2(200.0f, 100.0f));
    EXPECT_FALSE(layout.close(9));
    ASSERT_TRUE(layout.close(0));
    EXPECT_FALSE(layout.close(2));  // the last view stays
    EXPECT_EQ(layout.views(), std::vector<int>{2});
}

TEST(ViewLayout, SwappingExchangesPlaces) {
    ViewLayout layout(0);
    layout.split(0, SplitAxis::X, 1);
    layout.split(1, SplitAxis::Y, 2);
    const auto before = layout.arrange(kArea, 0.0f);
    ASSERT_TRUE(layout.swap(0, 2));
    const auto after = layout.arrange(kArea, 0.0f);
    EXPECT_EQ(after[0].view, 2);
    EXPECT_EQ(after[0].rect.max, before[0].rect.max);
    EXPECT_EQ(after[2].view, 0);
    EXPECT_FALSE(layout.swap(0, 0));
    EXPECT_FALSE(layout.swap(0, 5));
}

TEST(ViewLayout, MaximisingShowsOneViewAndTogglesBack) {
    ViewLayout layout(0);
    layout.split(0, SplitAxis::X, 1);
    layout.toggleMaximise(1);
    auto cells = layout.arrange(kArea, 4.0f);
    ASSERT_EQ(cells.size(), 1u);
    EXPECT_EQ(cells[0].view, 1);
    EXPECT_EQ(cells[0].rect.max, kArea.max);
    layout.toggleMaximise(1);
    EXPECT_EQ(layout.arrange(kArea, 4.0f).size(), 2u);
    layout.toggleMaximise(0);
    layout.close(0);  // closing the maximised view restores the grid
    EXPECT_EQ(layout.maximised(), -1);
}

TEST(ViewLayout, DividersLieInTheGapsAndTheirTracksPlaceTheGapAtTheFraction) {
    ViewLayout layout(0);
    layout.split(0, SplitAxis::X, 1, 0.3f);
    layout.split(1, SplitAxis::Y, 2);
    const float gap = 4.0f;
    const auto dividers = layout.dividers(kArea, gap);
    ASSERT_EQ(dividers.size(), 2u);
    const auto cells = layout.arrange(kArea, gap);
    // The root divider is the strip between view 0 and the right column; the nested one between 1 and 2.
    EXPECT_EQ(dividers[0].path, "");
    EXPECT_EQ(dividers[0].strip.min.x, cells[0].rect.max.x);
    EXPECT_EQ(dividers[0].strip.max.x, cells[1].rect.min.x);
    EXPECT_EQ(dividers[0].strip.size().y, 100.0f);
    EXPECT_EQ(dividers[1].path, "1");
    EXPECT_EQ(dividers[1].axis, SplitAxis::Y);
    EXPECT_EQ(dividers[1].strip.min.y, cells[1].rect.max.y);
    EXPECT_EQ(dividers[1].strip.max.y, cells[2].rect.min.y);
    // The gap's centre sits at the fraction of the track (what a splitter over the track draws).
    for (const ViewDivider& d : dividers) {
        const bool x = d.axis == SplitAxis::X;
        const float centre = x ? 0.5f * (d.strip.min.x + d.strip.max.x) : 0.5f * (d.strip.min.y + d.strip.max.y);
        const float along = x ? d.track.min.x + d.fraction * d.track.size().x : d.track.min.y + d.fraction * d.track.size().y;
        EXPECT_NEAR(centre, along, 1e-4f) << d.path;
    }

    // Setting a fraction moves that split only; it is clamped to keep 5 % a side and kept in the text.
    ASSERT_TRUE(layout.setFraction("1", 0.8f));
    auto moved = layout.arrange(kArea, gap);
    EXPECT_EQ(moved[0].rect.min, cells[0].rect.min);
    EXPECT_EQ(moved[0].rect.max, cells[0].rect.max);
    EXPECT_GT(moved[1].rect.size().y, cells[1].rect.size().y);
    ASSERT_TRUE(layout.setFraction("", -3.0f));
    EXPECT_NEAR(layout.arrange(kArea, gap)[0].rect.size().x, 0.05f * (200.0f - gap), 1e-3f);
    EXPECT_NE(layout.toText().find("x(0.05,"), std::string::npos) << layout.toText();
    EXPECT_EQ(ViewLayout::fromText(layout.toText()).toText(), layout.toText());
    // No split at these paths: a leaf, beyond the tree, or not a path.
    EXPECT_FALSE(layout.setFraction("0", 0.5f));
    EXPECT_FALSE(layout.setFraction("111", 0.5f));
    EXPECT_FALSE(layout.setFraction("x", 0.5f));
    // Maximised: no dividers.
    layout.toggleMaximise(0);
    EXPECT_TRUE(layout.dividers(kArea, gap).empty());
}

TEST(ViewLayout, HitTestingFindsTheCellUnderAPoint) {
    ViewLayout layout(0);
    layout.split(0, SplitAxis::Y, 1);
    const auto cells = layout.arrange(kArea, 10.0f);
    EXPECT_EQ(ViewLayout::hit(cells, {50.0f, 10.0f}), 0);
    EXPECT_EQ(ViewLayout::hit(cells, {50.0f, 90.0f}), 1);
    EXPECT_EQ(ViewLayout::hit(cells, {50.0f, 50.0f}), -1);  // in the gap
    EXPECT_EQ(ViewLayout::hit(cells, {250.0f, 10.0f}), -1);
}

TEST(ViewLayout, NextCyclesInReadingOrder) {
    ViewLayout layout(4);
    layout.split(4, SplitAxis::X, 2);
    layout.split(4, SplitAxis::Y, 9);
    EXPECT_EQ(layout.views(), (std::vector<int>{4, 9, 2}));
    EXPECT_EQ(layout.next(4), 9);
    EXPECT_EQ(layout.next(2), 4);
    EXPECT_EQ(layout.next(4, -1), 2);
}

TEST(ViewLayout, TheTextFormRoundTrips) {
    ViewLayout layout(0);
    layout.split(0, SplitAxis::X, 1, 0.3f);
    layout.split(1, SplitAxis::Y, 5);
    const std::string text = layout.toText();
    EXPECT_EQ(text, "x(0.3,0,y(0.5,1,5))");
    const ViewLayout back = ViewLayout::fromText(text);
    EXPECT_EQ(back.toText(), text);
    const auto a = layout.arrange(kArea, 2.0f), b = back.arrange(kArea, 2.0f);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].view, b[i].view);
        EXPECT_EQ(a[i].rect.min, b[i].rect.min);
        EXPECT_EQ(a[i].rect.max, b[i].rect.max);
    }
}

TEST(ViewLayout, BadTextIsRejectedWithAReason) {
    for (const char* bad : {"", "x(0.5,0)", "x(1.5,0,1)", "x(0.5,0,0)", "q(0.5,0,1)", "x(0.5,0,1)junk", "-1",
                            "x(0.5,0,y(0.5,1,2)", "2.5"}) {
        EXPECT_THROW((void)ViewLayout::fromText(bad), std::runtime_error) << bad;
    }
    try {
        (void)ViewLayout::fromText("x(0.5,3,3)");
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("twice"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace airlight
