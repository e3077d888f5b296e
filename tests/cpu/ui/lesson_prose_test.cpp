// The lesson panel's Markdown (app/lesson_prose.h): a list item's continuation lines belong to the item,
// as in Markdown, instead of starting a paragraph of their own under it.
#include <gtest/gtest.h>

#include "lesson_prose.h"
#include "ui/font.h"

namespace airlight {
namespace {

float height(const std::string& markdown, float width) {
    static const viz::ui::FontAtlas font = viz::ui::FontAtlas::bake(viz::ui::FontAtlas::kDefaultFontPath, 14.0f);
    viz::ui::DrawList dl(font);
    return drawLessonProse(dl, markdown, {0.0f, 0.0f}, width, 1.0f);
}

TEST(LessonProse, AListItemsContinuationLinesFlowWithIt) {
    const std::string words = "results.csv and results.json: one row per scene, technique and setting with the stage "
                              "times and the total, and the error of L_air against the reference";
    const float oneLine = height("- " + words + "\n", 300.0f);
    // The same item written over three lines, continuations indented by two spaces and not at all.
    const float split = height("- results.csv and results.json: one row per scene,\n  technique and setting with the "
                               "stage times and the total,\nand the error of L_air against the reference\n",
                               300.0f);
    EXPECT_FLOAT_EQ(split, oneLine);
    // A blank line ends the item: what follows is a paragraph of its own, below a gap.
    const float withParagraph = height("- " + words + "\n\nA paragraph.\n", 300.0f);
    EXPECT_GT(withParagraph, oneLine);
    // Two items are two bullets: taller than one item holding both texts.
    EXPECT_GT(height("- first item\n- second item\n", 300.0f), height("- first item second item\n", 300.0f));
}

}  // namespace
}  // namespace airlight
