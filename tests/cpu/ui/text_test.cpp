// core/text.h: the text helpers the window, the loader's messages and the reports share.
#include <gtest/gtest.h>

#include "core/text.h"

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

}  // namespace
