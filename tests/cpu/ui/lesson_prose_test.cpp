// The lesson panel's Markdown (app/lesson_prose.h): a list item's continuation lines belong to the item,
// as in Markdown, instead of starting a paragraph of their own under it.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lesson_prose.h"
#include "ui/font.h"

namespace airlight {
namespace {

float height(const std::string& markdown, float width) {
    static const viz::ui::FontAtlas font = viz::ui::FontAtlas::bake(viz::ui::FontAtlas::kDefaultFontPath, 14.0f);
    viz::ui::DrawList dl(font);
    return drawLessonProse(dl, parseProse(markdown), {0.0f, 0.0f}, width, 1.0f);
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

// A single line (a step's title, the state line) is one paragraph whatever it starts with: "1. Title"
// keeps its number (CommonMark would make it a list item and drop the "1.").
TEST(LessonProse, ALineThatLooksLikeAListKeepsItsMarker) {
    static const viz::ui::FontAtlas font = viz::ui::FontAtlas::bake(viz::ui::FontAtlas::kDefaultFontPath, 14.0f);
    for (const std::string title : {"1. Rectification", "- a dash", "# three", "**strong** start"}) {
        viz::ui::DrawList numbered(font), plain(font);
        drawLessonText(numbered, title, SpanStyle::Normal, {0.0f, 0.0f}, 1000.0f, 1.0f);
        // The same words drawn one by one as they are: the marker's glyphs are there (as many vertices),
        // and a "**strong**" start is still parsed (no asterisks; strong words are drawn twice).
        const bool strong = title.rfind("**", 0) == 0;
        for (const std::string& word : strong ? std::vector<std::string>{"strong", "strong", "start"}
                                               : std::vector<std::string>{title.substr(0, title.find(' ')),
                                                                          title.substr(title.find(' ') + 1)})
            plain.text({0.0f, 0.0f}, word, glm::vec4(1.0f));
        EXPECT_EQ(numbered.vertices().size(), plain.vertices().size()) << title;
    }
}

}  // namespace
}  // namespace airlight
