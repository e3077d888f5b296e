#include "report/text_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/atomic_file.h"
#include "core/error.h"

namespace viz::report {

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

std::string escapeHtml(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    }
    return out;
}

namespace {

// A ratio above 1 as "N x better", below 1 as "1/N x worse" (never "0.17x"), "same" within 1 %.
std::string ratioPhrase(double ratio, const char* better, const char* worse, const char* same) {
    if (!(ratio > 0.0) || !std::isfinite(ratio)) return "-";
    if (std::abs(ratio - 1.0) < 0.01) return same;
    char text[48];
    const double r = ratio > 1.0 ? ratio : 1.0 / ratio;
    std::snprintf(text, sizeof(text), r < 10.0 ? "%.2fx %s" : "%.0fx %s", r, ratio > 1.0 ? better : worse);
    return text;
}

}  // namespace

std::string speedupPhrase(double ratio) { return ratioPhrase(ratio, "faster", "slower", "as fast"); }

std::string speedupRangePhrase(double a, double b) {
    const double low = std::min(a, b), high = std::max(a, b);
    const std::string slow = speedupPhrase(low), fast = speedupPhrase(high);
    auto number = [](const std::string& phrase) { return phrase.substr(0, phrase.find(' ')); };
    if (slow.ends_with(" faster") && fast.ends_with(" faster")) return "between " + number(slow) + " and " + fast;
    // Both slower: the one nearer to 1 first.
    if (slow.ends_with(" slower") && fast.ends_with(" slower")) return "between " + number(fast) + " and " + slow;
    return "between " + slow + " and " + fast;
}

std::string workRatioPhrase(double ratio) { return ratioPhrase(ratio, "less work", "more work", "as much work"); }

std::string formatFigure(double value, const char* format) {
    if (!std::isfinite(value)) return "";
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, format, value);
    return buffer;
}

void writeTextFile(const std::string& path, const std::string& text) {
    const std::string error = writeFileAtomically(path, text);
    if (!error.empty()) throw InputError("cannot write '" + path + "': " + error);
}

}  // namespace viz::report
