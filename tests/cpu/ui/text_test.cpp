// core/text.h: the text helpers the window, the loader's messages and the reports share.
#include <gtest/gtest.h>

#include <cstdlib>

#include "core/text.h"
#include "techniques/registry.h"

namespace {

TEST(Text, FirstLineDropsTheRestAndTrailingBlanksAndMarksWhatWasCut) {
    EXPECT_EQ(viz::firstLine("one line"), "one line");
    EXPECT_EQ(viz::firstLine("first  \r\nsecond\nthird"), "first");
    EXPECT_EQ(viz::firstLine("first\nsecond", " (...)"), "first (...)");
    EXPECT_EQ(viz::firstLine("only", " (...)"), "only");  // nothing cut, nothing marked
    EXPECT_EQ(viz::firstLine("\nafter an empty line"), "");
    EXPECT_EQ(viz::firstLine(""), "");
}

TEST(Text, TrimAndFormat) {
    EXPECT_EQ(viz::trim(" \t a b \n"), "a b");
    EXPECT_EQ(viz::trim("   "), "");
    EXPECT_EQ(viz::format("%.1f ms", 2.25), "2.2 ms");  // printf's round-half-even on the binary value
    EXPECT_EQ(viz::format("%g", 1e-7), "1e-07");
}

// A figure a user types back reads back as the same double: every declared default and range end of every
// registered technique's parameters (ivsv's 8388608 points once printed as 8.38861e+06, which is out of its
// own range), and a few by hand.
TEST(Text, ExactNumberReadsBackAsTheSameDouble) {
    EXPECT_EQ(viz::exactNumber(8388608.0), "8388608");
    EXPECT_EQ(viz::exactNumber(0.1), "0.1");
    EXPECT_EQ(viz::exactNumber(-2.25), "-2.25");
    EXPECT_EQ(viz::exactNumber(1e30), "1e+30");
    EXPECT_EQ(viz::exactNumber(0.0), "0");
    int checked = 0;
    for (const std::string& id : viz::techniqueIds()) {
        const auto t = viz::makeTechnique(id);
        for (const viz::ParamInfo& p : t->params())
            for (double v : {p.defaultValue, p.minValue, p.maxValue, std::nextafter(p.maxValue, 0.0)}) {
                const std::string text = viz::exactNumber(v);
                EXPECT_EQ(std::strtod(text.c_str(), nullptr), v) << id << "." << p.name << " " << text;
                ++checked;
            }
    }
    EXPECT_GT(checked, 400);
}

}  // namespace
