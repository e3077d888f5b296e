// Text fitted to a width in pixels of a font: shortened in the middle (a title, whose start and end both
// say something) or at the end (a legend entry, whose start says the most).
#pragma once

#include <string>

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

}  // namespace airlight
