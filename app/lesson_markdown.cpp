#include "lesson_markdown.h"

#include <md4c.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>

#include "report/text_output.h"

namespace airlight {

namespace {

// The parse's state: the block being filled and the inline styles open at this point.
struct Builder {
    std::vector<ProseBlock> blocks;
    bool open = false;     // a block takes text
    int items = 0;         // list items open (a nested list's text joins its item)
    int code = 0, em = 0, strong = 0;

    void begin(ProseBlock::Kind kind, int level = 0) {
        blocks.push_back({kind, level, {}});
        open = true;
    }
    SpanStyle style() const {
        if (code) return SpanStyle::Code;
        if (strong) return SpanStyle::Strong;
        if (em) return SpanStyle::Emphasis;
        return SpanStyle::Normal;
    }
    void add(const std::string& text, SpanStyle s) {
        if (!open || text.empty()) return;
        std::vector<ProseSpan>& spans = blocks.back().spans;
        if (!spans.empty() && spans.back().style == s) spans.back().text += text;
        else spans.push_back({text, s});
    }
};

// The named entities lessons may write, and numeric ones; anything else stays as written.
std::string decodeEntity(const std::string& e) {
    if (e == "&amp;") return "&";
    if (e == "&lt;") return "<";
    if (e == "&gt;") return ">";
    if (e == "&quot;") return "\"";
    if (e == "&apos;") return "'";
    if (e == "&nbsp;") return " ";
    if (e.size() > 3 && e[1] == '#') {
        const bool hex = e[2] == 'x' || e[2] == 'X';
        const long code = std::strtol(e.c_str() + (hex ? 3 : 2), nullptr, hex ? 16 : 10);
        if (code > 0 && code < 0x80) return std::string(1, char(code));
    }
    return e;
}

int enterBlock(MD_BLOCKTYPE type, void* detail, void* user) {
    Builder& b = *static_cast<Builder*>(user);
    switch (type) {
        case MD_BLOCK_LI:
            ++b.items;
            if (b.items == 1) b.begin(ProseBlock::Kind::Item);
            break;
        case MD_BLOCK_P:
            if (b.items == 0) b.begin(ProseBlock::Kind::Paragraph);
            else b.add(b.blocks.back().spans.empty() ? "" : " ", SpanStyle::Normal);  // a loose item's next paragraph
            break;
        case MD_BLOCK_H: b.begin(ProseBlock::Kind::Heading, int(static_cast<MD_BLOCK_H_DETAIL*>(detail)->level)); break;
        case MD_BLOCK_CODE:
            if (b.items == 0) b.begin(ProseBlock::Kind::Formula);
            break;
        default: break;
    }
    return 0;
}

int leaveBlock(MD_BLOCKTYPE type, void*, void* user) {
    Builder& b = *static_cast<Builder*>(user);
    switch (type) {
        case MD_BLOCK_LI:
            if (--b.items == 0) b.open = false;
            break;
        case MD_BLOCK_P:
        case MD_BLOCK_H:
        case MD_BLOCK_CODE:
            if (b.items == 0) b.open = false;
            if (type == MD_BLOCK_CODE && !b.blocks.empty() && b.blocks.back().kind == ProseBlock::Kind::Formula) {
                std::vector<ProseSpan>& spans = b.blocks.back().spans;  // no trailing newline
                while (!spans.empty() && !spans.back().text.empty() && spans.back().text.back() == '\n')
                    spans.back().text.pop_back();
            }
            break;
        default: break;
    }
    return 0;
}

int enterSpan(MD_SPANTYPE type, void*, void* user) {
    Builder& b = *static_cast<Builder*>(user);
    if (type == MD_SPAN_CODE) ++b.code;
    if (type == MD_SPAN_EM) ++b.em;
    if (type == MD_SPAN_STRONG) ++b.strong;
    return 0;
}

int leaveSpan(MD_SPANTYPE type, void*, void* user) {
    Builder& b = *static_cast<Builder*>(user);
    if (type == MD_SPAN_CODE) --b.code;
    if (type == MD_SPAN_EM) --b.em;
    if (type == MD_SPAN_STRONG) --b.strong;
    return 0;
}

int text(MD_TEXTTYPE type, const MD_CHAR* data, MD_SIZE size, void* user) {
    Builder& b = *static_cast<Builder*>(user);
    const std::string t(data, size);
    const bool formula = !b.blocks.empty() && b.open && b.blocks.back().kind == ProseBlock::Kind::Formula;
    switch (type) {
        case MD_TEXT_SOFTBR:
        case MD_TEXT_BR: b.add(" ", b.style()); break;
        case MD_TEXT_NULLCHAR: break;
        case MD_TEXT_ENTITY: b.add(decodeEntity(t), b.style()); break;
        case MD_TEXT_CODE: b.add(t, formula ? SpanStyle::Normal : SpanStyle::Code); break;
        default: b.add(t, b.style()); break;
    }
    return 0;
}

std::string inlineHtml(const std::vector<ProseSpan>& spans) {
    std::string html;
    for (const ProseSpan& s : spans) {
        const std::string t = viz::report::escapeHtml(s.text);
        switch (s.style) {
            case SpanStyle::Code: html += "<code>" + t + "</code>"; break;
            case SpanStyle::Emphasis: html += "<em>" + t + "</em>"; break;
            case SpanStyle::Strong: html += "<strong>" + t + "</strong>"; break;
            default: html += t; break;
        }
    }
    return html;
}

}  // namespace

std::vector<ProseBlock> parseProse(const std::string& markdown) {
    MD_PARSER parser{};
    parser.abi_version = 0;
    parser.flags = MD_FLAG_NOHTML;
    parser.enter_block = enterBlock;
    parser.leave_block = leaveBlock;
    parser.enter_span = enterSpan;
    parser.leave_span = leaveSpan;
    parser.text = text;
    Builder b;
    md_parse(markdown.data(), MD_SIZE(markdown.size()), &parser, &b);
    // Blocks that took no text (an empty item) say nothing.
    std::vector<ProseBlock> out;
    for (ProseBlock& block : b.blocks)
        if (!block.spans.empty()) out.push_back(std::move(block));
    return out;
}

std::vector<ProseSpan> parseLine(const std::string& text) {
    // A leading list or heading marker is escaped, so that CommonMark reads the line as a paragraph.
    std::string line = text;
    const std::size_t start = line.find_first_not_of(' ');
    if (start != std::string::npos) {
        std::size_t marker = start;
        while (marker < line.size() && std::isdigit(static_cast<unsigned char>(line[marker]))) ++marker;
        const bool numbered = marker > start && marker < line.size() && (line[marker] == '.' || line[marker] == ')');
        const char c = line[start];
        const bool bullet = (c == '-' || c == '+' || c == '*') && (start + 1 == line.size() || line[start + 1] == ' ');
        if (numbered || bullet || c == '#' || c == '>') {
            const std::size_t at = numbered ? marker : start;
            line = line.substr(0, at) + "\\" + line.substr(at);
        }
    }
    std::vector<ProseSpan> spans;
    for (const ProseBlock& b : parseProse(line))
        for (const ProseSpan& s : b.spans) spans.push_back(s);
    return spans;
}

std::string proseHtml(const std::vector<ProseBlock>& blocks) {
    std::string html;
    bool list = false;
    for (const ProseBlock& b : blocks) {
        if (list && b.kind != ProseBlock::Kind::Item) html += "</ul>\n", list = false;
        switch (b.kind) {
            case ProseBlock::Kind::Paragraph: html += "<p>" + inlineHtml(b.spans) + "</p>\n"; break;
            case ProseBlock::Kind::Heading: {
                const std::string h = "h" + std::to_string(std::min(b.level + 1, 6));
                html += "<" + h + ">" + inlineHtml(b.spans) + "</" + h + ">\n";
                break;
            }
            case ProseBlock::Kind::Item:
                if (!list) html += "<ul>\n", list = true;
                html += "<li>" + inlineHtml(b.spans) + "</li>\n";
                break;
            case ProseBlock::Kind::Formula:
                html += "<pre>" + viz::report::escapeHtml(b.spans.front().text) + "</pre>\n";
                break;
        }
    }
    if (list) html += "</ul>\n";
    return html;
}

}  // namespace airlight
