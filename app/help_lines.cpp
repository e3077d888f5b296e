#include "help_lines.h"

namespace airlight {

std::vector<std::string> packHelp(const std::vector<std::string>& briefs, float width,
                                  const std::function<float(std::string_view)>& measure, int maxLines) {
    std::vector<std::string> lines;
    for (const std::string& brief : briefs) {
        if (brief.empty()) continue;
        if (!lines.empty()) {
            const std::string joined = lines.back() + "   " + brief;
            if (measure(joined) <= width || int(lines.size()) >= maxLines) {
                lines.back() = joined;
                continue;
            }
        }
        lines.push_back(brief);
    }
    return lines;
}

}  // namespace airlight
