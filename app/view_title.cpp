#include "view_title.h"

#include <algorithm>
#include <cmath>

#include "core/text.h"
#include "temporal_monitor.h"
#include "text_fit.h"

namespace airlight {

std::pair<std::string, std::string> viewTitle(const ViewState& v, const ViewTitleFacts& f) {
    if (!f.haveOutput) return {f.gpuTechnique ? "(no view)" : "computing...", ""};
    std::string title = v.pane.label.empty() ? v.content : v.pane.label;
    // The temporal view's running score, in the first section: a narrow title keeps that one whole.
    const bool temporal = v.pane.id == kTemporalChangeId || v.pane.id == kTemporalErrorChangeId;
    if (v.pane.id == kTemporalChangeId) title += ": " + f.temporalChange;
    if (v.pane.id == kTemporalErrorChangeId) title += ": " + f.temporalErrorChange;
    // --path: how far the reference's frames of the loop are while some are still to come (the error
    // change view needs two in a row), or why there are none.
    if (temporal && !f.referenceError.empty()) {
        title += "   reference failed: " + f.referenceError;
    } else if (temporal && f.referenceReady < f.referenceTotal) {
        title += "   reference frames " + std::to_string(f.referenceReady) + "/" +
                 std::to_string(f.referenceTotal);
        // What the rest will take, once one frame has been computed (minutes a frame for an area light).
        if (const double s = f.referenceSecondsPerFrame; s > 0.0)
            title += viz::format(", %.3g s each", s);
    }
    if (v.shown >= 0) title += "   [" + std::to_string(v.shown + 1) + "/" + std::to_string(f.contentCount) + "]";
    if (v.pane.id != "final" && v.pane.id != "airlight" && !temporal) {
        title += "  " + v.pane.id;
        // The stage that publishes it (stepping shows it from that stage on).
        if (f.stages)
            if (const int k = viz::stageOfIntermediate(*f.stages, v.pane.id); k >= 0)
                title += "  (stage " + (*f.stages)[std::size_t(k)].id + ")";
    }
    if (v.pane.layers > 1) title += "   layer " + std::to_string(v.pane.layer + 1) + "/" + std::to_string(v.pane.layers);
    std::string note = v.pane.note;
    if (v.pane.id == "final" && v.display.difference == DifferenceMode::Off)
        note = "surface radiance * exp(-sigma_t d) + L_air   (exposure " + viz::format("%+.1f EV)", std::round(f.exposure * 10.0) / 10.0 + 0.0);  // never "-0.0"
    const DisplayMapping m = resolveMapping(v.pane, v.display, f.exposure, v.measured);
    const bool picture = v.pane.picture && m.mode == DisplayMode::RangeColour;  // no range to state
    if (m.mode != DisplayMode::HdrColour && !picture) {
        // A multi-quantity pane names the channel shown, with that quantity's units.
        const viz::ChannelInfo* declared = declaredChannel(v.pane, v.display.channel);
        const std::string& units = declared ? declared->units : v.pane.units;
        note += "   [" + viz::format("%.4g", m.lo) + ", " + viz::format("%.4g", m.hi) + "]" + (v.display.logScale ? " log" : "") +
                (units.empty() ? "" : " " + units) + ", " +
                (declared ? "showing " + declared->name : std::string(viz::viewKindName(v.pane.kind)));
    }
    if (v.error) {
        const auto figure = [](double x) { return std::isfinite(x) ? viz::format("%.3g", x) : std::string("n/a"); };
        note = "relative L2 " + figure(v.error->relativeL2) + "   max |a - b| " + figure(v.error->maxAbsolute) +
               "   RMSE " + figure(v.error->rmse) + "   |   " + note;
    } else if (!v.differenceNote.empty()) {
        note = v.differenceNote + "   |   " + note;
    }
    if (v.transform.zoom > 1.0) note = viz::format("zoom %.0fx (wheel; drag to pan; 0 fits)   ", v.transform.zoom) + note;
    return {title, note};
}

TitleWarnings titleWarnings(const ViewState& v, const std::string& stoppedEarly, float exposure) {
    TitleWarnings w;
    if (!stoppedEarly.empty()) w.early = "   [" + stoppedEarly + "]";
    if (!v.standIn.empty()) w.early += "   [" + v.standIn + "]";
    const SpecialCounts& n = v.counts;
    const int negative = resolveMapping(v.pane, v.display, exposure, v.measured).markNegative ? n.negative : 0;
    if (n.nan + n.inf + negative > 0) {
        w.counts = " ";
        if (negative) w.counts += " " + std::to_string(negative) + " negative";
        if (n.nan) w.counts += " " + std::to_string(n.nan) + " NaN";
        if (n.inf) w.counts += " " + std::to_string(n.inf) + " Inf";
        w.counts += " px";
    }
    return w;
}

FittedTitle fitTitleBar(const viz::ui::FontAtlas& font, const std::string& title, const TitleWarnings& warnings,
                        const std::string& note, float width, float noteWidth) {
    FittedTitle f;
    const float warningWidth = font.measure(warnings.early + warnings.counts);
    f.title = elideSections(font, title, std::max(0.35f * width, width - warningWidth));
    const float rest = width - font.measure(f.title);
    f.early = elideBracketWords(font, warnings.early, std::max(0.0f, rest - font.measure(warnings.counts)));
    f.note = elideSections(font, note, noteWidth);
    f.titleElided = f.title != title || f.early != warnings.early;
    f.noteElided = f.note != note;
    return f;
}

}  // namespace airlight
