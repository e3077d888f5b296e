// The window's help lines (app/help_lines.h): every brief shown whole, in order, on lines that fit.
#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <vector>

#include "help_lines.h"

namespace airlight {
namespace {

// One unit per character: widths are lengths.
float chars(std::string_view s) { return float(s.size()); }

TEST(HelpLines, BriefsArePackedWholeInOrderIntoLinesThatFit) {
    const std::vector<std::string> briefs = {"Tab technique", "S/Shift+S stage", "D sub-step", "Home/End",
                                             "[ ] view", "P play/pause", "left drag orbit"};
    const std::string help = "Tab technique   S/Shift+S stage   D sub-step   Home/End   [ ] view   P play/pause   left drag orbit";
    const std::vector<std::string> lines = packHelp(briefs, 40.0f, chars, 10);
    ASSERT_GE(lines.size(), 3u);
    std::string again;
    for (const std::string& l : lines) {
        EXPECT_LE(l.size(), 40u) << l;
        EXPECT_NE(l.substr(0, 1), " ") << l;
        again += (again.empty() ? "" : "   ") + l;
    }
    EXPECT_EQ(again, help) << "every brief, whole and in order";
    // Each line is as full as it can be: the next line's first brief would not have fitted on it.
    for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
        const std::string first = lines[i + 1].substr(0, lines[i + 1].find("   "));
        EXPECT_GT(lines[i].size() + 3 + first.size(), 40u) << lines[i] << " | " << first;
    }
    // Wide enough: one line, the text as it was.
    EXPECT_EQ(packHelp(briefs, 1000.0f, chars, 10), std::vector<std::string>{help});
}

TEST(HelpLines, TheLastAllowedLineTakesTheRestAndALongBriefGetsItsOwnLine) {
    const std::vector<std::string> two = packHelp({"a", "bb", "ccc", "dddd", "eeeee"}, 7.0f, chars, 2);
    ASSERT_EQ(two.size(), 2u);
    EXPECT_EQ(two[0], "a   bb");
    EXPECT_EQ(two[1], "ccc   dddd   eeeee") << "clipped when drawn, never dropped";
    const std::vector<std::string> narrow = packHelp({"x", "a brief wider than the line", "y"}, 5.0f, chars, 10);
    EXPECT_EQ(narrow, (std::vector<std::string>{"x", "a brief wider than the line", "y"}));
    EXPECT_TRUE(packHelp({}, 10.0f, chars, 2).empty());
    EXPECT_EQ(packHelp({"", "a", ""}, 10.0f, chars, 2), std::vector<std::string>{"a"}) << "an empty brief is no brief";
}

}  // namespace
}  // namespace airlight
