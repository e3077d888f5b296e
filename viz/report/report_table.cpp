#include "report/report_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "report/text_output.h"
#include "report/tradeoff.h"

namespace viz::report {

namespace {

std::string number(double v) { return formatFigure(v); }

nlohmann::json jsonNumber(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json workJson(const ReportRow& r) {
    if (r.work.empty()) return nullptr;
    nlohmann::json j = nlohmann::json::object();
    for (const auto& [name, count] : r.work) j[name] = count;
    return j;
}

std::string workText(const ReportRow& r) {
    std::string text;
    for (const auto& [name, count] : r.work) text += (text.empty() ? "" : ";") + name + "=" + std::to_string(count);
    return text;
}

nlohmann::json temporalJson(const std::optional<TemporalFigures>& t) {
    if (!t) return nullptr;
    return {{"path", t->path},
            {"frames", t->frames},
            {"mean_frame_error", jsonNumber(t->meanFrameError)},
            {"temporal_rms", jsonNumber(t->temporalRms)},
            {"worst_flicker", jsonNumber(t->worstFlicker)},
            {"ms_per_frame", jsonNumber(t->msPerFrame)},
            {"excluded_differences", t->excludedDifferences},
            {"flicker_image", t->flickerImage}};
}

}  // namespace

void annotateTradeoffs(std::vector<ReportRow>& rows, const std::string& baseline) {
    std::set<std::string> scenes;
    for (const ReportRow& r : rows) scenes.insert(r.scene);
    for (const std::string& scene : scenes) {
        std::vector<int> members;
        std::vector<TradeoffPoint> points, baselinePoints;
        for (int i = 0; i < int(rows.size()); ++i) {
            const ReportRow& r = rows[std::size_t(i)];
            if (r.scene != scene) continue;
            members.push_back(i);
            points.push_back({r.totalMilliseconds, r.error.relativeL2});
            if (r.technique == baseline) baselinePoints.push_back(points.back());
        }
        for (int m : members) rows[std::size_t(m)].pareto = false;
        for (int k : paretoFront(points)) rows[std::size_t(members[std::size_t(k)])].pareto = true;
        for (std::size_t k = 0; k < members.size(); ++k)
            rows[std::size_t(members[k])].speedup = speedupAtEqualError(baselinePoints, points[k]);
    }
}

double ReportRow::workTotal() const {
    if (work.empty()) return NAN;
    double sum = 0.0;
    for (const auto& [name, count] : work) sum += double(count);
    return sum;
}

const std::vector<double>& errorTargets() {
    static const std::vector<double> kTargets = {0.05, 0.01};
    return kTargets;
}

TargetSpeedup targetSpeedup(const std::vector<ReportRow>& rows, const std::string& scene, const std::string& technique,
                            double target, const std::string& baseline, Measure measure, ErrorOver errorOver) {
    // TradeoffPoint's "milliseconds" is the cost axis: time, or counted operations; for the time, also each
    // row's fastest and slowest run.
    std::vector<TradeoffPoint> base, own, baseFast, baseSlow, ownFast, ownSlow;
    bool spread = measure == Measure::Time;
    for (const ReportRow& r : rows) {
        if (r.scene != scene || (r.technique != baseline && r.technique != technique)) continue;
        const bool isBase = r.technique == baseline;
        const double e = errorOver == ErrorOver::AllPixels ? r.error.relativeL2 : r.relativeL2Agreeing;
        (isBase ? base : own).push_back({measure == Measure::Time ? r.totalMilliseconds : r.workTotal(), e});
        spread = spread && std::isfinite(spreadFraction(r.totalMilliseconds, r.totalSpread));
        (isBase ? baseFast : ownFast).push_back({r.totalSpread.minMilliseconds, e});
        (isBase ? baseSlow : ownSlow).push_back({r.totalSpread.maxMilliseconds, e});
    }
    TargetSpeedup s = speedupAtTarget(base, own, target);
    if (spread && s.bound != TargetSpeedup::Bound::Unknown) {
        const TargetSpeedup low = speedupAtTarget(baseFast, ownSlow, target), high = speedupAtTarget(baseSlow, ownFast, target);
        if (low.bound == s.bound && high.bound == s.bound)
            s.ratioLow = std::min(low.ratio, high.ratio), s.ratioHigh = std::max(low.ratio, high.ratio);
    }
    return s;
}

std::vector<std::string> targetSettings(const std::vector<ReportRow>& rows, const std::string& scene,
                                        const std::string& series, const TimeToTarget& t) {
    std::vector<std::string> labels;
    int k = 0;
    for (const ReportRow& r : rows) {
        if (r.scene != scene || r.technique != series) continue;
        if (k == t.above) labels.insert(labels.begin(), r.setting);
        else if (k == t.below) labels.push_back(r.setting);
        ++k;
    }
    return labels;
}

std::string targetSettingsPhrase(const std::vector<std::string>& settings) {
    if (settings.empty()) return "";
    if (settings.size() == 1) return "at " + settings[0];
    return "between " + settings[0] + " and " + settings[1];
}

std::string targetSpeedupPhrase(const TargetSpeedup& s, const std::string& baseline, Measure measure) {
    using Kind = TimeToTarget::Kind;
    const std::string percent = formatFigure(100.0 * s.target, "%.3g") + " %";
    auto best = [](const TimeToTarget& t) {
        return std::isfinite(t.bestError) ? " (best " + formatFigure(100.0 * t.bestError, "%.3g") + " %)" : std::string();
    };
    if (s.technique.kind == Kind::NotReached) return "does not reach " + percent + best(s.technique);
    if (s.baseline.kind == Kind::NotReached) return baseline + " does not reach " + percent + best(s.baseline);
    const bool time = measure == Measure::Time;
    auto amount = [&](double v) {
        return time ? formatFigure(v, v < 100.0 ? "%.3g" : "%.0f") : formatFigure(v, v < 1e5 ? "%.0f" : "%.3g");
    };
    const std::string unit = time ? " ms" : " ops";
    const std::string times = " (" + amount(s.technique.milliseconds) + unit +
                              (s.technique.kind == Kind::AtMost ? " or less" : "") + " against " +
                              amount(s.baseline.milliseconds) + unit +
                              (s.baseline.kind == Kind::AtMost ? " or less)" : ")");
    const std::string ratio = time ? speedupPhrase(s.ratio) : workRatioPhrase(s.ratio);
    // How far the runs' spread could move it (or the bound, when it is one), when it was measured.
    // Left out when both ends read the same (one timed run, or runs that agree to the printed digits).
    const std::string range =
        time && std::isfinite(s.ratioLow) && std::isfinite(s.ratioHigh) &&
                speedupPhrase(s.ratioLow) != speedupPhrase(s.ratioHigh)
            ? std::string(s.bound == TargetSpeedup::Bound::Exact ? "; " : "; the bound lies ") +
                  speedupRangePhrase(s.ratioLow, s.ratioHigh) + " over the runs' spread"
            : "";
    switch (s.bound) {
        case TargetSpeedup::Bound::Exact: break;
        case TargetSpeedup::Bound::AtLeast: return (s.ratio >= 1.0 ? "at least " : "at most ") + ratio + times + range;
        case TargetSpeedup::Bound::AtMost: return (s.ratio >= 1.0 ? "at most " : "at least ") + ratio + times + range;
        case TargetSpeedup::Bound::Unknown: return "both reach " + percent + " at their cheapest setting" + times;
    }
    return ratio + times + range;
}

bool savingIsSignificant(const PlanSaving& p) {
    // NaN (no runs on a side) compares false: not significant.
    const RunSpread planned = spreadOf(p.plannedRuns), forced = spreadOf(p.forcedRuns);
    return planned.maxMilliseconds < forced.minMilliseconds || forced.maxMilliseconds < planned.minMilliseconds;
}

const std::vector<std::string>& csvColumns() {
    static const std::vector<std::string> kColumns = {
        "scene", "technique", "setting", "settings", "width", "height", "runs", "clock", "total_ms", "wall_ms",
        "relative_l2", "rmse", "max_abs", "relative_p999", "psnr_db", "nan_pixels", "inf_pixels",
        "negative_pixels", "speedup_vs_raymarch", "pareto", "stage_ms",
        // --temporal (empty on rows it does not measure): report/temporal_error.h's figures on a motion path
        "temporal_path", "temporal_frames", "mean_frame_error", "temporal_rms", "worst_flicker", "ms_per_frame",
        "flicker_image",
        // one counting run (gl/work_counters.h): the sum of the counters, and each as name=count
        "work_ops", "work",
        // --temporal: a stabilising option's pair (Technique::stabilisingOptions): "OPTION off" or "OPTION on"
        "stabiliser",
        // the fastest and slowest timed run's sum of stage times (total_ms is their median)
        "total_ms_min", "total_ms_max",
        // the scene's pixels whose rasterised and traced first hits disagree (report/first_hits.h), and
        // relative_l2 over the other pixels
        "first_hit_disagreements", "relative_l2_agreeing"};
    return kColumns;
}

void writeCsv(const std::string& path, const std::vector<ReportRow>& rows) {
    std::ostringstream out;
    const auto& columns = csvColumns();
    for (std::size_t i = 0; i < columns.size(); ++i) out << (i ? "," : "") << columns[i];
    out << "\n";
    for (const ReportRow& r : rows) {
        std::string stages;
        for (const StageTime& s : r.stages) stages += (stages.empty() ? "" : ";") + s.stage + "=" + number(s.milliseconds);
        const std::optional<TemporalFigures>& t = r.temporal;
        const std::vector<std::string> fields = {
            r.scene, r.technique, r.setting, r.settings, std::to_string(r.width), std::to_string(r.height),
            std::to_string(r.runs), r.clock, number(r.totalMilliseconds), number(r.wallMilliseconds),
            number(r.error.relativeL2), number(r.error.rmse), number(r.error.maxAbsolute),
            number(r.error.relativeP999), number(r.error.psnr), std::to_string(r.error.nanPixels),
            std::to_string(r.error.infPixels), std::to_string(r.error.negativePixels),
            r.speedup ? number(*r.speedup) : "", r.pareto ? "1" : "0", stages,
            t ? t->path : "", t ? std::to_string(t->frames) : "", t ? number(t->meanFrameError) : "",
            t ? number(t->temporalRms) : "", t ? number(t->worstFlicker) : "", t ? number(t->msPerFrame) : "",
            t ? t->flickerImage : "", r.work.empty() ? "" : formatFigure(r.workTotal(), "%.0f"), workText(r),
            r.stabiliser.empty() ? "" : r.stabiliser + (r.stabiliserOn ? " on" : " off"),
            number(r.totalSpread.minMilliseconds), number(r.totalSpread.maxMilliseconds),
            std::to_string(r.firstHitDisagreements), number(r.relativeL2Agreeing)};
        for (std::size_t i = 0; i < fields.size(); ++i) out << (i ? "," : "") << csvField(fields[i]);
        out << "\n";
    }
    writeTextFile(path, out.str());
}

void writeJson(const std::string& path, const ReportMeta& meta, const std::vector<ReportRow>& rows,
               const std::vector<PlanSaving>& savings) {
    nlohmann::json j;
    j["meta"] = {{"date", meta.date},         {"command", meta.command}, {"machine", meta.machine},
                 {"renderer", meta.renderer}, {"width", meta.width},     {"height", meta.height},
                 {"runs", meta.runs},         {"quick", meta.quick},
                 {"reference_settings", meta.referenceSettings},
                 {"fragment_over_compute", meta.fragmentOverCompute},
                 {"error_of", "L_air (RGB radiance) against the reference technique's L_air"},
                 {"tone_map", "PSNR on v*k/(1+v*k), k = 0.18 / mean of the reference, peak 1"},
                 {"relative_p999", "99.9th percentile of sum_c|t-r| / max(sum_c|r|, 0.01 * mean sum_c|r|)"},
                 {"relative_l2_agreeing",
                  "relative_l2 over the pixels whose rasterised first hit lies within 0.1 % of the reference's "
                  "traced one; first_hit_disagreements counts the others"},
                 {"temporal", meta.temporal}};
    if (meta.temporal)
        j["meta"]["temporal_of"] =
            "rows' 'temporal': the setting on every frame of its scene's motion path against the reference on the "
            "same frames; e_t = T_t - R_t, d_t = e_t - e_{t-1}; temporal_rms = sqrt(mean d_t^2) / 2 / mean(R), "
            "worst_flicker = 99th percentile over pixels of sqrt(mean over t, c of d_t^2) / 2 / mean(R); "
            "ms_per_frame = median over frames of the sum of stage times";
    nlohmann::json list = nlohmann::json::array();
    for (const ReportRow& r : rows) {
        nlohmann::json stages = nlohmann::json::object();
        for (const StageTime& s : r.stages) stages[s.stage] = jsonNumber(s.milliseconds);
        list.push_back({{"scene", r.scene},
                        {"technique", r.technique},
                        {"setting", r.setting},
                        {"settings", r.settings},
                        {"width", r.width},
                        {"height", r.height},
                        {"runs", r.runs},
                        {"clock", r.clock},
                        {"total_ms", jsonNumber(r.totalMilliseconds)},
                        {"wall_ms", jsonNumber(r.wallMilliseconds)},
                        {"total_ms_min", jsonNumber(r.totalSpread.minMilliseconds)},
                        {"total_ms_max", jsonNumber(r.totalSpread.maxMilliseconds)},
                        {"stage_ms", stages},
                        {"error",
                         {{"relative_l2", jsonNumber(r.error.relativeL2)},
                          {"rmse", jsonNumber(r.error.rmse)},
                          {"max_abs", jsonNumber(r.error.maxAbsolute)},
                          {"relative_p999", jsonNumber(r.error.relativeP999)},
                          {"psnr_db", jsonNumber(r.error.psnr)},
                          {"nan_pixels", r.error.nanPixels},
                          {"inf_pixels", r.error.infPixels},
                          {"negative_pixels", r.error.negativePixels},
                          {"first_hit_disagreements", r.firstHitDisagreements},
                          {"relative_l2_agreeing", jsonNumber(r.relativeL2Agreeing)}}},
                        {"speedup_vs_raymarch", r.speedup ? jsonNumber(*r.speedup) : nlohmann::json(nullptr)},
                        {"pareto", r.pareto},
                        {"image", r.image},
                        {"error_image", r.errorImage},
                        {"temporal", temporalJson(r.temporal)},
                        {"work", workJson(r)},
                        {"work_ops", jsonNumber(r.workTotal())},
                        {"stabiliser", r.stabiliser.empty() ? nlohmann::json(nullptr)
                                                            : nlohmann::json{{"option", r.stabiliser},
                                                                             {"on", r.stabiliserOn}}}});
    }
    j["rows"] = list;
    nlohmann::json targets = nlohmann::json::array();
    {
        std::vector<std::string> scenes, techniques;
        for (const ReportRow& r : rows) {
            if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) scenes.push_back(r.scene);
            if (std::find(techniques.begin(), techniques.end(), r.technique) == techniques.end())
                techniques.push_back(r.technique);
        }
        static const char* kKinds[] = {"interpolated", "at_most", "not_reached"};
        static const char* kBounds[] = {"exact", "at_least", "at_most", "unknown"};
        for (const std::string& scene : scenes)
            for (const std::string& technique : techniques) {
                if (technique == "raymarch") continue;
                for (double target : errorTargets()) {
                    const TargetSpeedup t = targetSpeedup(rows, scene, technique, target);
                    targets.push_back({{"scene", scene},
                                       {"technique", technique},
                                       {"target_relative_l2", target},
                                       {"technique_ms", jsonNumber(t.technique.kind == TimeToTarget::Kind::NotReached
                                                                       ? NAN : t.technique.milliseconds)},
                                       {"technique_time", kKinds[int(t.technique.kind)]},
                                       {"technique_best_error", jsonNumber(t.technique.bestError)},
                                       {"raymarch_ms", jsonNumber(t.baseline.kind == TimeToTarget::Kind::NotReached
                                                                      ? NAN : t.baseline.milliseconds)},
                                       {"raymarch_time", kKinds[int(t.baseline.kind)]},
                                       {"raymarch_best_error", jsonNumber(t.baseline.bestError)},
                                       {"speedup", t.bound == TargetSpeedup::Bound::Unknown ? nlohmann::json(nullptr)
                                                                                            : jsonNumber(t.ratio)},
                                       {"speedup_bound", kBounds[int(t.bound)]},
                                       {"phrase", targetSpeedupPhrase(t)},
                                       {"technique_settings", targetSettings(rows, scene, technique, t.technique)},
                                       {"raymarch_settings", targetSettings(rows, scene, "raymarch", t.baseline)}});
                    const TargetSpeedup w = targetSpeedup(rows, scene, technique, target, "raymarch", Measure::Work);
                    targets.back()["work_ratio"] =
                        w.bound == TargetSpeedup::Bound::Unknown ? nlohmann::json(nullptr) : jsonNumber(w.ratio);
                    targets.back()["work_ratio_bound"] = kBounds[int(w.bound)];
                    targets.back()["work_phrase"] = targetSpeedupPhrase(w, "raymarch", Measure::Work);
                    const TargetSpeedup a =
                        targetSpeedup(rows, scene, technique, target, "raymarch", Measure::Time, ErrorOver::AgreeingPixels);
                    targets.back()["speedup_agreeing"] =
                        a.bound == TargetSpeedup::Bound::Unknown ? nlohmann::json(nullptr) : jsonNumber(a.ratio);
                    targets.back()["speedup_agreeing_bound"] = kBounds[int(a.bound)];
                    targets.back()["phrase_agreeing"] = targetSpeedupPhrase(a);
                }
            }
    }
    j["speedups_at_targets"] = targets;
    nlohmann::json planList = nlohmann::json::array();
    for (const PlanSaving& p : savings)
        planList.push_back({{"scene", p.scene},
                            {"technique", p.technique},
                            {"planned_ms", jsonNumber(p.plannedMilliseconds)},
                            {"forced_ms", jsonNumber(p.forcedMilliseconds)},
                            {"planned_runs_ms", p.plannedRuns},
                            {"forced_runs_ms", p.forcedRuns},
                            {"significant", savingIsSignificant(p)},
                            {"skipped", p.skipped}});
    j["plan_savings"] = planList;
    writeTextFile(path, j.dump(2) + "\n");
}

}  // namespace viz::report
