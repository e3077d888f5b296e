// The rows of `airlight report` (one per scene x technique x setting) and the files written from them:
// results.csv, results.json and index.html. Pure CPU; the runner that fills the rows lives in the app.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <optional>
#include <string>
#include <vector>

#include "report/error_metrics.h"
#include "report/run_spread.h"
#include "report/tradeoff.h"

namespace viz::report {

struct StageTime {
    std::string stage;  // stage id, e.g. "raymarch.march"
    double milliseconds = 0.0;
};

// The row's setting rendered on every frame of its scene's motion path (`report --temporal`): the figures
// of report/temporal_error.h against the reference on the same frames, and the time per frame.
struct TemporalFigures {
    std::string path;             // the motion path, as given to --path
    int frames = 0;
    double meanFrameError = 0.0;  // mean over frames of the relative L2
    double temporalRms = 0.0;     // relative to the reference's mean
    double worstFlicker = 0.0;    // 99th percentile over pixels of the per-pixel flicker, relative
    double msPerFrame = 0.0;      // median over the frames of the sum of stage times (each frame run once)
    std::size_t excludedDifferences = 0;  // frame-to-frame differences left out (NaN or Inf)
    std::string flickerImage;     // PNG next to index.html: per-pixel temporal RMS as a heat map
};

struct ReportRow {
    std::string scene, technique;
    std::string setting;   // the sweep label, e.g. "N=64"
    std::string settings;  // the settings that differ from the defaults, "samples=64"
    int width = 0, height = 0;
    int runs = 0;          // timed runs (after one warm-up)
    std::string clock;     // how stages were timed (Timing::clock)
    std::vector<StageTime> stages;  // medians over the runs
    double totalMilliseconds = 0.0; // median over runs of the sum of stage times
    double wallMilliseconds = 0.0;  // median over runs of the whole run() call, readbacks included
    RunSpread totalSpread{};        // the fastest and slowest run's sum of stage times
    ErrorMetrics error;             // L_air against the reference's L_air
    // The scene's pixels whose rasterised and traced first hits disagree (report/first_hits.h), and the
    // relative L2 over the others: the error a technique can change.
    std::size_t firstHitDisagreements = 0;
    double relativeL2Agreeing = kUndefined;
    std::optional<double> speedup;  // over the baseline at equal error (annotateTradeoffs)
    bool pareto = false;            // on its scene's Pareto front, all techniques together
    std::string image;              // files next to index.html (PNG), empty when not written
    std::string errorImage;
    std::optional<TemporalFigures> temporal{};  // with --temporal, on the settings it measures
    // With --temporal, a row of a stabilising option's pair (Technique::stabilisingOptions): the
    // option's name, and which side of the pair (off: without it, on: with it); empty otherwise.
    std::string stabiliser{};
    bool stabiliserOn = false;
    // One counting run's work (gl/work_counters.h), summed over the stages: (counter name, count) in the
    // counters' order; empty when not counted.
    std::vector<std::pair<std::string, std::uint64_t>> work{};
    // The sum of every counter: the row's counted operations (each a texel, sample, segment, node,
    // fragment or voxel word), NaN when not counted.
    double workTotal() const;
};

// What a technique's plan saves on a scene: its cheapest sweep setting timed as planned and with
// force_features=1 (everything the plan leaves out for the scene run anyway), medians side by side.
struct PlanSaving {
    std::string scene, technique;
    double plannedMilliseconds = 0.0, forcedMilliseconds = 0.0;
    std::vector<std::string> skipped;  // the stages and features the plan leaves out ("stage x", "feature Y")
    std::vector<double> plannedRuns{}, forcedRuns{};  // every timed run of each (the medians' samples)
};

// Whether a plan saving stands out of the timing noise: the planned runs' and the forced runs' ranges
// [min, max] do not overlap. False when either side has no runs.
bool savingIsSignificant(const PlanSaving& saving);

struct ReportMeta {
    std::string date;       // ISO 8601, UTC
    std::string command;    // the command line
    std::string machine;    // host name, CPU model, core count
    std::string renderer;   // GL_RENDERER and GL_VERSION
    // gl::measureArithmeticRatio: fragment over compute time for the same arithmetic (0: not measured),
    // and gl::describeArithmeticRatio's line
    double fragmentOverCompute = 0.0;
    std::string arithmeticNote;
    int width = 0, height = 0, runs = 0;
    bool quick = false;
    std::string referenceSettings;  // the reference's settings that differ from its defaults ("" = none)
    bool temporal = false;          // --temporal: rows may carry TemporalFigures
};

// Per scene: marks the Pareto front over all techniques (time = totalMilliseconds, error = relative L2)
// and the speed-up of every row over the baseline technique's rows of the same scene.
void annotateTradeoffs(std::vector<ReportRow>& rows, const std::string& baseline = "raymarch");

// The error targets (relative L2 of L_air) at which the report's headline compares each technique with
// the baseline: 5 % and 1 %.
const std::vector<double>& errorTargets();

// A technique's speed-up over the baseline at `target` on a scene, each along its own rows' Pareto front
// (tradeoff.h: speedupAtTarget).
// Measure::Work compares counted operations (ReportRow::workTotal) instead of times: the ratio that
// carries over from one GPU to another.
// ErrorOver::AgreeingPixels reads each row's relativeL2Agreeing instead of its relative L2: the speed-up
// with the silhouette pixels that no technique can get right left out (report/first_hits.h).
enum class Measure { Time, Work };
enum class ErrorOver { AllPixels, AgreeingPixels };
TargetSpeedup targetSpeedup(const std::vector<ReportRow>& rows, const std::string& scene, const std::string& technique,
                            double target, const std::string& baseline = "raymarch", Measure measure = Measure::Time,
                            ErrorOver errorOver = ErrorOver::AllPixels);
// The rows a side's time at a target comes from (TimeToTarget::above and below, as indices into the rows of
// `series` on `scene` in their order, the order targetSpeedup reads them in): the setting labels, the one
// above the target first; one label when the time is that row's own; none when the target is not reached.
std::vector<std::string> targetSettings(const std::vector<ReportRow>& rows, const std::string& scene,
                                        const std::string& series, const TimeToTarget& t);
// They in words: "between N=16 and area_samples=8 samples=16", "at N=16", or "".
std::string targetSettingsPhrase(const std::vector<std::string>& settings);
// It in words for the headline: "5.2x faster (12.1 ms against 63 ms)", "at least 2.0x faster (...)",
// "does not reach 1 % (best 2.3 %)", "raymarch does not reach 1 % (best 1.4 %)"; with Measure::Work
// "12x less work (1.3e+06 ops against 1.6e+07 ops)".
std::string targetSpeedupPhrase(const TargetSpeedup& s, const std::string& baseline = "raymarch",
                                Measure measure = Measure::Time);

// Column names of results.csv, in order (the schema tests check against this list).
const std::vector<std::string>& csvColumns();

// Write atomically; throw InputError naming the path when the folder cannot be written.
void writeCsv(const std::string& path, const std::vector<ReportRow>& rows);
void writeJson(const std::string& path, const ReportMeta& meta, const std::vector<ReportRow>& rows,
               const std::vector<PlanSaving>& savings = {});

// The static page: headline table, per scene the plot (plotFiles[i] for scenes[i]), the rows, and for
// each technique its image, the reference image (referenceImages[i]) and the error heat map.
struct ScenePage {
    std::string scene;
    std::string plot;            // PNG file name
    std::string referenceImage;  // PNG file name
    std::string motionPath{};    // with --temporal: the scene's path, its frame count and plot
    int frames = 0;
    std::string temporalPlot{};  // PNG file name
};
void writeHtml(const std::string& path, const ReportMeta& meta, const std::vector<ReportRow>& rows,
               const std::vector<ScenePage>& scenes, const std::vector<PlanSaving>& savings = {});

}  // namespace viz::report
