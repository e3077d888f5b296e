// Text fitted to a width in pixels of a font: shortened in the middle (a title, whose start and end both
// say something), at the end (a legend entry, whose start says the most), by whole sections (a view's title:
// its name first) or by whole words (where the run stopped).
#pragma once

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "ui/font.h"

namespace airlight {

// `text` shortened in the middle ("start ... end") to fit `width` pixels in `font`; unchanged when it fits.
inline std::string elideMiddle(const viz::ui::FontAtlas& font, const std::string& text, float width) {
    if (font.measure(text) <= width) return text;
    const std::string dots = " ... ";
    const auto boundary = [&](std::size_t i) {  // never inside a UTF-8 sequence
        while (i > 0 && i < text.size() && (static_cast<unsigned char>(text[i]) & 0xc0) == 0x80) --i;
        return i;
    };
    std::size_t lo = 0, hi = text.size();  // characters kept in all, found by bisection
    while (lo < hi) {
        const std::size_t keep = (lo + hi + 1) / 2;
        const std::size_t head = boundary((keep + 1) / 2), tail = boundary(text.size() - keep / 2);
        if (font.measure(text.substr(0, head) + dots + text.substr(tail)) <= width) lo = keep;
        else hi = keep - 1;
    }
    if (lo == 0) return dots.substr(1, 3);
    return text.substr(0, boundary((lo + 1) / 2)) + dots + text.substr(boundary(text.size() - lo / 2));
}

// `text` cut at the end ("start ...") to fit `width` pixels in `font`; unchanged when it fits. For text
// whose start says the most (a legend entry's "value: meaning").
inline std::string elideEnd(const viz::ui::FontAtlas& font, const std::string& text, float width) {
    if (font.measure(text) <= width) return text;
    const std::string dots = "...";
    std::size_t lo = 0, hi = text.size();  // characters kept, found by bisection
    while (lo < hi) {
        const std::size_t keep = (lo + hi + 1) / 2;
        if (font.measure(text.substr(0, keep) + dots) <= width) lo = keep;
        else hi = keep - 1;
    }
    while (lo > 0 && lo < text.size() && (static_cast<unsigned char>(text[lo]) & 0xc0) == 0x80) --lo;  // not inside UTF-8
    return text.substr(0, lo) + dots;
}

// `text` in sections (runs of two or more spaces part them: "Distance d   [3/8]  reference.distance"):
// the first sections that fit `width` with "  ..." after them in place of the rest; the first section
// alone shortened in the middle when even it does not fit; unchanged when it fits. For a title whose
// name comes first and whose later sections add detail.
inline std::string elideSections(const viz::ui::FontAtlas& font, const std::string& text, float width) {
    if (font.measure(text) <= width) return text;
    const std::string more = "  ...";
    std::string best;
    for (std::size_t at = text.find("  "); at != std::string::npos; at = text.find("  ", at)) {
        const std::string head = text.substr(0, at);
        if (font.measure(head + more) > width) break;
        best = head + more;
        at = text.find_first_not_of(' ', at);
        if (at == std::string::npos) break;
    }
    if (!best.empty()) return best;
    return elideMiddle(font, text.substr(0, std::min(text.size(), text.find("  "))), width);
}

// Each bracketed part of `text` ("   [stopped after stage 1/5 reference.trace]") cut by whole words
// from its end, "..." in place of the cut words, until the whole fits `width` (at least the first word
// of each part is kept; shortened in the middle when even that does not fit); unchanged when it fits.
inline std::string elideBracketWords(const viz::ui::FontAtlas& font, const std::string& text, float width) {
    if (font.measure(text) <= width) return text;
    // The parts: [open, close] of every "[...]".
    std::vector<std::pair<std::size_t, std::size_t>> parts;
    for (std::size_t open = text.find('['); open != std::string::npos; open = text.find('[', open + 1)) {
        const std::size_t close = text.find(']', open);
        if (close == std::string::npos) break;
        parts.push_back({open, close});
        open = close;
    }
    std::string shortened = text;  // shortened word by word from the last part: earlier parts keep their place
    for (std::size_t i = parts.size(); i-- > 0;) {
        const auto [open, close] = parts[i];
        std::string inner = text.substr(open + 1, close - open - 1);
        while (font.measure(shortened) > width) {
            const std::size_t space = inner.find_last_of(' ');
            if (space == std::string::npos) break;
            inner = inner.substr(0, space);
            shortened = shortened.substr(0, open + 1) + inner + " ...]" + shortened.substr(shortened.find(']', open) + 1);
        }
        if (font.measure(shortened) <= width) return shortened;
    }
    return elideMiddle(font, shortened, width);
}

}  // namespace airlight
