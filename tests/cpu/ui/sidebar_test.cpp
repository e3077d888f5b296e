// The sidebar's layout (app/sidebar.h): every technique listed and numbered for the digit keys, views
// only as far as they fit, entries inside the panel and one under another, names for scripts, and a
// panel wide enough for the longest technique name.
#include <gtest/gtest.h>

#include <algorithm>

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
    const SidebarLayout side = layoutSidebar(techniques, 3, views, {}, 5, metrics(60.0f, 600.0f));
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
    ASSERT_EQ(side.headings.size(), 3u);
    EXPECT_LT(side.headings[0].at.y, side.entries.front().rect.min.y);
    // The last line says how many views the list leaves out.
    EXPECT_TRUE(side.headings[2].hidden);
    EXPECT_EQ(side.headings[2].text, "(" + std::to_string(40 - listedViews) + " more views: [ ])");
    EXPECT_GT(side.headings[2].at.y, side.entries.back().rect.min.y);
    EXPECT_LE(side.headings[2].at.y + 16.0f, side.panel.max.y);
}

std::vector<std::string> viewTexts(const SidebarLayout& side);

// The number in a "(N views above)" or "(N more views: [ ])" line, or 0 when there is none.
int hiddenCount(const SidebarLayout& side, const std::string& which) {
    for (const SidebarHeading& h : side.headings)
        if (h.hidden && h.text.find(which) != std::string::npos) return std::stoi(h.text.substr(1));
    return 0;
}

// Whichever view is shown, the list scrolls as little as shows it: it is listed and selected, the views
// listed are consecutive, and the lines above and below count exactly the views left out; checked for
// every view of a long list in panels of many heights.
TEST(Sidebar, TheViewShownIsAlwaysListedAndTheRestAreCounted) {
    std::vector<std::string> views = {"Final image", "Airlight L_air"}, stages = {"", ""};
    for (int k = 0; k < 5; ++k)
        for (int i = 0; i < 7; ++i) {
            views.push_back("stage " + std::to_string(k) + " view " + std::string(1, char('a' + i)));
            stages.push_back(std::to_string(k + 1) + " Stage");
        }
    const int total = int(views.size());
    for (float bottom : {300.0f, 420.0f, 640.0f}) {
        for (int shown = 0; shown < total; ++shown) {
            const SidebarLayout side = layoutSidebar({"t"}, 0, views, stages, shown, metrics(60.0f, bottom));
            std::vector<int> listed;
            for (const SidebarEntry& e : side.entries) {
                if (e.list != SidebarEntry::List::Views) continue;
                listed.push_back(e.index);
                EXPECT_EQ(e.selected, e.index == shown);
                EXPECT_LE(e.rect.min.y + 16.0f, side.panel.max.y);
            }
            ASSERT_FALSE(listed.empty()) << bottom << " " << shown;
            EXPECT_NE(std::find(listed.begin(), listed.end(), shown), listed.end()) << bottom << ": view " << shown << " not listed";
            for (std::size_t i = 1; i < listed.size(); ++i) EXPECT_EQ(listed[i], listed[i - 1] + 1);
            EXPECT_EQ(hiddenCount(side, "above"), listed.front()) << bottom << " " << shown;
            EXPECT_EQ(hiddenCount(side, "more"), total - 1 - listed.back()) << bottom << " " << shown;
            for (const SidebarHeading& h : side.headings) EXPECT_LE(h.at.y + 16.0f, side.panel.max.y) << h.text;
            // Scrolled or not, every view listed sits under its own stage's sub-heading (the nearest one
            // above it), and the outputs under none.
            for (const SidebarEntry& e : side.entries) {
                if (e.list != SidebarEntry::List::Views) continue;
                const SidebarHeading* above = nullptr;
                for (const SidebarHeading& h : side.headings)
                    if (!h.hidden && h.at.y < e.rect.min.y && (!above || h.at.y > above->at.y)) above = &h;
                ASSERT_NE(above, nullptr);
                const std::string& stage = stages[std::size_t(e.index)];
                EXPECT_EQ(above->text, stage.empty() ? "Views ([ ])" : stage) << bottom << " " << shown << ": " << e.text;
            }
        }
    }
    // A list that fits has no such lines and starts at the top.
    const SidebarLayout all = layoutSidebar({"t"}, 0, views, stages, total - 1, metrics(60.0f, 4000.0f));
    EXPECT_EQ(hiddenCount(all, "above") + hiddenCount(all, "more"), 0);
    EXPECT_EQ(int(viewTexts(all).size()), total);
}

TEST(Sidebar, ThePanelIsWideEnoughForTheLongestTechniqueAndNoViewsBeforeARun) {
    const SidebarLayout narrow = layoutSidebar({"a", "b"}, 0, {}, {}, -1, metrics(60.0f, 600.0f));
    EXPECT_FLOAT_EQ(narrow.panel.max.x, 170.0f) << "never narrower than the minimum";
    for (const SidebarEntry& e : narrow.entries) EXPECT_EQ(e.list, SidebarEntry::List::Techniques);

    const std::string longName(40, 'x');  // 280 px of text
    const SidebarLayout wide = layoutSidebar({"a", longName}, 1, {"Final image"}, {}, 0, metrics(60.0f, 600.0f));
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
    SidebarLayout side = layoutSidebar({"vsv"}, 0, views, {}, 1, metrics(60.0f, 2000.0f));
    const std::vector<std::string> collapsed = {"Final image", "Airlight L_air", "VPL shadow cube (16)",
                                                "Distance d", "Surface radiance", "L_air 2", "Visibility"};
    EXPECT_EQ(viewTexts(side), collapsed);
    // The group's entry shows its first view and carries that view's script name.
    const SidebarEntry& group = side.entries[1 + 2];
    EXPECT_EQ(group.index, 2);
    EXPECT_EQ(group.screenName, "view:VPL shadow cube");
    EXPECT_FALSE(group.selected);
    // Showing one of them lists each, the shown one selected, in order.
    side = layoutSidebar({"vsv"}, 0, views, {}, 7, metrics(60.0f, 2000.0f));
    EXPECT_EQ(viewTexts(side), views);
    for (const SidebarEntry& e : side.entries) {
        if (e.list == SidebarEntry::List::Views) {
            EXPECT_EQ(e.selected, e.index == 7) << e.text;
        }
    }
    // Three alike stay three entries.
    const std::vector<std::string> three = {"map", "map 1", "map 2", "other"};
    EXPECT_EQ(viewTexts(layoutSidebar({"t"}, 0, three, {}, 0, metrics(60.0f, 2000.0f))), three);
}

// Each view under the stage that makes it: the run's two outputs first with no sub-heading, then one
// sub-heading per stage, just above its first view, in order, never repeated; so a stage's own "L_air"
// reads apart from the run's "Airlight L_air".
TEST(Sidebar, StageViewsSitUnderTheirStagesSubHeading) {
    const std::vector<std::string> views = {"Final image", "Airlight L_air", "Shadow map", "VPL cells",
                                            "Distance d", "Surface radiance", "L_air", "Lit fraction"};
    const std::vector<std::string> stages = {"", "", "1 Shadow maps", "1 Shadow maps", "2 Camera view",
                                             "2 Camera view", "3 Ray march", "3 Ray march"};
    const SidebarLayout side = layoutSidebar({"raymarch"}, 0, views, stages, 0, metrics(60.0f, 2000.0f));
    EXPECT_EQ(viewTexts(side), views) << "sub-headings change no entry";
    std::vector<std::string> subHeadings;
    for (const SidebarHeading& h : side.headings)
        if (h.stage) subHeadings.push_back(h.text);
    EXPECT_EQ(subHeadings, (std::vector<std::string>{"1 Shadow maps", "2 Camera view", "3 Ray march"}));
    // Every view's nearest heading above it is its own stage's (or the list's, for the outputs); nothing
    // overlaps a heading.
    for (const SidebarEntry& e : side.entries) {
        if (e.list != SidebarEntry::List::Views) continue;
        const SidebarHeading* above = nullptr;
        for (const SidebarHeading& h : side.headings) {
            EXPECT_FALSE(h.at.y + 16.0f > e.rect.min.y && h.at.y < e.rect.max.y) << h.text << " overlaps " << e.text;
            if (h.at.y < e.rect.min.y && (!above || h.at.y > above->at.y)) above = &h;
        }
        ASSERT_NE(above, nullptr);
        const std::string& stage = stages[std::size_t(e.index)];
        EXPECT_EQ(above->text, stage.empty() ? "Views ([ ])" : stage) << e.text;
    }
}

TEST(Sidebar, AGroupNeverSpansTwoStagesAndNoSubHeadingIsLeftAloneAtTheBottom) {
    // Four views named alike from two stages are two groups of two, so neither collapses.
    const std::vector<std::string> views = {"Final image", "Airlight L_air", "map", "map 1", "map 2", "map 3"};
    const std::vector<std::string> stages = {"", "", "1 A", "1 A", "2 B", "2 B"};
    EXPECT_EQ(groupViews(views).size(), 3u) << "without stages the four are one group";
    const std::vector<ViewGroup> groups = groupViews(views, stages);
    ASSERT_EQ(groups.size(), 4u);
    EXPECT_EQ(groups[2].stage, "1 A");
    EXPECT_EQ(groups[3].first, 4);
    EXPECT_EQ(viewTexts(layoutSidebar({"t"}, 0, views, stages, 0, metrics(60.0f, 2000.0f))), views);
    // A panel that ends where only a sub-heading would fit stops before it, at every height.
    for (float bottom = 120.0f; bottom < 400.0f; bottom += 1.0f) {
        const SidebarLayout side = layoutSidebar({"t"}, 0, views, stages, 0, metrics(60.0f, bottom));
        float lastEntry = -1.0f;
        for (const SidebarEntry& e : side.entries) lastEntry = std::max(lastEntry, e.rect.min.y);
        for (const SidebarHeading& h : side.headings) {
            if (!h.stage) continue;
            EXPECT_LT(h.at.y, lastEntry) << "bottom " << bottom << ": " << h.text << " has no view under it";
            EXPECT_LE(h.at.y + 16.0f, side.panel.max.y) << "bottom " << bottom << ": " << h.text;
        }
    }
}

}  // namespace
}  // namespace airlight
