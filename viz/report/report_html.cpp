// index.html of `airlight report`: static HTML, inline CSS, no scripts, every resource a file next to it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "report/page_style.h"
#include "report/report_table.h"
#include "report/temporal_report.h"
#include "report/text_output.h"

namespace viz::report {

namespace {

// The plan's saving in percent; a planned run that measured slower than the forced one saved nothing,
// and the page says so instead of printing a negative saving.
// A difference inside the noise (the two sets of runs overlap) is said to be one.
std::string savedCell(const PlanSaving& p) {
    const double saved = 100.0 * (1.0 - p.plannedMilliseconds / p.forcedMilliseconds);
    if (!std::isfinite(saved)) return "&ndash;";
    const bool significant = savingIsSignificant(p);
    if (!significant && !p.plannedRuns.empty())
        return "not significant <span class=\"note\">(" + formatFigure(saved, "%+.0f") +
               " %; the planned and forced runs' ranges overlap)</span>";
    if (saved >= 0.0) return formatFigure(saved, "%.0f") + " %";
    return "none <span class=\"note\">(planned " + formatFigure(-saved, "%.0f") +
           " % slower: the plan costs more)</span>";
}

// A figure for a table cell: a dash when undefined.
std::string figure(double v, const char* format = "%.3g") {
    const std::string text = formatFigure(v, format);
    return text.empty() ? "&ndash;" : text;
}

// One row per scene and error target, one column per technique but the baseline: its time (or work)
// against raymarch's at the target, in words.
void appendTargetTable(std::ostringstream& h, const std::string& title, const std::vector<ReportRow>& rows,
                       const std::vector<ScenePage>& scenes, const std::vector<std::string>& techniques,
                       Measure measure, ErrorOver errorOver = ErrorOver::AllPixels) {
    h << "<h2>" << escapeHtml(title) << "</h2>\n<table><tr><th class=\"l\">scene</th><th>error target</th>";
    for (const std::string& t : techniques)
        if (t != "raymarch") h << "<th>" << escapeHtml(t) << "</th>";
    h << "</tr>\n";
    for (const ScenePage& s : scenes)
        for (double target : errorTargets()) {
            // Under the target, the raymarch settings its time lies between (the same for every column);
            // under each figure, the technique's.
            auto settingsLine = [&](const std::string& series, const TimeToTarget& side, const std::string& prefix) {
                const std::string p = targetSettingsPhrase(targetSettings(rows, s.scene, series, side));
                return p.empty() ? std::string() : "<br><span class=\"note\">" + escapeHtml(prefix + p) + "</span>";
            };
            std::vector<std::pair<std::string, TargetSpeedup>> row;  // every column shares raymarch's side
            for (const std::string& t : techniques)
                if (t != "raymarch") row.push_back({t, targetSpeedup(rows, s.scene, t, target, "raymarch", measure, errorOver)});
            h << "<tr><td class=\"l\">" << escapeHtml(s.scene) << "</td><td>" << figure(100.0 * target) << " %"
              << (row.empty() ? std::string() : settingsLine("raymarch", row.front().second.baseline, "raymarch "))
              << "</td>";
            for (const auto& [t, ts] : row)
                h << "<td" << (ts.bound != TargetSpeedup::Bound::Unknown ? "" : " class=\"note\"") << ">"
                  << escapeHtml(targetSpeedupPhrase(ts, "raymarch", measure)) << settingsLine(t, ts.technique, "")
                  << "</td>";
            h << "</tr>\n";
        }
    h << "</table>\n";
}

// The first row of `scene`, which carries the scene's figures every row of it repeats (the image size, the
// silhouette pixels' count); null when the scene has no row.
const ReportRow* firstRowOf(const std::vector<ReportRow>& rows, const std::string& scene) {
    const auto it = std::find_if(rows.begin(), rows.end(), [&](const ReportRow& r) { return r.scene == scene; });
    return it == rows.end() ? nullptr : &*it;
}

// Under a scene's table: how many of its pixels the rasteriser and the reference's traced ray see a
// different first surface in (report/first_hits.h), and what that means for the errors above.
void appendFirstHitNote(std::ostringstream& h, const std::vector<ReportRow>& rows, const std::string& scene) {
    const ReportRow* first = firstRowOf(rows, scene);
    if (!first) return;
    const double pixels = double(first->width) * double(first->height);
    const std::size_t n = first->firstHitDisagreements;
    h << "<p class=\"note\">";
    if (n == 0) {
        h << "The rasterised first hit agrees with the reference's traced ray on every pixel, so both error "
             "columns are the same figure.";
    } else {
        h << n << (n == 1 ? " pixel" : " pixels") << " of " << std::size_t(pixels) << " ("
          << figure(100.0 * double(n) / pixels, "%.2g") << " %) " << (n == 1 ? "sees" : "see")
          << " a different first surface rasterised than along the reference's traced ray (more than 0.1 % "
             "apart): silhouettes, where a pixel's centre lies within the rasteriser's snapping of an edge. Every "
             "technique here finds its surfaces by rasterising, so each integrates the air over the wrong span "
             "there whatever it does; <em>rel. L2, agreeing px</em> leaves those pixels out. Their share shrinks "
             "as the image grows.";
    }
    h << "</p>\n";
}

constexpr const char* kReportStyle = "body{max-width:72em}tr.front td{font-weight:bold}figure img{image-rendering:pixelated}";

}  // namespace

void writeHtml(const std::string& path, const ReportMeta& meta, const std::vector<ReportRow>& rows,
               const std::vector<ScenePage>& scenes, const std::vector<PlanSaving>& savings) {
    std::set<std::string> techniqueSet;
    std::vector<std::string> techniques;
    for (const ReportRow& r : rows)
        if (techniqueSet.insert(r.technique).second) techniques.push_back(r.technique);

    std::ostringstream h;
    h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Airlight report</title><style>"
      << kPageStyle << kReportStyle << "</style></head><body>\n<h1>Airlight report: error against run time</h1>\n";
    h << "<p class=\"note\">" << escapeHtml(meta.date) << " &middot; " << escapeHtml(meta.machine) << " &middot; "
      << escapeHtml(meta.renderer) << " &middot; " << meta.width << "&times;" << meta.height << " &middot; median of "
      << meta.runs << " runs after one warm-up" << (meta.quick ? " &middot; quick sweep" : "")
      << (meta.referenceSettings.empty() ? std::string() : " &middot; reference with " + escapeHtml(meta.referenceSettings))
      << (meta.arithmeticNote.empty() ? std::string() : "<br>Renderer: " + escapeHtml(meta.arithmeticNote) + ".")
      << "<br><code>"
      << escapeHtml(meta.command) << "</code></p>\n";
    h << "<p class=\"note\">Error: L_air against the reference (Embree ray tracing and adaptive quadrature, cached). "
         "Relative L2 = ||t&minus;r||/||r|| over all pixels and channels; p99.9 = 99.9th percentile of the per-pixel "
         "relative error (floor 1% of the mean); PSNR on the tone map v&middot;k/(1+v&middot;k), k = 0.18 / mean of "
         "the reference, peak 1. Time: sum of the technique's stage times (the clock each row names). Speed-up: "
         "brute-force <code>raymarch</code>'s time at the same relative L2 (log-log interpolation along its sweep, "
         "no extrapolation) divided by the row's time. Bold rows lie on the scene's Pareto front. Every figure but "
         "<em>rel. L2, agreeing px</em> counts every pixel, silhouette pixels included (see under each scene's "
         "table).</p>\n";

    // Headline: per scene and error target, each technique's speed-up over raymarch, both interpolated
    // along their own Pareto fronts.
    appendTargetTable(h, "Speed-up over brute-force ray marching at equal error", rows, scenes, techniques,
                      Measure::Time);
    h << "<p class=\"note\">Each side's time to reach the target is interpolated linearly in log(time) "
         "against log(error) between the two points of its own Pareto front (its sweep settings that no faster "
         "setting beats) that bracket the target; no extrapolation. Under each figure, the settings it lies between "
         "(or the one it is), and under each target raymarch's: where the two differ in more than one knob, the line "
         "between them is a guess at how the knobs trade, and a setting the sweep did not measure may reach the "
         "target sooner. &ldquo;or "
         "less&rdquo;: even the cheapest setting "
         "is below the target, so its time only bounds the true one, and the speed-up is a bound (at least / at "
         "most). The per-row speed-ups in the tables below compare at each row's own error instead.";
    std::vector<ScenePage> withSilhouettes;  // scenes with pixels whose first hits disagree
    std::string names;
    for (const ScenePage& p : scenes) {
        const ReportRow* r = firstRowOf(rows, p.scene);
        if (r && r->firstHitDisagreements > 0) {
            withSilhouettes.push_back(p);
            names += (names.empty() ? "" : ", ") + escapeHtml(p.scene);
        }
    }
    if (!withSilhouettes.empty())
        h << " The errors here count every pixel. On " << names << ", silhouette pixels (see under the "
          << "scene's table) lift every technique's error alike, raymarch's too; the next table leaves them out.";
    h << "</p>\n";
    if (!withSilhouettes.empty()) {
        appendTargetTable(h, "The same over the pixels whose first hit agrees", rows, withSilhouettes, techniques,
                          Measure::Time, ErrorOver::AgreeingPixels);
        h << "<p class=\"note\">As above, each row's error taken over the pixels where the rasterised first "
             "surface and the reference's traced one agree (<em>rel. L2, agreeing px</em>): the error a "
             "technique's settings can lower.</p>\n";
    }

    // The same comparison in counted operations (one counting run per setting): what carries over to a GPU.
    if (std::any_of(rows.begin(), rows.end(), [](const ReportRow& r) { return !r.work.empty(); })) {
        appendTargetTable(h, "Work against brute-force ray marching at equal error", rows, scenes, techniques,
                          Measure::Work);
        h << "<p class=\"note\">Work: one run of each setting with every shader counting what it does "
             "(shadow-map lookups and texels, ray samples, closed-form segments and their quadrature nodes, tree "
             "nodes, fragments, voxel words; <code>airlight render --count-work</code>), summed into counted "
             "operations, each about one memory read or one integrand evaluation. These counts do not depend on "
             "the GPU or its driver; how long an operation takes does. Interpolated along each side's Pareto front "
             "in work as above.</p>\n";
    }

    appendRankingHtml(h, rows, scenes);

    if (!savings.empty()) {
        h << "<h2>What each plan leaves out, and what that saves</h2>\n<p class=\"note\">The technique's cheapest sweep "
             "setting, timed as planned and with <code>force_features=1</code> (everything the plan leaves out for the scene runs "
             "anyway; the image is the same), medians of runs alternated in pairs between the two (each side its own instance of the technique, warmed up once, so that neither recompiles and a slow spell of the machine falls on both). A saving is called significant only when every planned run is faster than every forced one (or slower: then the plan costs more).</p>\n<table><tr><th class=\"l\">"
             "scene</th><th class=\"l\">technique</th><th>planned ms</th><th>forced ms</th><th>saved</th><th "
             "class=\"l\">left out</th></tr>\n";
        for (const PlanSaving& p : savings) {
            std::string skipped;
            for (const std::string& k : p.skipped) skipped += (skipped.empty() ? "" : ", ") + k;
            h << "<tr><td class=\"l\">" << escapeHtml(p.scene) << "</td><td class=\"l\">" << escapeHtml(p.technique)
              << "</td><td>" << figure(p.plannedMilliseconds, "%.1f") << "</td><td>"
              << figure(p.forcedMilliseconds, "%.1f") << "</td><td>"
              << savedCell(p) << "</td><td class=\"l\">"
              << escapeHtml(skipped.empty() ? "nothing" : skipped) << "</td></tr>\n";
        }
        h << "</table>\n";
    }

    for (const ScenePage& s : scenes) {
        bool noisy = false;  // some row's timed runs spread too far (its time is marked)
        h << "<h2 id=\"" << escapeHtml(s.scene) << "\">" << escapeHtml(s.scene) << "</h2>\n";
        if (!s.plot.empty())
            h << "<figure><img src=\"" << escapeHtml(s.plot) << "\" alt=\"error against time, " << escapeHtml(s.scene)
              << "\"><figcaption>relative L2 error against time per frame (log-log)</figcaption></figure>\n";
        if (!s.temporalPlot.empty())
            h << "<figure><img src=\"" << escapeHtml(s.temporalPlot) << "\" alt=\"temporal error against time, "
              << escapeHtml(s.scene) << "\"><figcaption>temporal RMS along " << escapeHtml(s.motionPath)
              << " against time per frame (log-log)</figcaption></figure>\n";
        h << "<table><tr><th class=\"l\">technique</th><th class=\"l\">setting</th><th>time ms</th><th>wall ms</th>"
             "<th>rel. L2</th><th>rel. L2, agreeing px</th><th>RMSE</th><th>max abs</th><th>p99.9 rel.</th>"
             "<th>PSNR dB</th><th>NaN/Inf/neg px</th><th>speed-up</th><th>work ops</th></tr>\n";
        for (const ReportRow& r : rows) {
            if (r.scene != s.scene) continue;
            const std::size_t bad = r.error.nanPixels + r.error.infPixels + r.error.negativePixels;
            h << "<tr" << (r.pareto ? " class=\"front\"" : "") << "><td class=\"l\">" << escapeHtml(r.technique)
              << "</td><td class=\"l\">" << escapeHtml(r.setting) << "</td>"
              << timeCellHtml(figure(r.totalMilliseconds, "%.1f"), r.totalMilliseconds, r.totalSpread, noisy)
              << "<td>" << figure(r.wallMilliseconds, "%.1f") << "</td><td>" << figure(r.error.relativeL2)
              << "</td><td>" << figure(r.relativeL2Agreeing) << "</td><td>" << figure(r.error.rmse) << "</td><td>"
              << figure(r.error.maxAbsolute) << "</td><td>"
              << figure(r.error.relativeP999) << "</td><td>" << figure(r.error.psnr, "%.1f") << "</td><td"
              << (bad ? " class=\"bad\"" : "") << ">" << r.error.nanPixels << "/" << r.error.infPixels << "/"
              << r.error.negativePixels << "</td><td>" << (r.speedup ? escapeHtml(speedupPhrase(*r.speedup)) : "&ndash;")
              << "</td><td>" << figure(r.workTotal(), "%.3g") << "</td></tr>\n";
        }
        h << "</table>\n";
        appendFirstHitNote(h, rows, s.scene);
        if (noisy) h << noisyFootnoteHtml("Speed-ups that rest on such a time are in doubt: measure again.");
        appendTemporalHtml(h, rows, s);
        if (!s.referenceImage.empty())
            h << "<figure><img src=\"" << escapeHtml(s.referenceImage) << "\" alt=\"reference\"><figcaption>reference"
              << "</figcaption></figure>\n";
        for (const ReportRow& r : rows) {
            if (r.scene != s.scene || r.image.empty()) continue;
            h << "<figure><img src=\"" << escapeHtml(r.image) << "\" alt=\"" << escapeHtml(r.technique) << "\"><figcaption>"
              << escapeHtml(r.technique) << " " << escapeHtml(r.setting) << "</figcaption></figure>\n";
            if (!r.errorImage.empty())
                h << "<figure><img src=\"" << escapeHtml(r.errorImage) << "\" alt=\"error of " << escapeHtml(r.technique)
                  << "\"><figcaption>|error|, " << escapeHtml(r.technique) << "</figcaption></figure>\n";
        }
    }
    h << "<p class=\"note\">Images: L_air at the reference's exposure (99.5th percentile to white). Error heat maps: "
         "sum over channels of |t&minus;r| divided by the reference's 99.5th percentile, black 0 to yellow 0.1 and "
         "above; NaN/Inf pixels magenta.</p>\n</body></html>\n";
    writeTextFile(path, h.str());
}

}  // namespace viz::report
