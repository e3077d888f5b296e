// The sidebar at the window's left edge: the techniques (Tab, 1-9) and the frame's views ([ ]), two
// headed lists of entries. The layout is a plain function (tested); the window draws each entry as a
// clickable list item and registers it for scripts under its screen name.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "ui/immediate.h"

namespace airlight {

struct SidebarEntry {
    enum class List { Techniques, Views };
    List list = List::Techniques;
    int index = 0;            // into the list given
    std::string text;         // as drawn ("1  reference")
    std::string screenName;   // for scripts ("technique:reference", "view:Final image")
    bool selected = false;
    viz::ui::Rect rect;
};

struct SidebarHeading {
    std::string text;
    glm::vec2 at{0.0f};
    bool stage = false;  // a stage's sub-heading in the views list ("4 Ray march"), drawn dimmer
    bool hidden = false;  // says how many views the list leaves out above or below ("(5 more views: [ ])")
};

struct SidebarLayout {
    viz::ui::Rect panel;
    std::vector<SidebarHeading> headings;
    std::vector<SidebarEntry> entries;
};

struct SidebarMetrics {
    float top = 0.0f, bottom = 0.0f;  // the panel's vertical extent (its first line starts at `top`)
    float pad = 0.0f, line = 0.0f, scale = 1.0f;
    float minWidth = 0.0f;
    std::function<float(const std::string&)> measure;  // text width in pixels
};

// Techniques first, every one of them, numbered 1-9 for the digit keys; then as many views as fit above
// the panel's bottom (none before the first run: `views` empty), scrolled as little as shows the view
// shown, with a line above and below saying how many views are left out. Wide enough for every technique's name.
// A run of kViewGroupMin or more views named alike ("VPL shadow cube", "VPL shadow cube 1", ...) is one
// entry, "VPL shadow cube (16)", that shows its first view, unless the view shown is one of them:
// then each is listed. [ ] step through every view either way.
// `viewStages[i]` names the stage that makes view i, as the stage bar does ("4 Ray march"); "" for the
// run's own outputs (the final image and L_air). Each stage's views sit under its sub-heading, so a
// stage's intermediate "L_air" is not mistaken for the run's "Airlight L_air". Empty: no sub-headings.
inline constexpr int kViewGroupMin = 4;

// The runs of views named alike: a name's stem is the name less a trailing " <digits>". A run never
// spans two stages (`viewStages` as for layoutSidebar; empty: one stage).
struct ViewGroup {
    int first = 0, count = 1;
    std::string stem;
    std::string stage;  // the stage that makes them ("" for the run's outputs or without `viewStages`)
};
std::vector<ViewGroup> groupViews(const std::vector<std::string>& views, const std::vector<std::string>& viewStages = {});

SidebarLayout layoutSidebar(const std::vector<std::string>& techniques, int currentTechnique,
                            const std::vector<std::string>& views, const std::vector<std::string>& viewStages,
                            int shownView, const SidebarMetrics& m);

}  // namespace airlight
