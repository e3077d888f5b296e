#include "lesson_prose.h"

#include <algorithm>
#include <cctype>
#include <sstream>
#include <vector>

#include "ui/font.h"

namespace airlight {

namespace {

using viz::ui::DrawList;
using namespace lesson_style;

constexpr glm::vec4 kCode{0.55f, 0.92f, 0.72f, 1.0f};      // `code`: a terminal green on a dark box
constexpr glm::vec4 kCodeBox{0.20f, 0.23f, 0.22f, 1.0f};
constexpr glm::vec4 kEmphasis{0.62f, 0.80f, 1.0f, 1.0f};   // *emphasis*: no italic face, so a colour
constexpr glm::vec4 kStrong{1.0f, 1.0f, 1.0f, 1.0f};       // **strong**: drawn twice, one pixel apart
constexpr glm::vec4 kFormula{0.80f, 0.86f, 0.95f, 1.0f};
constexpr glm::vec4 kFormulaBox{0.17f, 0.18f, 0.22f, 1.0f};

std::string trim(const std::string& s) {
    std::size_t a = 0, b = s.size();
    while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
    while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
    return s.substr(a, b - a);
}

// A word of running text: consecutive pieces without a space between them stay on one line.
struct Piece {
    std::string text;
    SpanStyle style = SpanStyle::Normal;
};
struct Word {
    std::vector<Piece> pieces;
};

// Splits a line of Markdown into words with `code`, *emphasis* and **strong** (as in markdownToHtml).
std::vector<Word> inlineWords(const std::string& text, SpanStyle base) {
    std::vector<Word> words;
    bool code = false, em = false, strong = false;
    Word word;
    Piece piece;
    const auto style = [&] {
        if (code) return SpanStyle::Code;
        if (strong) return SpanStyle::Strong;
        if (em) return SpanStyle::Emphasis;
        return base;
    };
    const auto endPiece = [&] {
        if (!piece.text.empty()) word.pieces.push_back(piece);
        piece = {};
        piece.style = style();
    };
    const auto endWord = [&] {
        endPiece();
        if (!word.pieces.empty()) words.push_back(word);
        word = {};
    };
    piece.style = style();
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '`') {
            endPiece();
            code = !code;
            piece.style = style();
        } else if (!code && base != SpanStyle::Formula && c == '*' && i + 1 < text.size() && text[i + 1] == '*') {
            endPiece();
            strong = !strong;
            piece.style = style();
            ++i;
        } else if (!code && base != SpanStyle::Formula && c == '*') {
            endPiece();
            em = !em;
            piece.style = style();
        } else if (std::isspace(static_cast<unsigned char>(c))) {
            endWord();
        } else {
            piece.text += c;
        }
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
    return flowWords(&dl, dl.font(), inlineWords(text, style), at, 0.0f, 0.0f, width, scale);
}

float drawLessonProse(DrawList& dl, const std::string& markdown, glm::vec2 at, float width, float scale) {
    const viz::ui::FontAtlas& font = dl.font();
    const float line = font.lineHeight(), gap = 0.45f * line;
    std::istringstream in(markdown);
    std::string raw, paragraph;
    float y = 0.0f;
    bool pendingGap = false;
    const auto block = [&](float height) {
        y += height;
        pendingGap = true;
    };
    const auto flush = [&] {
        if (paragraph.empty()) return;
        if (pendingGap) y += gap;
        block(flowWords(&dl, font, inlineWords(paragraph, SpanStyle::Normal), {at.x, at.y + y}, 0.0f, 0.0f, width, scale));
        paragraph.clear();
    };
    const float bulletIndent = 1.2f * font.measure("M");
    // A list item: "- " and the lines after it up to a blank line or the next item (continuation lines,
    // indented or not, belong to it, as in Markdown).
    std::string item;
    bool inItem = false;
    const auto flushItem = [&] {
        if (!inItem) return;
        inItem = false;
        if (pendingGap) y += gap * 0.5f;
        pendingGap = false;
        // The bullet: a small square at the first line's mid-height (the atlas has no U+2022).
        const float b = std::max(2.0f, 0.22f * line), mid = at.y + y + 0.5f * line;
        dl.rect({{at.x + 3.0f * scale, mid - 0.5f * b}, {at.x + 3.0f * scale + b, mid + 0.5f * b}}, kAccent);
        y += flowWords(&dl, font, inlineWords(item, SpanStyle::Normal), {at.x, at.y + y}, bulletIndent, bulletIndent,
                       width, scale);
        item.clear();
        pendingGap = true;
    };
    while (std::getline(in, raw)) {
        const std::string t = trim(raw);
        if (inItem && !t.empty() && t.rfind("- ", 0) != 0) {
            item += " " + t;
            continue;
        }
        if (raw.rfind("    ", 0) == 0 && !t.empty() && paragraph.empty()) {
            // A formula line: its own box, wrapped with a hanging indent.
            if (pendingGap) y += gap;
            pendingGap = false;
            const float pad = 6.0f * scale;
            const std::vector<Word> words = inlineWords(t, SpanStyle::Formula);
            const float h = flowWords(nullptr, font, words, {}, pad, pad + 2.0f * font.measure(" "), width - pad, scale);
            dl.rect({{at.x, at.y + y - 2.0f * scale}, {at.x + width, at.y + y + h + 2.0f * scale}}, kFormulaBox);
            flowWords(&dl, font, words, {at.x, at.y + y}, pad, pad + 2.0f * font.measure(" "), width - pad, scale);
            y += h + 4.0f * scale;
            continue;
        }
        if (t.empty()) {
            flushItem();
            flush();
        } else if (t[0] == '#') {
            flush();
            if (pendingGap) y += gap;
            const std::string heading = trim(t.substr(t.find_first_not_of('#')));
            block(flowWords(&dl, font, inlineWords(heading, SpanStyle::Heading), {at.x, at.y + y}, 0.0f, 0.0f, width, scale));
        } else if (t.rfind("- ", 0) == 0) {
            flushItem();
            flush();
            inItem = true;
            item = t.substr(2);
        } else {
            paragraph += t + " ";
        }
    }
    flushItem();
    flush();
    return y;
}

}  // namespace airlight
