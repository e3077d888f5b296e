// What the window's last frame drew where, by name: the one registry every part registers its rectangles
// in (sidebar items, grid views' cells, titles and strips, colour bars, gizmo handles, the timeline, the
// comparison grid), which scripts (`click NAME`) and the screenshot sidecar read. The immediate-mode UI's
// widgets keep their own registry (viz/ui/immediate.h, which scrolls a panel to a widget); find() and
// known() consult it first, as a script names either.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "ui/text_renderer.h"

namespace airlight {

class ScreenMap {
public:
    using Rect = viz::ui::Rect;
    // A view's image: its content's name (a pane id), its title, and the grid's view number (-1 for the
    // comparison grid's parts).
    struct View {
        std::string name, title;
        Rect rect;
        int cell = -1;
    };

    void clear();
    // A named rectangle; a later one of the same name replaces it unless `keepFirst` (a gizmo handle is
    // named after the first view that shows it).
    void place(const std::string& name, const Rect& rect, bool keepFirst = false);
    // A view's image, in drawing order; a script may name it too.
    void placeView(View view);

    // The rectangle a script names: a widget's, else a view's (the first of that name), else a named one.
    std::optional<Rect> find(const std::string& name, const std::map<std::string, Rect>& widgets) const;
    // Every name find() knows, for the error that names none: named ones, views, widgets.
    std::string known(const std::map<std::string, Rect>& widgets) const;

    const std::vector<View>& views() const { return mViews; }

private:
    std::map<std::string, Rect> mNamed;
    std::vector<View> mViews;
};

}  // namespace airlight
