#include "parameter_widgets.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace airlight {

ParamWidget paramWidgetFor(const viz::ParamInfo& p) {
    if (!p.choices.empty()) return ParamWidget::Choice;
    if (p.integer && p.minValue == 0.0 && p.maxValue == 1.0) return ParamWidget::Toggle;
    if (p.maxValue - p.minValue > 1e4 && !(p.minValue > 0.0)) return ParamWidget::Drag;
    if (p.minValue > 0.0 && p.maxValue / p.minValue >= 100.0) return ParamWidget::LogSlider;
    return p.integer ? ParamWidget::IntSlider : ParamWidget::Slider;
}

bool parameterWidget(viz::ui::Context& ui, const viz::ParamInfo& p, double& value) {
    bool changed = false;
    double next = value;
    switch (paramWidgetFor(p)) {
    case ParamWidget::Choice: {
        int index = int(value);
        changed = ui.combo(p.name, index, p.choices);
        next = index;
        break;
    }
    case ParamWidget::Toggle: {
        bool on = value != 0.0;
        changed = ui.checkbox(p.name, on);
        next = on ? 1.0 : 0.0;
        break;
    }
    case ParamWidget::Drag: {
        float v = float(value);
        changed = ui.dragFloat(p.name, v, float(std::max(1.0, std::abs(value)) * 0.01), float(p.minValue),
                               float(p.maxValue));
        next = p.integer ? std::round(v) : v;
        break;
    }
    case ParamWidget::LogSlider: {
        float v = float(value);
        changed = ui.sliderFloat(p.name, v, float(p.minValue), float(p.maxValue), true);
        next = p.integer ? std::round(v) : v;
        break;
    }
    case ParamWidget::IntSlider: {
        int v = int(value);
        changed = ui.sliderInt(p.name, v, int(p.minValue), int(p.maxValue));
        next = v;
        break;
    }
    case ParamWidget::Slider: {
        float v = float(value);
        changed = ui.sliderFloat(p.name, v, float(p.minValue), float(p.maxValue));
        next = v;
        break;
    }
    }
    ui.tooltip(p.help);
    // The widgets work in float, the declaration in double: a slider's end as a float may lie just outside
    // the declared range (0.01f < 0.01), which the technique would refuse as out of range.
    if (paramWidgetFor(p) != ParamWidget::Choice && paramWidgetFor(p) != ParamWidget::Toggle)
        next = std::clamp(next, p.minValue, p.maxValue);
    if (!changed || next == value) return false;
    value = next;
    return true;
}

bool mediumWidgets(viz::ui::Context& ui, viz::scene::Medium& m, OnOffSlider& sigmaS, OnOffSlider& sigmaA) {
    // 0 is a box unticked ("scatters", "absorbs"): sigma_s = 0 makes L_air 0, sigma_a = 0 leaves extinction
    // to scattering.
    bool changed = sigmaS.draw(ui, "scatters", "sigma_s (scattering)", m.sigma_s);
    ui.tooltip("per scene unit; untick 'scatters' for sigma_s = 0 (no airlight)");
    changed = sigmaA.draw(ui, "absorbs", "sigma_a (absorption)", m.sigma_a) || changed;
    ui.tooltip("per scene unit; untick 'absorbs' for sigma_a = 0");
    float g = float(m.g);
    if (ui.sliderFloat("g (Henyey-Greenstein)", g, -0.99f, 0.99f)) m.g = g, changed = true;
    ui.tooltip("phase function asymmetry: > 0 scatters forward, < 0 back");
    return changed;
}

bool lightPlacementWidgets(viz::ui::Context& ui, viz::scene::Light& light, double orbitDistance) {
    using viz::scene::LightType;
    bool changed = false;
    if (light.type == LightType::Spot || light.type == LightType::Directional) {
        const glm::dvec3 d = glm::normalize(light.direction);
        float azimuth = float(glm::degrees(std::atan2(d.x, -d.z)));
        float elevation = float(glm::degrees(std::asin(std::clamp(d.y, -1.0, 1.0))));
        const bool turned = ui.sliderFloat("direction azimuth (deg)", azimuth, -180.0f, 180.0f);
        ui.tooltip("about the vertical axis; 0 travels along -z");
        const bool tilted = ui.sliderFloat("direction elevation (deg)", elevation, -90.0f, 90.0f);
        if (turned || tilted) {
            const double a = glm::radians(double(azimuth)), e = glm::radians(double(elevation));
            light.direction = {std::cos(e) * std::sin(a), std::sin(e), -std::cos(e) * std::cos(a)};
            changed = true;
        }
    }
    if (light.type == LightType::Point || light.type == LightType::Spot) {
        const float speed = float(0.004 * std::max(orbitDistance, 1e-3));
        const char* names[3] = {"position x", "position y", "position z"};
        for (int axis = 0; axis < 3; ++axis) {
            float v = float(light.position[axis]);
            if (ui.dragFloat(names[axis], v, speed, -1e6f, 1e6f)) {
                light.position[axis] = v;
                changed = true;
            }
        }
    }
    return changed;
}

std::optional<viz::Settings> presetWidget(viz::ui::Context& ui, const viz::Technique& technique,
                                          const viz::Settings& current) {
    const viz::Settings paper = technique.paperSettings();
    if (paper.empty()) return std::nullopt;
    const viz::Settings defaults = viz::completeSettings(technique, {});
    bool isPaper = true, isOurs = true;
    std::string names;
    for (const auto& [name, value] : paper) {
        isPaper = isPaper && current.at(name) == value;
        isOurs = isOurs && current.at(name) == defaults.at(name);
        names += (names.empty() ? "" : ", ") + name;
    }
    int index = isPaper ? 1 : isOurs ? 0 : 2;
    const std::vector<std::string> choices = {"ours (defaults)", "paper", "(mixed)"};
    const bool changed = ui.combo("preset", index, choices);
    ui.tooltip("the paper's own configuration or Airlight's defaults, for " + names +
               " (airlight render --preset paper)");
    if (!changed || index == 2) return std::nullopt;
    viz::Settings picked;
    for (const auto& [name, value] : paper) picked[name] = index == 1 ? value : defaults.at(name);
    return picked;
}

}  // namespace airlight
