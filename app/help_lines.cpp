#include "help_lines.h"

namespace airlight {

namespace {

constexpr std::string_view kSeparator = "   ";

std::vector<std::string> pieces(const std::string& text) {
    std::vector<std::string> out;
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t next = text.find(kSeparator, at);
        const std::size_t end = next == std::string::npos ? text.size() : next;
        if (end > at) out.push_back(text.substr(at, end - at));
        if (next == std::string::npos) break;
        at = next + kSeparator.size();
        while (at < text.size() && text[at] == ' ') ++at;  // a longer gap is still one separator
    }
    return out;
}

}  // namespace

std::vector<std::string> packHelp(const std::string& text, float width,
                                  const std::function<float(std::string_view)>& measure, int maxLines) {
    std::vector<std::string> lines;
    for (const std::string& piece : pieces(text)) {
        if (!lines.empty()) {
            const std::string joined = lines.back() + std::string(kSeparator) + piece;
            if (measure(joined) <= width || int(lines.size()) >= maxLines) {
                lines.back() = joined;
                continue;
            }
        }
        lines.push_back(piece);
    }
    return lines;
}

}  // namespace airlight
