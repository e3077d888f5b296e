#include "view_grid.h"

#include <algorithm>

namespace airlight {

int ViewGrid::reset(const std::string& content) {
    layout = ViewLayout(0);
    layout.split(0, SplitAxis::X, 1);
    views.clear();
    views[0].content = "final";
    views[1].content = content.empty() ? "airlight" : content;
    nextView = 2;
    lessonGrid = false;
    return 1;
}

int ViewGrid::lesson(const std::vector<std::string>& contents) {
    const std::string text = contents.size() <= 2 ? "x(0.3333,0,x(0.5,1,2))" : "y(0.5,x(0.5,0,1),x(0.5,2,3))";
    layout = ViewLayout::fromText(text);
    views.clear();
    views[0].content = "final";
    const std::size_t shown = std::min<std::size_t>(contents.size(), 3);
    for (std::size_t i = 0; i < shown; ++i) views[int(i) + 1].content = contents[i];
    for (int id : layout.views()) views[id];  // a layout's view without a content keeps the default
    nextView = int(views.size());
    lessonGrid = true;
    return 1;
}

int ViewGrid::restore(const SessionState& s) {
    if (s.layout.empty()) {
        reset(s.view);
        ViewState& v = views[1];
        v.transform.zoom = s.viewZoom;
        v.transform.center = s.viewCenter;
        v.transform.clampCenter();
        return 1;
    }
    ViewLayout parsed = ViewLayout::fromText(s.layout);  // throws before anything changes
    std::map<int, ViewState> restored;
    for (int id : parsed.views()) restored[id];
    for (const SessionState::GridView& g : s.gridViews) {
        if (!restored.count(g.id)) continue;
        ViewState& v = restored[g.id];
        v.content = g.content;
        v.layer = std::max(0, g.layer);
        v.transform.zoom = g.zoom;
        v.transform.center = g.center;
        v.transform.clampCenter();
        DisplaySettings& d = v.display;
        d.channel = Channel(g.channel);
        d.range = RangeMode(g.range);
        d.colourMap = ColourMap(g.colourMap);
        d.difference = DifferenceMode(g.difference);
        d.manualMin = g.manualMin;
        d.manualMax = g.manualMax;
        d.logScale = g.logScale;
        d.markNegative = g.markNegative;
        d.stripOpen = g.stripOpen;
        d.against = g.against;
    }
    layout = std::move(parsed);
    views = std::move(restored);
    if (s.maximisedView >= 0 && layout.contains(s.maximisedView)) layout.toggleMaximise(s.maximisedView);
    nextView = 0;
    for (int id : layout.views()) nextView = std::max(nextView, id + 1);
    lessonGrid = false;
    return layout.contains(s.focusedView) ? s.focusedView : layout.views().front();
}

int ViewGrid::split(int focused, SplitAxis axis) {
    layout.restore();
    if (!layout.split(focused, axis, nextView)) return -1;
    const int id = nextView++;
    views[id];
    return id;
}

int ViewGrid::close(int focused) {
    if (!layout.close(focused)) return -1;
    views.erase(focused);
    return layout.views().front();
}

void ViewGrid::swap(int focused, int step) {
    layout.restore();
    layout.swap(focused, layout.next(focused, step));
}

}  // namespace airlight
