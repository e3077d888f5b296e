// Parts of the screenshot sidecar (the JSON beside a window screenshot that tests and handouts read) that
// are plain conversions of one value: the plan, the lights, the last run's stage times, a colour bar as
// drawn. The window assembles the sidecar from them (window_automation.cpp).
#pragma once

#include <vector>

#include <nlohmann/json.hpp>

#include "colour_bar.h"
#include "debug/technique.h"
#include "scene/scene.h"
#include "ui/text_renderer.h"

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

}  // namespace airlight
