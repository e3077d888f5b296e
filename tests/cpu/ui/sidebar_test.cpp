// The sidebar's layout (app/sidebar.h): every technique listed and numbered for the digit keys, views
// only as far as they fit, entries inside the panel and one under another, names for scripts, and a
// panel wide enough for the longest technique name.
#include <gtest/gtest.h>

#include "sidebar.h"

namespace airlight {
namespace {

// A monospaced stand-in for the font: 7 px a character.
SidebarMetrics metrics(float top, float bottom) {
    return {top, bottom, 8.0f, 16.0f, 1.0f, 170.0f, [](const std::string& s) { return 7.0f * float(s.size()); }};
}

std::vector<std::string> names(const std::string& stem, int n) {
    std::vector<std::string> out;
    for (int i = 0; i < n; ++i) out.push_back(stem + std::to_string(i));
    return out;
}

TEST(Sidebar, TechniquesAreNumberedForTheDigitKeysAndViewsStopWhereThePanelEnds) {
    const auto techniques = names("technique", 11);
    const auto views = names("view ", 40);
    const SidebarLayout side = layoutSidebar(techniques, 3, views, 5, metrics(60.0f, 600.0f));
    int listedTechniques = 0, listedViews = 0;
    float previousBottom = -1.0f;
    for (const SidebarEntry& e : side.entries) {
        EXPECT_GE(e.rect.min.y, previousBottom) << e.text << ": entries do not overlap";
        previousBottom = e.rect.max.y;
        EXPECT_GE(e.rect.min.x, side.panel.min.x);
        EXPECT_LE(e.rect.max.x, side.panel.max.x);
        EXPECT_GE(e.rect.min.y, side.panel.min.y);
        if (e.list == SidebarEntry::List::Techniques) {
            EXPECT_EQ(e.index, listedTechniques++);
            EXPECT_EQ(e.screenName, "technique:" + techniques[std::size_t(e.index)]);
            EXPECT_EQ(e.selected, e.index == 3);
            const std::string number = e.index < 9 ? std::to_string(e.index + 1) + "  " : "   ";
            EXPECT_EQ(e.text, number + techniques[std::size_t(e.index)]);
        } else {
            EXPECT_EQ(e.index, listedViews++);
            EXPECT_EQ(e.screenName, "view:" + views[std::size_t(e.index)]);
            EXPECT_EQ(e.selected, e.index == 5);
            EXPECT_LE(e.rect.min.y + 16.0f, side.panel.max.y) << e.text << ": a view's text starts inside the panel";
        }
    }
    EXPECT_EQ(listedTechniques, 11) << "every technique is listed";
    EXPECT_GT(listedViews, 5);
    EXPECT_LT(listedViews, 40) << "40 views do not fit in 540 px";
    ASSERT_EQ(side.headings.size(), 2u);
    EXPECT_LT(side.headings[0].at.y, side.entries.front().rect.min.y);
}

TEST(Sidebar, ThePanelIsWideEnoughForTheLongestTechniqueAndNoViewsBeforeARun) {
    const SidebarLayout narrow = layoutSidebar({"a", "b"}, 0, {}, -1, metrics(60.0f, 600.0f));
    EXPECT_FLOAT_EQ(narrow.panel.max.x, 170.0f) << "never narrower than the minimum";
    for (const SidebarEntry& e : narrow.entries) EXPECT_EQ(e.list, SidebarEntry::List::Techniques);

    const std::string longName(40, 'x');  // 280 px of text
    const SidebarLayout wide = layoutSidebar({"a", longName}, 1, {"Final image"}, 0, metrics(60.0f, 600.0f));
    EXPECT_GE(wide.panel.max.x, 280.0f + 2.0f * 8.0f);
    EXPECT_EQ(wide.entries.back().screenName, "view:Final image");
    EXPECT_TRUE(wide.entries.back().selected);
}

// vsv's views on an area light: 16 VPL cube maps between the frame's images and the rest.
std::vector<std::string> vsvViews() {
    std::vector<std::string> v = {"Final image", "Airlight L_air", "VPL shadow cube"};
    for (int i = 1; i < 16; ++i) v.push_back("VPL shadow cube " + std::to_string(i));
    v.insert(v.end(), {"Distance d", "Surface radiance", "L_air 2", "Visibility"});
    return v;
}

std::vector<std::string> viewTexts(const SidebarLayout& side) {
    std::vector<std::string> out;
    for (const SidebarEntry& e : side.entries)
        if (e.list == SidebarEntry::List::Views) out.push_back(e.text);
    return out;
}

TEST(Sidebar, ViewsNamedAlikeAreGroupedByTheirStem) {
    const std::vector<ViewGroup> groups = groupViews(vsvViews());
    ASSERT_EQ(groups.size(), 7u);
    EXPECT_EQ(groups[2].stem, "VPL shadow cube");
    EXPECT_EQ(groups[2].first, 2);
    EXPECT_EQ(groups[2].count, 16);
    EXPECT_EQ(groups[5].stem, "L_air");  // a single numbered view is a group of one
    EXPECT_EQ(groups[5].count, 1);
    // Only a trailing run of digits after a space is a number: "L_air" and "Distance d" keep their names.
    EXPECT_EQ(groupViews({"a1", "a2", "a3", "a4"}).size(), 4u);
    EXPECT_EQ(groupViews({"a 1", "a 2", "a 3x", "a 4"}).size(), 3u);
}

TEST(Sidebar, AGroupOfFourOrMoreIsOneEntryUntilTheViewShownIsInIt) {
    const auto views = vsvViews();
    SidebarLayout side = layoutSidebar({"vsv"}, 0, views, 1, metrics(60.0f, 2000.0f));
    const std::vector<std::string> collapsed = {"Final image", "Airlight L_air", "VPL shadow cube (16)",
                                                "Distance d", "Surface radiance", "L_air 2", "Visibility"};
    EXPECT_EQ(viewTexts(side), collapsed);
    // The group's entry shows its first view and carries that view's script name.
    const SidebarEntry& group = side.entries[1 + 2];
    EXPECT_EQ(group.index, 2);
    EXPECT_EQ(group.screenName, "view:VPL shadow cube");
    EXPECT_FALSE(group.selected);
    // Showing one of them lists each, the shown one selected, in order.
    side = layoutSidebar({"vsv"}, 0, views, 7, metrics(60.0f, 2000.0f));
    EXPECT_EQ(viewTexts(side), views);
    for (const SidebarEntry& e : side.entries) {
        if (e.list == SidebarEntry::List::Views) {
            EXPECT_EQ(e.selected, e.index == 7) << e.text;
        }
    }
    // Three alike stay three entries.
    const std::vector<std::string> three = {"map", "map 1", "map 2", "other"};
    EXPECT_EQ(viewTexts(layoutSidebar({"t"}, 0, three, 0, metrics(60.0f, 2000.0f))), three);
}

}  // namespace
}  // namespace airlight
