// Running one technique on one stiff case and judging it: finite output everywhere (no NaN, Inf or
// negative pixel) and an error against the reference within the bound the technique declares for the
// case's class (Technique::stiffBound), or a clear refusal where it declares none.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/image.h"
#include "debug/technique.h"
#include "report/error_metrics.h"
#include "scene/stiff_scenes.h"

namespace viz::report {

struct StiffOutcome {
    std::string caseId, caseClass, technique;
    bool ran = false;              // false: the technique refused (InputError) with `refusal`
    std::string refusal;
    ErrorMetrics error;            // L_air against the reference, excluded pixels left out of the figures
    std::optional<StiffBound> bound;
    bool passed = false;
    std::string verdict;           // one line: why it passed or failed
    double milliseconds = 0.0;     // the technique's stage times, summed
};

// Runs `technique` (GL context current if it needs one) at its stiffSettings() on the case's scene and
// compares its L_air with `reference` (the reference technique's L_air for the same scene and size).
StiffOutcome runStiffCase(Technique& technique, const scene::StiffCase& c, const scene::Scene& scene, const Image& reference);

// The pixels whose error figures a case leaves out (1 = excluded), width x height, one channel.
Image stiffExclusionMask(const scene::StiffCase& c, const scene::Scene& scene);

}  // namespace viz::report

namespace viz::report {

struct ReportMeta;

// stiff.csv (one row per case x technique) and stiff.html (cases x techniques: pass/fail and figures),
// written atomically into `folder`.
void writeStiffFiles(const std::string& folder, const ReportMeta& meta, const std::vector<StiffOutcome>& outcomes);

}  // namespace viz::report
