// `airlight report --temporal` on the page: per scene the temporal table (each measured setting's mean
// per-frame error, temporal RMS, worst flicker and time per frame) with the flicker heat maps, and the
// summary's ranking of techniques by error, time and temporal stability. Pure CPU, like report_table.h.
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "report/report_table.h"

namespace viz::report {

// One series (a technique, or "T (paper)") of one scene, ranked three ways. Ranks start at 1; a series
// without a finite error ranks after every series with one; `stabilityRank` is 0 for a series none of
// whose rows has a finite temporal RMS (not measured along the path).
struct TechniqueRank {
    std::string technique;
    double bestError = 0.0;          // lowest finite relative L2 over the series' rows (NaN if none)
    std::string bestErrorSetting;
    double fastestMs = 0.0;          // lowest time per frame over its rows
    std::string fastestSetting;
    double mostStable = 0.0;         // lowest temporal RMS over its rows with temporal figures (NaN if none)
    std::string mostStableSetting;
    double mostStableFlicker = 0.0;  // that row's worst flicker
    int errorRank = 0, timeRank = 0, stabilityRank = 0;
};

// The series of `scene` in the order they first appear in `rows`, each with its three ranks (ties share
// the order of appearance).
std::vector<TechniqueRank> rankTechniques(const std::vector<ReportRow>& rows, const std::string& scene);

// A stabilising option measured on a scene: the rows without and with it (both with temporal figures).
struct StabiliserPair {
    std::string technique, option;
    const ReportRow* off = nullptr;
    const ReportRow* on = nullptr;
};
// The pairs of `scene` in the order they appear in `rows`; an option with a side missing or without
// temporal figures is left out.
std::vector<StabiliserPair> stabiliserPairs(const std::vector<ReportRow>& rows, const std::string& scene);
// "slices plane_grid=world: temporal RMS 1.33 -> 0.41 (3.24x lower), frame error 0.301 -> 0.310, 12.0 ->
// 11.5 ms per frame": what the option buys, for the terminal.
std::string stabiliserLine(const StabiliserPair& pair);

// The summary's ranking section (every scene) and a scene's temporal section (nothing when no row of
// the scene has temporal figures), written into index.html by writeHtml.
void appendRankingHtml(std::ostringstream& h, const std::vector<ReportRow>& rows, const std::vector<ScenePage>& scenes);
void appendTemporalHtml(std::ostringstream& h, const std::vector<ReportRow>& rows, const ScenePage& scene);

}  // namespace viz::report
