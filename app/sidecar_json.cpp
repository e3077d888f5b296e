#include "sidecar_json.h"

#include <algorithm>
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
        if (std::isfinite(s.milliseconds))
            stages.push_back({{"stage", s.stage}, {"ms", s.milliseconds}, {"programs_compiled", s.programsCompiled}});
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

nlohmann::json animationJson(const WindowAnimation& a) {
    nlohmann::json j = {{"playing", a.playing},
                        {"seconds", a.clock},
                        {"light_turn", a.turn},
                        {"frame", a.frame},
                        {"temporal_pairs", a.temporal.pairs()}};
    // The temporal view's score, once there is one (two frames played).
    if (std::isfinite(a.temporal.score())) j["temporal_change_rms"] = a.temporal.score();
    // Against the reference (--path with a temporal view shown): its frames and the error's score.
    j["temporal_error_pairs"] = a.temporal.errorPairs();
    if (std::isfinite(a.temporal.errorScore())) j["temporal_error_rms"] = a.temporal.errorScore();
    j["reference_frames"] = {{"ready", a.reference.ready()},
                             {"total", a.reference.total()},
                             {"seconds_per_frame", a.reference.secondsPerFrame()},
                             {"error", a.reference.error()}};
    // --path: the motion and the loop's frame shown.
    if (a.path) j["path"] = {{"text", a.path->text}, {"frames", a.pathFrames}, {"frame", a.pathFrame}};
    return j;
}

nlohmann::json viewSidecar(const ViewState& v, const ViewSidecarFacts& facts) {
    const DisplaySettings& d = v.display;
    const DisplayMapping m = resolveMapping(v.pane, d, facts.exposure, v.measured);
    nlohmann::json j = {{"cell", facts.id},
                        {"content", v.content},
                        {"cell_rect", rectJson(v.cell)},
                        {"focused", facts.focused},
                        {"layer", v.pane.layer},
                        {"zoom", v.transform.zoom},
                        {"center", {v.transform.center.x, v.transform.center.y}},
                        {"size", {v.pane.size.x, v.pane.size.y}},
                        {"screen_space", facts.screenSpace},
                        {"display", {{"channel", channelChoices(v.pane)[std::size_t(d.channel)]},
                                     {"range", rangeModeNames()[std::size_t(d.range)]},
                                     {"lo", m.lo}, {"hi", m.hi}, {"log", d.logScale},
                                     {"colour_map", colourMapNames()[std::size_t(d.colourMap)]},
                                     {"mode", int(m.mode)}, {"mark_negative", m.markNegative},
                                     {"strip_open", d.stripOpen}}},
                        {"plots", v.pane.plots.size()},
                        {"title_elided", v.titleElided},
                        {"note_elided", v.noteElided},
                        {"negative_pixels", v.counts.negative},
                        {"nan_pixels", v.counts.nan},
                        {"inf_pixels", v.counts.inf}};
    // What the bar under the view says, as drawn in the last frame.
    if (v.colourBar.kind != ColourBar::Kind::None) j["colour_bar"] = colourBarJson(v.colourBar, v.bar, v.ramp);
    if (d.difference != DifferenceMode::Off) {
        // Figures only where they were computed and are defined (relative L2 is not against a black
        // reference); the note says why one is missing.
        nlohmann::json diff = {{"mode", differenceModeNames()[std::size_t(d.difference)]},
                               {"against", d.against}, {"note", v.differenceNote}};
        if (v.error && std::isfinite(v.error->relativeL2)) diff["relative_l2"] = v.error->relativeL2;
        if (v.error && std::isfinite(v.error->maxAbsolute)) diff["max_abs"] = v.error->maxAbsolute;
        j["difference"] = std::move(diff);
    }
    // The linked cursor as this view marks it: the pixel itself in screen-space views.
    j["cursor"] = nullptr;
    if (facts.linkedPixel && facts.screenSpace) {
        const glm::ivec2 at = *facts.linkedPixel;
        j["cursor"] = {at.x, at.y};
        if (glm::vec4 value(0.0f); valueAt(v, at, value)) {
            nlohmann::json values = nlohmann::json::array();
            for (int c = 0; c < std::clamp(v.meaningful, 1, 4); ++c)
                values.push_back(std::isfinite(value[c]) ? nlohmann::json(value[c]) : nlohmann::json(nullptr));
            j["cursor_value"] = values;
        }
    }
    if (facts.markers) {
        nlohmann::json marks = nlohmann::json::array();
        for (const viz::ViewMarker& mk : *facts.markers)
            marks.push_back({{"from", {mk.from.x, mk.from.y}}, {"to", {mk.to.x, mk.to.y}}, {"label", mk.label},
                             {"layer", mk.layer}});
        j["markers"] = marks;
    }
    return j;
}

}  // namespace airlight
