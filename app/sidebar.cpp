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
    // The views' rows: each stage's sub-heading once (the stages publish in order), then its entries.
    struct Row {
        bool heading = false;
        std::string text, name;
        int first = 0, covers = 1;  // the views an entry stands for
        int under = -1;             // an entry's stage sub-heading (a row index), if any
    };
    std::vector<Row> rows;
    int shownRow = -1;
    int stageRow = -1;  // the current stage's sub-heading
    for (const ViewGroup& g : groupViews(views, viewStages)) {
        if (g.stage.empty()) {
            stageRow = -1;
        } else if (stageRow < 0 || rows[std::size_t(stageRow)].text != g.stage) {
            stageRow = int(rows.size());
            rows.push_back({true, g.stage, "", g.first, 0});
        }
        const bool holdsShown = shownView >= g.first && shownView < g.first + g.count;
        const bool collapsed = g.count >= kViewGroupMin && !holdsShown;
        for (int i = g.first; i < g.first + (collapsed ? 1 : g.count); ++i) {
            const std::string& name = views[std::size_t(i)];
            if (i == shownView) shownRow = int(rows.size());
            rows.push_back({false, collapsed ? g.stem + " (" + std::to_string(g.count) + ")" : name, name, i,
                            collapsed ? g.count : 1, stageRow});
        }
    }
    const int n = int(rows.size());
    const float headingStep = m.line + 2.0f * m.scale, entryStep = m.line + 4.0f * m.scale;
    const float noteStep = m.line + 2.0f * m.scale;  // a "views above" / "more views" line
    const auto step = [&](int r) { return rows[std::size_t(r)].heading ? headingStep : entryStep; };
    // A list scrolled into a stage starts with that stage's sub-heading again.
    const auto sticky = [&](int b) {
        const int h = b < n && !rows[std::size_t(b)].heading ? rows[std::size_t(b)].under : -1;
        return h >= 0 && h < b ? h : -1;
    };
    // The rows from `b` that fit, leaving room for the lines saying what is hidden above and below; a
    // sub-heading never ends the list alone.
    const auto end = [&](int b) {
        float at = y + (b > 0 ? noteStep : 0.0f) + (sticky(b) >= 0 ? headingStep : 0.0f);
        int e = b;
        while (e < n && at + m.line + (e + 1 < n ? noteStep : 0.0f) < out.panel.max.y) at += step(e++);
        while (e > b && rows[std::size_t(e - 1)].heading) --e;
        return e;
    };
    // From the top, or scrolled down as little as shows the view shown.
    int b = 0;
    while (shownRow >= end(b) && b < shownRow) ++b;
    const int e = end(b);
    const auto viewsIn = [&](int from, int to) {
        int count = 0;
        for (int r = from; r < to; ++r) count += rows[std::size_t(r)].heading ? 0 : rows[std::size_t(r)].covers;
        return count;
    };
    const auto plural = [](int k, const char* what) { return std::to_string(k) + what + (k == 1 ? " view" : " views"); };
    if (b > 0 && y + m.line < out.panel.max.y) {
        out.headings.push_back({"(" + plural(viewsIn(0, b), "") + " above)", {m.pad, y}, false, true});
        y += noteStep;
    }
    if (const int h = sticky(b); h >= 0 && b < e) {
        out.headings.push_back({rows[std::size_t(h)].text, {m.pad, y}, true});
        y += headingStep;
    }
    for (int r = b; r < e; ++r) {
        const Row& row = rows[std::size_t(r)];
        if (row.heading) {
            out.headings.push_back({row.text, {m.pad, y}, true});
        } else {
            out.entries.push_back({SidebarEntry::List::Views, row.first, row.text, "view:" + row.name,
                                   shownView >= row.first && shownView < row.first + row.covers, item(y)});
        }
        y += step(r);
    }
    if (e < n && viewsIn(e, n) > 0 && y + m.line < out.panel.max.y)
        out.headings.push_back({"(" + plural(viewsIn(e, n), " more") + ": [ ])", {m.pad, y}, false, true});
    return out;
}

}  // namespace airlight
