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

// The summary's ranking section (every scene) and a scene's temporal section (nothing when no row of
// the scene has temporal figures), written into index.html by writeHtml.
void appendRankingHtml(std::ostringstream& h, const std::vector<ReportRow>& rows, const std::vector<ScenePage>& scenes);
void appendTemporalHtml(std::ostringstream& h, const std::vector<ReportRow>& rows, const ScenePage& scene);

}  // namespace viz::report
