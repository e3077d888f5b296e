#include "app_state.h"

namespace airlight {

SessionState sessionOf(const AppState& state, SessionState s) {
    s.scene = state.scene;
    s.technique = state.technique;
    s.width = state.size.x;
    s.height = state.size.y;
    s.camera = state.camera;
    s.orbitTarget = state.orbitTarget;
    s.medium = state.medium;
    viz::scene::Scene lit;
    lit.lights = state.lights;
    s.lights = lightPlacements(lit);
    // Only what differs from the technique's defaults is kept, per technique.
    viz::Settings changed;
    for (const auto& [name, value] : state.settings)
        if (!state.defaults.count(name) || state.defaults.at(name) != value) changed[name] = value;
    s.settings[s.technique] = changed;
    // The first view in reading order that is not the final frame, for files read by older builds.
    s.view = "airlight";
    s.viewZoom = 1.0;
    s.viewCenter = glm::dvec2(0.5);
    for (const AppState::View& v : state.views)
        if (v.content != "final") {
            s.view = v.content;
            s.viewZoom = v.zoom;
            s.viewCenter = v.center;
            break;
        }
    s.layout = state.layout;
    s.focusedView = state.focusedView;
    s.maximisedView = state.maximisedView;
    s.gridViews.clear();
    for (const AppState::View& v : state.views) {
        const DisplaySettings& d = v.display;
        s.gridViews.push_back({v.id, v.content, v.layer, v.zoom, v.center, int(d.channel), int(d.range),
                               int(d.colourMap), int(d.difference), d.manualMin, d.manualMax, d.markNegative,
                               d.logScale, d.stripOpen, d.against});
    }
    s.exposure = state.exposure;
    s.exposureSet = state.exposureSet;
    return s;
}

LessonWindowState lessonStateOf(const AppState& state) {
    LessonWindowState s;
    s.scene = state.scene;
    s.technique = state.technique;
    s.size = state.size;
    s.settings = state.steppedSettings;
    s.stage = state.stageShown;
    s.view = "airlight";
    for (const AppState::View& v : state.views)
        if (v.id == state.focusedView) s.view = v.content;
    s.inspect = state.inspected;
    s.camera = state.camera;
    s.orbitTarget = state.orbitTarget;
    s.medium = state.medium;
    s.lights = state.lights;
    return s;
}

nlohmann::json sidecarStateOf(const AppState& state) {
    const viz::scene::Camera& c = state.camera;
    nlohmann::json j = {
        {"scene_source", state.scene},
        {"technique", state.technique},
        {"size", {state.size.x, state.size.y}},
        {"medium", {{"sigma_s", state.medium.sigma_s}, {"sigma_a", state.medium.sigma_a}, {"g", state.medium.g}}},
        {"settings", state.settings},
        {"cursor", {{"stage", state.cursor.stage}, {"substep", state.cursor.substep}}},
        {"camera", {{"mode", state.flyCamera ? "fly" : "orbit"},
                    {"position", {c.position.x, c.position.y, c.position.z}},
                    {"forward", {c.forward.x, c.forward.y, c.forward.z}},
                    {"target", {state.orbitTarget.x, state.orbitTarget.y, state.orbitTarget.z}}}},
        {"exposure", state.exposure},
        {"exposure_set", state.exposureSet},
        {"selected_light", state.selectedLight},
        {"focused_view", state.focusedView}};
    j["inspected"] = state.inspected ? nlohmann::json::array({state.inspected->x, state.inspected->y}) : nlohmann::json(nullptr);
    return j;
}

}  // namespace airlight
