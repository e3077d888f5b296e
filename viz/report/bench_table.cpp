#include "report/bench_table.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "report/page_style.h"
#include "report/text_output.h"

namespace viz::report {

const std::vector<BenchAxis>& benchAxes() {
    static const std::vector<BenchAxis> axes = {{"size", "pixels"},
                                                {"shadow_map", "shadow-map texels"},
                                                {"vpls", "VPLs"},
                                                {"triangles", "triangles"}};
    return axes;
}

const BenchAxis* findBenchAxis(const std::string& id) {
    for (const BenchAxis& a : benchAxes())
        if (a.id == id) return &a;
    return nullptr;
}

PowerFit fitPowerLaw(const std::vector<double>& work, const std::vector<double>& milliseconds) {
    PowerFit f;
    double sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
    std::set<double> distinct;
    const std::size_t n = std::min(work.size(), milliseconds.size());
    for (std::size_t i = 0; i < n; ++i) {
        if (!(work[i] > 0.0) || !(milliseconds[i] > 0.0) || !std::isfinite(work[i]) || !std::isfinite(milliseconds[i]))
            continue;
        const double x = std::log(work[i]), y = std::log(milliseconds[i]);
        sx += x, sy += y, sxx += x * x, sxy += x * y, syy += y * y;
        distinct.insert(work[i]);
        ++f.points;
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (distinct.size() < 2) {
        f.exponent = f.coefficient = f.r2 = nan;
        return f;
    }
    const double m = f.points;
    const double vx = sxx - sx * sx / m, vy = syy - sy * sy / m, cxy = sxy - sx * sy / m;
    f.exponent = cxy / vx;
    f.coefficient = std::exp((sy - f.exponent * sx) / m);
    f.r2 = vy > 0.0 ? cxy * cxy / (vx * vy) : 1.0;
    return f;
}

std::vector<BenchFit> fitSeries(const std::vector<BenchRow>& rows) {
    using Key = std::tuple<std::string, std::string, std::string, std::string>;
    std::vector<Key> order;
    std::map<Key, std::pair<std::vector<double>, std::vector<double>>> points;
    for (const BenchRow& r : rows) {
        const Key key{r.scene, r.technique, r.axis, r.stage};
        auto [it, added] = points.try_emplace(key);
        if (added) order.push_back(key);
        it->second.first.push_back(r.work);
        it->second.second.push_back(r.milliseconds);
    }
    std::vector<BenchFit> fits;
    for (const Key& k : order) {
        const auto& [work, ms] = points[k];
        fits.push_back({std::get<0>(k), std::get<1>(k), std::get<2>(k), std::get<3>(k), fitPowerLaw(work, ms)});
    }
    return fits;
}

void writeBenchCsv(const std::string& path, const std::vector<BenchRow>& rows) {
    std::ostringstream out;
    out << "scene,technique,axis,value,stage,ms,clock,renderer,work,runs,wall_ms,ms_min,ms_max\n";
    for (const BenchRow& r : rows) {
        const std::vector<std::string> fields = {r.scene, r.technique, r.axis, r.value, r.stage,
                                                 formatFigure(r.milliseconds, "%.6g"), r.clock, r.renderer,
                                                 formatFigure(r.work, "%.10g"), std::to_string(r.runs),
                                                 formatFigure(r.wallMilliseconds, "%.6g"),
                                                 formatFigure(r.spread.minMilliseconds, "%.6g"),
                                                 formatFigure(r.spread.maxMilliseconds, "%.6g")};
        for (std::size_t i = 0; i < fields.size(); ++i) out << (i ? "," : "") << csvField(fields[i]);
        out << "\n";
    }
    writeTextFile(path, out.str());
}

namespace {

constexpr const char* kBenchStyle = "tr.total td{font-weight:bold}";

std::string cell(double v, const char* format) {
    const std::string text = formatFigure(v, format);
    return text.empty() ? "&ndash;" : text;
}

}  // namespace

void writeBenchHtml(const std::string& path, const BenchMeta& meta, const std::vector<BenchRow>& rows,
                    const std::vector<BenchFit>& fits, const std::vector<BenchPlot>& plots) {
    std::ostringstream h;
    bool noisy = false;  // some time's runs spread too far (its cell is marked)
    h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Airlight bench</title><style>" << kPageStyle << kBenchStyle
      << "</style></head><body>\n<h1>Airlight bench: how each technique's cost grows</h1>\n<p class=\"note\">"
      << escapeHtml(meta.date) << " &middot; <code>" << escapeHtml(meta.command) << "</code><br>machine: "
      << escapeHtml(meta.machine) << "<br>renderer: " << escapeHtml(meta.renderer)
      << (meta.arithmeticNote.empty() ? std::string() : "; " + escapeHtml(meta.arithmeticNote))
      << "<br>clock: " << escapeHtml(meta.clock)
      << "; every time is the median of " << meta.runs << " runs after one warm-up run"
      << (meta.quick ? " (--quick: fewer points per axis)" : "") << ".<br>" << escapeHtml(meta.fixed) << "</p>\n"
      << "<p>Each axis varies one kind of work and keeps everything else at its default. The exponent k is the slope "
         "of a least-squares line through log(ms) against log(work): cost grows about as work<sup>k</sup> over the "
         "measured range (k = 1: linear; k &lt; 1: fixed costs still dominate, or the work is not where the time "
         "goes). <em>total</em> is the sum of the stage times, <em>wall</em> the whole run including read-backs.</p>\n";
    std::vector<std::pair<std::string, std::string>> sections;  // (scene, axis) in first-seen order
    for (const BenchRow& r : rows)
        if (std::find(sections.begin(), sections.end(), std::make_pair(r.scene, r.axis)) == sections.end())
            sections.push_back({r.scene, r.axis});
    for (const auto& [scene, axisId] : sections) {
        const BenchAxis* axis = findBenchAxis(axisId);
        h << "<h2>" << escapeHtml(scene) << ": " << escapeHtml(axisId) << " (work in "
          << escapeHtml(axis ? axis->workUnit : axisId) << ")</h2>\n";
        for (const BenchPlot& p : plots)
            if (p.scene == scene && p.axis == axisId)
                h << "<figure><img src=\"" << escapeHtml(p.file) << "\" alt=\"" << escapeHtml(scene + " " + axisId + " " + p.technique)
                  << "\"><figcaption>" << escapeHtml(p.technique.empty() ? "total per technique" : p.technique + " by stage")
                  << "</figcaption></figure>\n";
        // The table: one row per technique and stage, the median ms at each value, the fitted exponent.
        std::vector<std::string> values;
        for (const BenchRow& r : rows)
            if (r.scene == scene && r.axis == axisId && std::find(values.begin(), values.end(), r.value) == values.end())
                values.push_back(r.value);
        h << "<table><tr><th class=\"l\">technique</th><th class=\"l\">stage</th>";
        for (const std::string& v : values) h << "<th>" << escapeHtml(v) << "</th>";
        h << "<th>exponent k</th><th>r&sup2;</th></tr>\n";
        for (const BenchFit& f : fits) {
            if (f.scene != scene || f.axis != axisId) continue;
            h << "<tr" << (f.stage == "total" ? " class=\"total\"" : "") << "><td class=\"l\">" << escapeHtml(f.technique)
              << "</td><td class=\"l\">" << escapeHtml(f.stage) << "</td>";
            for (const std::string& v : values) {
                std::string td = "<td>&ndash;</td>";
                for (const BenchRow& r : rows)
                    if (r.scene == scene && r.axis == axisId && r.technique == f.technique && r.stage == f.stage && r.value == v)
                        td = timeCellHtml(cell(r.milliseconds, "%.3g"), r.milliseconds, r.spread, noisy);
                h << td;
            }
            h << "<td>" << cell(f.fit.exponent, "%.2f") << "</td><td>" << cell(f.fit.r2, "%.2f") << "</td></tr>\n";
        }
        h << "</table>\n";
    }
    if (noisy) h << noisyFootnoteHtml("Measure such points again before reading an exponent from them.");
    h << "<p class=\"note\">Data: <a href=\"bench.csv\">bench.csv</a> (scene, technique, axis, value, stage, ms, clock, "
         "renderer, work, runs, wall_ms: the stage's CPU wall time from its start until its GPU time was known, far above "
         "ms where a stage works on the CPU; ms_min, ms_max: the fastest and slowest run).</p>\n</body></html>\n";
    writeTextFile(path, h.str());
}

}  // namespace viz::report
