#include "lesson_prose.h"

#include <algorithm>
#include <cctype>
#include <sstream>
#include <vector>

#include "ui/font.h"

namespace airlight {

namespace {

using viz::ui::DrawList;
using namespace viz::ui::theme;


// A word of running text: consecutive pieces without a space between them stay on one line.
struct Piece {
    std::string text;
    SpanStyle style = SpanStyle::Normal;
};
struct Word {
    std::vector<Piece> pieces;
};

// Words of running text from parsed spans: a span's Normal text takes `base` (a heading's, a formula's);
// pieces with no space between them (`code`, and the comma after it) stay one word.
std::vector<Word> wordsOf(const std::vector<ProseSpan>& spans, SpanStyle base) {
    std::vector<Word> words;
    Word word;
    const auto endWord = [&] {
        if (!word.pieces.empty()) words.push_back(word);
        word = {};
    };
    for (const ProseSpan& span : spans) {
        const SpanStyle style = span.style == SpanStyle::Normal ? base : span.style;
        Piece piece{{}, style};
        for (char c : span.text) {
            if (std::isspace(static_cast<unsigned char>(c))) {
                if (!piece.text.empty()) word.pieces.push_back(piece);
                piece.text.clear();
                endWord();
            } else {
                piece.text += c;
            }
        }
        if (!piece.text.empty()) word.pieces.push_back(piece);
    }
    endWord();
    return words;
}

glm::vec4 colourOf(SpanStyle s) {
    switch (s) {
        case SpanStyle::Code: return kCode;
        case SpanStyle::Emphasis: return kEmphasis;
        case SpanStyle::Strong: return kStrong;
        case SpanStyle::Heading: return kAccent;
        case SpanStyle::Formula: return kFormula;
        case SpanStyle::Dim: return kDim;
        case SpanStyle::Normal: break;
    }
    return kText;
}

// Lays out words from x = indent within `width`, wrapping at spaces; continuation lines start at
// `hanging`. Draws when `dl` is given. Returns the height used.
float flowWords(DrawList* dl, const viz::ui::FontAtlas& font, const std::vector<Word>& words, glm::vec2 origin,
                float indent, float hanging, float width, float scale) {
    const float line = font.lineHeight(), space = font.measure(" ");
    float x = indent, y = 0.0f;
    bool first = true;
    float codeEnd = -1.0f;  // where the last `code` box on this line ended: a code span's words share one box
    for (const Word& w : words) {
        float wordWidth = 0.0f;
        for (const Piece& p : w.pieces) wordWidth += font.measure(p.text);
        if (!first && x + space + wordWidth > width) {
            x = hanging;
            y += line;
            codeEnd = -1.0f;
        } else if (!first) {
            x += space;
        }
        first = false;
        for (const Piece& p : w.pieces) {
            const float pw = font.measure(p.text);
            if (dl) {
                const glm::vec2 at = origin + glm::vec2(x, y);
                if (p.style == SpanStyle::Code) {
                    const float from = codeEnd >= 0.0f && x - codeEnd <= space + 0.5f ? origin.x + codeEnd : at.x - 1.0f;
                    dl->rect({{from, at.y}, at + glm::vec2(pw + 1.0f, line)}, kCodeBox);
                }
                const glm::vec4 c = colourOf(p.style);
                // Words longer than the panel are cut rather than run over its edge.
                dl->textClipped(at, p.text, c, origin.x + width + 1.0f);
                if (p.style == SpanStyle::Strong || p.style == SpanStyle::Heading)
                    dl->textClipped(at + glm::vec2(std::max(1.0f, 0.75f * scale), 0.0f), p.text, c, origin.x + width + 1.0f);
            }
            x += pw;
            codeEnd = p.style == SpanStyle::Code ? x : -1.0f;
        }
    }
    return words.empty() ? 0.0f : y + line;
}

}  // namespace

float drawLessonText(DrawList& dl, const std::string& text, SpanStyle style, glm::vec2 at, float width, float scale) {
    return flowWords(&dl, dl.font(), wordsOf(parseLine(text), style), at, 0.0f, 0.0f, width, scale);
}

float drawLessonProse(DrawList& dl, const std::vector<ProseBlock>& prose, glm::vec2 at, float width, float scale) {
    const viz::ui::FontAtlas& font = dl.font();
    const float line = font.lineHeight(), gap = 0.45f * line;
    const float bulletIndent = 1.2f * font.measure("M");
    float y = 0.0f;
    ProseBlock::Kind previous = ProseBlock::Kind::Paragraph;
    bool first = true;
    for (const ProseBlock& b : prose) {
        // A gap between blocks; half of one between the items of a list.
        if (!first) y += b.kind == ProseBlock::Kind::Item && previous == ProseBlock::Kind::Item ? 0.5f * gap : gap;
        first = false;
        previous = b.kind;
        switch (b.kind) {
            case ProseBlock::Kind::Paragraph:
                y += flowWords(&dl, font, wordsOf(b.spans, SpanStyle::Normal), {at.x, at.y + y}, 0.0f, 0.0f, width, scale);
                break;
            case ProseBlock::Kind::Heading:
                y += flowWords(&dl, font, wordsOf(b.spans, SpanStyle::Heading), {at.x, at.y + y}, 0.0f, 0.0f, width, scale);
                break;
            case ProseBlock::Kind::Item: {
                // The bullet: a small square at the first line's mid-height (the atlas has no U+2022).
                const float s = std::max(2.0f, 0.22f * line), mid = at.y + y + 0.5f * line;
                dl.rect({{at.x + 3.0f * scale, mid - 0.5f * s}, {at.x + 3.0f * scale + s, mid + 0.5f * s}}, kAccent);
                y += flowWords(&dl, font, wordsOf(b.spans, SpanStyle::Normal), {at.x, at.y + y}, bulletIndent,
                               bulletIndent, width, scale);
                break;
            }
            case ProseBlock::Kind::Formula: {
                // Each line of a formula in its own box, wrapped with a hanging indent.
                std::istringstream lines(b.spans.front().text);
                std::string text;
                bool firstLine = true;
                while (std::getline(lines, text)) {
                    if (!firstLine) y += 4.0f * scale;
                    firstLine = false;
                    const float pad = 6.0f * scale;
                    const std::vector<Word> words = wordsOf({{text, SpanStyle::Normal}}, SpanStyle::Formula);
                    const float hang = pad + 2.0f * font.measure(" ");
                    const float h = flowWords(nullptr, font, words, {}, pad, hang, width - pad, scale);
                    dl.rect({{at.x, at.y + y - 2.0f * scale}, {at.x + width, at.y + y + h + 2.0f * scale}}, kFormulaBox);
                    flowWords(&dl, font, words, {at.x, at.y + y}, pad, hang, width - pad, scale);
                    y += h;
                }
                y += 4.0f * scale;
                break;
            }
        }
    }
    return y;
}

}  // namespace airlight
