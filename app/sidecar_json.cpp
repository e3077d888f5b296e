#include "sidecar_json.h"

#include <cmath>

namespace airlight {

namespace {

nlohmann::json rectJson(const viz::ui::Rect& r) { return {r.min.x, r.min.y, r.max.x, r.max.y}; }

nlohmann::json numberOrNull(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

}  // namespace

nlohmann::json planJson(const viz::Plan& plan) {
    nlohmann::json skipped = nlohmann::json::array(), features = nlohmann::json::array();
    for (const viz::StagePlan& st : plan.stages)
        if (!st.runs) skipped.push_back({{"stage", st.stage}, {"why", st.why}});
    for (const viz::FeaturePlan& f : plan.features) features.push_back({{"feature", f.feature}, {"on", f.enabled}, {"why", f.why}});
    return {{"skipped", skipped}, {"features", features}};
}

nlohmann::json lightsJson(const std::vector<viz::scene::Light>& lights) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& l : lights)
        out.push_back({{"name", l.name},
                       {"position", {l.position.x, l.position.y, l.position.z}},
                       {"direction", {l.direction.x, l.direction.y, l.direction.z}},
                       {"intensity", l.intensity}});
    return out;
}

nlohmann::json timingJson(const viz::Timing& timing) {
    nlohmann::json stages = nlohmann::json::array();
    for (const viz::StageTiming& s : timing.stages)
        if (std::isfinite(s.milliseconds)) stages.push_back({{"stage", s.stage}, {"ms", s.milliseconds}});
    return {{"clock", timing.clock}, {"stages", stages}};
}

nlohmann::json colourBarJson(const ColourBar& b, const viz::ui::Rect& rect, const viz::ui::Rect& ramp) {
    const char* kind = b.kind == ColourBar::Kind::Ramp ? "ramp" : b.kind == ColourBar::Kind::Classes ? "classes" : "picture";
    nlohmann::json bar = {{"kind", kind},
                          {"lo", numberOrNull(b.lo)}, {"hi", numberOrNull(b.hi)}, {"log", b.logarithmic},
                          {"units", b.units}, {"caption", b.caption},
                          {"rect", rectJson(rect)}, {"ramp_rect", rectJson(ramp)}};
    nlohmann::json ticks = nlohmann::json::array(), at = nlohmann::json::array();
    for (std::size_t i = 0; i < b.ticks.size(); ++i) ticks.push_back(numberOrNull(b.ticks[i])), at.push_back(b.tickAt[i]);
    bar["ticks"] = ticks;
    bar["tick_labels"] = b.tickLabels;
    bar["tick_at"] = at;
    if (b.kind == ColourBar::Kind::Classes) bar["classes"] = b.classLabels;
    nlohmann::json legend = nlohmann::json::array();
    for (const LegendSwatch& sw : b.legend)
        // The overlays' values are NaN and Inf themselves: named, not null.
        legend.push_back({{"label", sw.label},
                          {"value", std::isfinite(sw.value) ? nlohmann::json(sw.value)
                                                            : nlohmann::json(std::isnan(sw.value) ? "NaN" : sw.value > 0 ? "Inf" : "-Inf")},
                          {"pixels", sw.pixels}, {"sentinel", sw.sentinel}});
    bar["legend"] = legend;
    return bar;
}

}  // namespace airlight
