#include "sidebar.h"

#include <algorithm>
#include <cctype>
#include <utility>

namespace airlight {
namespace {

std::string stemOf(const std::string& name) {
    const std::size_t space = name.find_last_of(' ');
    if (space == std::string::npos || space + 1 == name.size()) return name;
    for (std::size_t i = space + 1; i < name.size(); ++i)
        if (!std::isdigit(static_cast<unsigned char>(name[i]))) return name;
    return name.substr(0, space);
}

}  // namespace

std::vector<ViewGroup> groupViews(const std::vector<std::string>& views, const std::vector<std::string>& viewStages) {
    std::vector<ViewGroup> groups;
    for (int i = 0; i < int(views.size()); ++i) {
        std::string stem = stemOf(views[std::size_t(i)]);
        std::string stage = i < int(viewStages.size()) ? viewStages[std::size_t(i)] : std::string();
        if (!groups.empty() && groups.back().stem == stem && groups.back().stage == stage) ++groups.back().count;
        else groups.push_back({i, 1, std::move(stem), std::move(stage)});
    }
    return groups;
}

SidebarLayout layoutSidebar(const std::vector<std::string>& techniques, int currentTechnique,
                            const std::vector<std::string>& views, const std::vector<std::string>& viewStages,
                            int shownView, const SidebarMetrics& m) {
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
    std::string lastStage;
    for (const ViewGroup& g : groupViews(views, viewStages)) {
        // Each stage's views under its sub-heading, once (the stages publish in order).
        if (!g.stage.empty() && g.stage != lastStage) {
            // Not alone at the bottom: the heading and its first view, or neither.
            if (y + 2.0f * m.line + 2.0f * m.scale >= out.panel.max.y) return out;
            out.headings.push_back({g.stage, {m.pad, y}, true});
            y += m.line + 2.0f * m.scale;
            lastStage = g.stage;
        }
        const bool holdsShown = shownView >= g.first && shownView < g.first + g.count;
        const bool collapsed = g.count >= kViewGroupMin && !holdsShown;
        for (int i = g.first; i < g.first + (collapsed ? 1 : g.count); ++i) {
            if (y + m.line >= out.panel.max.y) return out;
            const std::string& name = views[std::size_t(i)];
            const std::string text = collapsed ? g.stem + " (" + std::to_string(g.count) + ")" : name;
            out.entries.push_back({SidebarEntry::List::Views, i, text, "view:" + name, i == shownView, item(y)});
            y += m.line + 4.0f * m.scale;
        }
    }
    return out;
}

}  // namespace airlight
