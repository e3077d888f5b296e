// The view grid's block of the session file: it round trips, old files without it still load, and a
// broken block gives the defaults with a reason.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cpu/ui/session_fixture.h"
#include "session_state.h"

namespace airlight {
namespace {

TEST(SessionGrid, RoundTripKeepsTheLayoutAndEveryViewsSettings) {
    const SessionState s = sessionWithGrid();
    std::string problem;
    const SessionState back = sessionFromJson(sessionToJson(s), problem);
    ASSERT_EQ(problem, "");
    EXPECT_EQ(back.layout, s.layout);
    EXPECT_EQ(back.focusedView, 3);
    EXPECT_EQ(back.maximisedView, 1);
    ASSERT_EQ(back.gridViews.size(), 3u);
    const auto& b = back.gridViews[1];
    EXPECT_EQ(b.id, 3);
    EXPECT_EQ(b.content, "minmax.rectified");
    EXPECT_EQ(b.layer, 2);
    EXPECT_EQ(b.zoom, 8.0);
    EXPECT_EQ(b.center, glm::dvec2(0.25, 0.625));
    EXPECT_EQ(b.channel, 5);
    EXPECT_EQ(b.range, 3);
    EXPECT_EQ(b.colourMap, 2);
    EXPECT_EQ(b.manualMin, -0.5f);
    EXPECT_EQ(b.manualMax, 2.25f);
    EXPECT_EQ(b.markNegative, 1);
    EXPECT_TRUE(b.logScale);
    EXPECT_TRUE(b.stripOpen);
    EXPECT_EQ(back.gridViews[2].difference, 3);
    EXPECT_EQ(back.gridViews[2].against, "raymarch");
    EXPECT_EQ(back.gridViews[2].markNegative, 0);
}

TEST(SessionGrid, AFileWithoutTheGridLoadsWithTheDefaultGrid) {
    SessionState s = sessionWithGrid();
    s.layout.clear();  // not written at all
    std::string problem;
    const SessionState back = sessionFromJson(sessionToJson(s), problem);
    ASSERT_EQ(problem, "");
    EXPECT_TRUE(back.layout.empty());
    EXPECT_TRUE(back.gridViews.empty());
    EXPECT_EQ(nlohmann::json::parse(sessionToJson(s)).count("view_grid"), 0u);
}

TEST(SessionGrid, ABrokenGridGivesTheDefaultsAndAReason) {
    const std::string good = sessionToJson(sessionWithGrid());
    const auto broken = [&](const std::string& key, const nlohmann::json& value) {
        nlohmann::json j = nlohmann::json::parse(good);
        j["view_grid"][key] = value;
        return j.dump();
    };
    const auto brokenView = [&](const std::string& key, const nlohmann::json& value) {
        nlohmann::json j = nlohmann::json::parse(good);
        j["view_grid"]["views"][1][key] = value;
        return j.dump();
    };
    for (const std::string& text : {broken("layout", "x(0.5,1"), broken("layout", "x(0.5,1,1)"),
                                    brokenView("id", 7), brokenView("zoom", 0.5), brokenView("channel", 9),
                                    brokenView("manual", nlohmann::json::array({1.0})), brokenView("difference", -1)}) {
        std::string problem;
        const SessionState s = sessionFromJson(text, problem);
        EXPECT_NE(problem, "") << text;
        EXPECT_TRUE(s.layout.empty());
        EXPECT_EQ(s.scene, "");  // the defaults
    }
}

}  // namespace
}  // namespace airlight
