#include "report/temporal_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "report/error_metrics.h"
#include "report/text_output.h"

namespace viz::report {

namespace {

std::string figure(double v, const char* format = "%.3g") {
    const std::string text = formatFigure(v, format);
    return text.empty() ? "&ndash;" : text;
}

// Ranks 1.. by ascending `key`; NaN keys after every finite one; ties keep the order given.
template <typename Key, typename Set>
void assignRanks(std::vector<TechniqueRank>& ranks, Key key, Set set) {
    std::vector<std::size_t> order(ranks.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        const double ka = key(ranks[a]), kb = key(ranks[b]);
        if (std::isfinite(ka) != std::isfinite(kb)) return std::isfinite(ka);
        return std::isfinite(ka) && ka < kb;
    });
    for (std::size_t k = 0; k < order.size(); ++k) set(ranks[order[k]], int(k) + 1);
}

}  // namespace

std::vector<TechniqueRank> rankTechniques(const std::vector<ReportRow>& rows, const std::string& scene) {
    std::vector<TechniqueRank> ranks;
    std::map<std::string, std::size_t> index;
    for (const ReportRow& r : rows) {
        if (r.scene != scene) continue;
        auto [it, added] = index.emplace(r.technique, ranks.size());
        if (added) ranks.push_back({r.technique, kUndefined, "", kUndefined, "", kUndefined, "", kUndefined, 0, 0, 0});
        TechniqueRank& t = ranks[it->second];
        const double e = r.error.relativeL2;
        if (std::isfinite(e) && !(t.bestError <= e)) t.bestError = e, t.bestErrorSetting = r.setting;
        if (std::isfinite(r.totalMilliseconds) && !(t.fastestMs <= r.totalMilliseconds))
            t.fastestMs = r.totalMilliseconds, t.fastestSetting = r.setting;
        if (r.temporal && std::isfinite(r.temporal->temporalRms) && !(t.mostStable <= r.temporal->temporalRms)) {
            t.mostStable = r.temporal->temporalRms;
            t.mostStableSetting = r.setting;
            t.mostStableFlicker = r.temporal->worstFlicker;
        }
    }
    assignRanks(ranks, [](const TechniqueRank& t) { return t.bestError; }, [](TechniqueRank& t, int k) { t.errorRank = k; });
    assignRanks(ranks, [](const TechniqueRank& t) { return t.fastestMs; }, [](TechniqueRank& t, int k) { t.timeRank = k; });
    const bool anyTemporal = std::any_of(ranks.begin(), ranks.end(), [](const TechniqueRank& t) { return std::isfinite(t.mostStable); });
    if (anyTemporal)
        assignRanks(ranks, [](const TechniqueRank& t) { return t.mostStable; },
                    [](TechniqueRank& t, int k) { t.stabilityRank = std::isfinite(t.mostStable) ? k : 0; });
    return ranks;
}

void appendRankingHtml(std::ostringstream& h, const std::vector<ReportRow>& rows, const std::vector<ScenePage>& scenes) {
    h << "<h2>Ranking: error, time and temporal stability</h2>\n<p class=\"note\">Per scene, each technique "
         "ranked by its lowest relative L2 over its settings, by its fastest setting, and (with "
         "<code>--temporal</code>) by its lowest temporal RMS along the scene's motion path; 1 is best, the setting "
         "that earns each rank in brackets. Rows in order of stability when it was measured, else of error.</p>\n";
    for (const ScenePage& s : scenes) {
        std::vector<TechniqueRank> ranks = rankTechniques(rows, s.scene);
        const bool temporal = std::any_of(ranks.begin(), ranks.end(), [](const TechniqueRank& t) { return t.stabilityRank > 0; });
        std::stable_sort(ranks.begin(), ranks.end(), [&](const TechniqueRank& a, const TechniqueRank& b) {
            if (!temporal) return a.errorRank < b.errorRank;
            const int ka = a.stabilityRank ? a.stabilityRank : 1 << 20, kb = b.stabilityRank ? b.stabilityRank : 1 << 20;
            return ka < kb;
        });
        h << "<h3>" << escapeHtml(s.scene) << "</h3>\n<table><tr><th class=\"l\">technique</th>";
        if (temporal) h << "<th>stability</th><th>temporal RMS</th><th>worst flicker</th>";
        h << "<th>error</th><th>rel. L2</th><th>time</th><th>ms</th></tr>\n";
        for (const TechniqueRank& t : ranks) {
            h << "<tr><td class=\"l\">" << escapeHtml(t.technique) << "</td>";
            if (temporal)
                h << "<td>" << (t.stabilityRank ? std::to_string(t.stabilityRank) : "&ndash;") << "</td><td>"
                  << figure(t.mostStable) << " <span class=\"note\">(" << escapeHtml(t.mostStableSetting)
                  << ")</span></td><td>" << figure(t.mostStableFlicker) << "</td>";
            h << "<td>" << t.errorRank << "</td><td>" << figure(t.bestError) << " <span class=\"note\">("
              << escapeHtml(t.bestErrorSetting) << ")</span></td><td>" << t.timeRank << "</td><td>"
              << figure(t.fastestMs, "%.1f") << " <span class=\"note\">(" << escapeHtml(t.fastestSetting)
              << ")</span></td></tr>\n";
        }
        h << "</table>\n";
    }
}

std::vector<StabiliserPair> stabiliserPairs(const std::vector<ReportRow>& rows, const std::string& scene) {
    std::vector<StabiliserPair> pairs;
    for (const ReportRow& r : rows) {
        if (r.scene != scene || r.stabiliser.empty() || !r.temporal) continue;
        auto it = std::find_if(pairs.begin(), pairs.end(), [&](const StabiliserPair& p) {
            return p.technique == r.technique && p.option == r.stabiliser;
        });
        if (it == pairs.end()) it = pairs.insert(pairs.end(), {r.technique, r.stabiliser});
        (r.stabiliserOn ? it->on : it->off) = &r;
    }
    std::erase_if(pairs, [](const StabiliserPair& p) { return !p.off || !p.on; });
    return pairs;
}

namespace {

// "3.24x lower", "1.10x higher", "unchanged" for a figure going from `without` to `with`.
std::string changeWords(double without, double with) {
    if (!std::isfinite(without) || !std::isfinite(with)) return "not comparable";
    if (without == with) return "unchanged";
    char text[64];
    if (with < without) {
        if (with <= 0.0) return "down to 0";
        std::snprintf(text, sizeof text, "%.3gx lower", without / with);
    } else {
        if (without <= 0.0) return "up from 0";
        std::snprintf(text, sizeof text, "%.3gx higher", with / without);
    }
    return text;
}

}  // namespace

std::string stabiliserLine(const StabiliserPair& p) {
    const TemporalFigures& a = *p.off->temporal;
    const TemporalFigures& b = *p.on->temporal;
    char text[256];
    std::snprintf(text, sizeof text, "temporal RMS %.3g -> %.3g (%s), frame error %.3g -> %.3g, %.1f -> %.1f ms per frame",
                  a.temporalRms, b.temporalRms, changeWords(a.temporalRms, b.temporalRms).c_str(), a.meanFrameError,
                  b.meanFrameError, a.msPerFrame, b.msPerFrame);
    return p.technique + " " + p.option + ": " + text;
}

void appendTemporalHtml(std::ostringstream& h, const std::vector<ReportRow>& rows, const ScenePage& s) {
    const bool any = std::any_of(rows.begin(), rows.end(), [&](const ReportRow& r) { return r.scene == s.scene && r.temporal; });
    if (!any) return;
    h << "<h3>Temporal error along " << escapeHtml(s.motionPath) << " (" << s.frames << " frames)</h3>\n";
    h << "<table><tr><th class=\"l\">technique</th><th class=\"l\">setting</th><th>mean frame error</th>"
         "<th>temporal RMS</th><th>worst flicker (p99)</th><th>ms per frame</th><th>differences left out</th></tr>\n";
    for (const ReportRow& r : rows) {
        if (r.scene != s.scene || !r.temporal) continue;
        const TemporalFigures& t = *r.temporal;
        h << "<tr><td class=\"l\">" << escapeHtml(r.technique) << "</td><td class=\"l\">" << escapeHtml(r.setting)
          << "</td><td>" << figure(t.meanFrameError) << "</td><td>" << figure(t.temporalRms) << "</td><td>"
          << figure(t.worstFlicker) << "</td><td>" << figure(t.msPerFrame, "%.1f") << "</td><td"
          << (t.excludedDifferences ? " class=\"bad\"" : "") << ">" << t.excludedDifferences << "</td></tr>\n";
    }
    h << "</table>\n";
    for (const ReportRow& r : rows) {
        if (r.scene != s.scene || !r.temporal || r.temporal->flickerImage.empty()) continue;
        h << "<figure><img src=\"" << escapeHtml(r.temporal->flickerImage) << "\" alt=\"flicker of "
          << escapeHtml(r.technique) << "\"><figcaption>flicker, " << escapeHtml(r.technique) << " "
          << escapeHtml(r.setting) << "</figcaption></figure>\n";
    }
    const std::vector<StabiliserPair> pairs = stabiliserPairs(rows, s.scene);
    if (!pairs.empty()) {
        h << "<h4>Stabilising options</h4>\n<table><tr><th class=\"l\">technique</th><th class=\"l\">option</th>"
             "<th class=\"l\">without it</th><th>temporal RMS without &rarr; with</th><th>worst flicker</th>"
             "<th>mean frame error</th><th>ms per frame</th></tr>\n";
        for (const StabiliserPair& p : pairs) {
            const TemporalFigures& a = *p.off->temporal;
            const TemporalFigures& b = *p.on->temporal;
            h << "<tr><td class=\"l\">" << escapeHtml(p.technique) << "</td><td class=\"l\">" << escapeHtml(p.option)
              << "</td><td class=\"l\">" << escapeHtml(p.off->setting) << "</td><td>" << figure(a.temporalRms)
              << " &rarr; " << figure(b.temporalRms) << " (" << changeWords(a.temporalRms, b.temporalRms) << ")</td><td>"
              << figure(a.worstFlicker) << " &rarr; " << figure(b.worstFlicker) << "</td><td>"
              << figure(a.meanFrameError) << " &rarr; " << figure(b.meanFrameError) << "</td><td>"
              << figure(a.msPerFrame, "%.1f") << " &rarr; " << figure(b.msPerFrame, "%.1f") << "</td></tr>\n";
        }
        h << "</table>\n<p class=\"note\">Each option measured as a pair of settings that differ in it alone, on the "
             "same frames against the same reference frames; its rows are also in the temporal table above.</p>\n";
    }
    h << "<p class=\"note\">Temporal RMS: the RMS over pixels, channels and frames of the frame-to-frame change of "
         "the error (technique &minus; reference), halved, over the reference's mean; worst flicker: the 99th "
         "percentile over pixels of each pixel's own such RMS. A wrong but stable technique scores 0. Flicker maps: "
         "per-pixel temporal RMS on the error maps' scale (yellow at 0.1 of the reference's 99.5th percentile); "
         "magenta where a pixel had no finite difference.</p>\n";
}

}  // namespace viz::report
