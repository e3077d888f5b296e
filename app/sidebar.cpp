#include "sidebar.h"

#include <algorithm>

namespace airlight {

SidebarLayout layoutSidebar(const std::vector<std::string>& techniques, int currentTechnique,
                            const std::vector<std::string>& views, int shownView, const SidebarMetrics& m) {
    SidebarLayout out;
    float width = m.minWidth;
    for (const std::string& id : techniques) width = std::max(width, m.measure(id) + 4.0f * m.pad);
    out.panel = {{0.0f, m.top - m.pad}, {width, m.bottom - m.pad}};
    const auto item = [&](float y) {
        return viz::ui::Rect{{m.pad * 0.5f, y}, {width - m.pad * 0.5f, y + m.line + 2.0f * m.scale}};
    };
    float y = m.top;
    out.headings.push_back({"Techniques (Tab)", {m.pad, y}});
    y += m.line + 2.0f * m.scale;
    for (int i = 0; i < int(techniques.size()); ++i) {
        const std::string& id = techniques[std::size_t(i)];
        out.entries.push_back({SidebarEntry::List::Techniques, i, (i < 9 ? std::to_string(i + 1) + "  " : "   ") + id,
                               "technique:" + id, i == currentTechnique, item(y)});
        y += m.line + 4.0f * m.scale;
    }
    y += m.line;
    out.headings.push_back({"Views ([ ])", {m.pad, y}});
    y += m.line + 2.0f * m.scale;
    for (int i = 0; i < int(views.size()) && y + m.line < out.panel.max.y; ++i) {
        const std::string& name = views[std::size_t(i)];
        out.entries.push_back({SidebarEntry::List::Views, i, name, "view:" + name, i == shownView, item(y)});
        y += m.line + 4.0f * m.scale;
    }
    return out;
}

}  // namespace airlight
