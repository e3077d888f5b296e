// Small text helpers shared by the window, the widgets, the report and the lessons (one copy each).
#pragma once

#include <cctype>
#include <cstdio>
#include <string>

namespace viz {

// `fmt` (one printf conversion of a double, e.g. "%.1f ms") applied to `value`; at most 63 characters.
inline std::string format(const char* fmt, double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, fmt, value);
    return buffer;
}

// `text` without leading and trailing white space.
inline std::string trim(const std::string& text) {
    std::size_t a = 0, b = text.size();
    while (a < b && std::isspace(static_cast<unsigned char>(text[a]))) ++a;
    while (b > a && std::isspace(static_cast<unsigned char>(text[b - 1]))) --b;
    return text.substr(a, b - a);
}

}  // namespace viz
