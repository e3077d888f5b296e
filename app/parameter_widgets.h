// The parameter panel's widgets as plain functions of the immediate-mode UI and the values they edit:
// a technique parameter's widget chosen from its declaration (never from its current value), the medium,
// a light's placement and the preset picker. The window composes them into its panel
// (window_parameters.cpp); tests drive them with synthetic input (tests/cpu/ui/parameter_widgets_test.cpp).
#pragma once

#include <optional>

#include "debug/technique.h"
#include "on_off_slider.h"
#include "scene/scene.h"
#include "ui/immediate.h"

namespace airlight {

// Which widget a parameter gets, from its declaration:
// - Choice: a combo over its declared choices;
// - Toggle: a checkbox (an integer from 0 to 1);
// - Drag: a drag field (a range over 1e4 wide that reaches 0 or below: a slider would be too coarse);
// - LogSlider: a log slider (positive range spanning a factor of 100 or more);
// - IntSlider, Slider: a linear slider over the declared range.
enum class ParamWidget { Choice, Toggle, Drag, LogSlider, IntSlider, Slider };
ParamWidget paramWidgetFor(const viz::ParamInfo& p);

// Draws `p`'s widget for `value` (labelled with its name, its help as tooltip). True when the user changed
// it: the new value is then within the declared range, whole for an integer parameter, one of the choices'
// indices for a choice.
bool parameterWidget(viz::ui::Context& ui, const viz::ParamInfo& p, double& value);

// The medium's scattering and absorption (each 0 through its "on" box) and phase asymmetry; true when one
// changed. Values are written only when a widget changes them, so the scene keeps its exact doubles.
bool mediumWidgets(viz::ui::Context& ui, viz::scene::Medium& medium, OnOffSlider& sigmaS, OnOffSlider& sigmaA);

// Where the light points (azimuth and elevation of a spot's or a directional light's direction) and where
// it is (a point or spot light's position, dragged at a speed proportional to `orbitDistance`); an area
// light's rectangle is scene geometry and stays put. True when the light changed.
bool lightPlacementWidgets(viz::ui::Context& ui, viz::scene::Light& light, double orbitDistance);

// The preset picker for a technique with a paper configuration: "ours (defaults)", "paper", or "(mixed)"
// when the parameters where the two differ are neither. `current`: the technique's complete settings.
// Returns the values to set when the user picked ours or paper (only the parameters the two differ in).
std::optional<viz::Settings> presetWidget(viz::ui::Context& ui, const viz::Technique& technique,
                                          const viz::Settings& current);

}  // namespace airlight
