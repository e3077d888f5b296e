// Small text helpers shared by the window, the widgets, the report and the lessons (one copy each).
#pragma once

#include <cctype>
#include <charconv>
#include <cstdio>
#include <string>

namespace viz {

// `fmt` (one printf conversion of a double, e.g. "%.1f ms") applied to `value`; at most 63 characters.
inline std::string format(const char* fmt, double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, fmt, value);
    return buffer;
}

// The shortest text that reads back as exactly `value` ("8388608", "0.1", "1e+30"): for figures a user
// types back, such as a parameter's range, where "%g" would print 8388608 as 8.38861e+06.
inline std::string exactNumber(double value) {
    char buffer[32];
    const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
    return error == std::errc() ? std::string(buffer, end) : format("%.17g", value);
}

// `text` without leading and trailing white space.
inline std::string trim(const std::string& text) {
    std::size_t a = 0, b = text.size();
    while (a < b && std::isspace(static_cast<unsigned char>(text[a]))) ++a;
    while (b > a && std::isspace(static_cast<unsigned char>(text[b - 1]))) --b;
    return text.substr(a, b - a);
}

// The first line of `text` without trailing spaces or a carriage return (error messages, shader logs and
// parser messages can span lines); `more` is appended when `text` had further lines.
inline std::string firstLine(const std::string& text, const std::string& more = "") {
    const std::size_t end = text.find('\n');
    std::string line = text.substr(0, end);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    return end == std::string::npos ? line : line + more;
}

}  // namespace viz
