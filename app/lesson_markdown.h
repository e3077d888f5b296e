// A lesson's prose as blocks of styled text: parsed once with md4c (CommonMark), then drawn by the lesson
// panel (lesson_prose.h) and written as HTML by the handout (lesson.h). Paragraphs, headings, list items,
// indented blocks (the lessons' formulas), with `code`, *emphasis* and **strong** inline.
#pragma once

#include <string>
#include <vector>

namespace airlight {

// How a run of text is drawn (colour, box, bold).
enum class SpanStyle { Normal, Code, Emphasis, Strong, Heading, Formula, Dim };

struct ProseSpan {
    std::string text;
    SpanStyle style = SpanStyle::Normal;  // Normal, Code, Emphasis or Strong from the parse
};

struct ProseBlock {
    enum class Kind { Paragraph, Heading, Item, Formula };
    Kind kind = Kind::Paragraph;
    int level = 0;                 // headings: 1 for '#'
    std::vector<ProseSpan> spans;  // a formula: one Normal span, its lines joined by '\n'
};

// Parses `markdown` (raw HTML is kept as text). Soft line breaks become spaces; a list item's lines,
// however indented, are one item.
std::vector<ProseBlock> parseProse(const std::string& markdown);

// One line of text (a step's title, a state line) as styled spans: its inline Markdown parsed, but never a
// block of its own: "1. Rectification" keeps its number (not a list item), "# 3" its '#'.
std::vector<ProseSpan> parseLine(const std::string& line);

// The blocks as HTML: <p>, <h2>.. (a '#' heading is h2: the page's title is h1), <ul><li>, <pre>, with
// <code>, <em> and <strong> inline; text escaped.
std::string proseHtml(const std::vector<ProseBlock>& blocks);

}  // namespace airlight
