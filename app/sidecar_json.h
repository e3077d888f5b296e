// Parts of the screenshot sidecar (the JSON beside a window screenshot that tests and handouts read) that
// are plain conversions of one value: the plan, the lights, the last run's stage times, a colour bar as
// drawn, the animation, one view of the grid. The window assembles the sidecar from them (window_automation.cpp).
#pragma once

#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "colour_bar.h"
#include "debug/technique.h"
#include "scene/scene.h"
#include "ui/text_renderer.h"
#include "view_state.h"
#include "window_animation.h"

namespace airlight {

// {"skipped": [{stage, why}] (only the stages that do not run), "features": [{feature, on, why}]}.
nlohmann::json planJson(const viz::Plan& plan);
// [{name, position, direction, intensity}] per light.
nlohmann::json lightsJson(const std::vector<viz::scene::Light>& lights);
// {"clock", "stages": [{stage, ms}]}, the stages whose time is known (finite).
nlohmann::json timingJson(const viz::Timing& timing);
// What the bar under a view says: kind, range, units, caption, ticks (non-finite numbers as null), the
// classes of a class bar, the legend's swatches (NaN and Inf named), and where it and its ramp were drawn.
nlohmann::json colourBarJson(const ColourBar& bar, const viz::ui::Rect& rect, const viz::ui::Rect& ramp);

// The animation (P) and what it measured: playing, seconds, the light's turn, frames; the temporal view's
// pairs and change RMS (once two frames were played) and, along a --path, its error RMS against the
// reference's frames, those frames' progress and the path itself with the loop's frame shown.
nlohmann::json animationJson(const WindowAnimation& a);

// What the window knows about a view beyond the view itself.
struct ViewSidecarFacts {
    int id = 0;                               // its cell in the view grid
    bool focused = false;
    bool screenSpace = false;                 // one texel per frame pixel: the linked cursor is its pixel
    float exposure = 0.0f;                    // the window's, for the resolved display mapping
    std::optional<glm::ivec2> linkedPixel;    // the linked cursor, when there is one
    std::optional<std::vector<viz::ViewMarker>> markers;  // what a data view marks for the linked cursor
};

// One view of the grid: what it shows and how (content, layer, zoom, the display settings resolved),
// its counts of negative, NaN and Inf pixels, its colour bar, the difference figures when it shows a
// difference (only those defined), the linked cursor and the values under it (non-finite as null), and
// the markers a data view draws for it.
nlohmann::json viewSidecar(const ViewState& v, const ViewSidecarFacts& facts);

}  // namespace airlight
