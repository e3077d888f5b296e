// The measurements of `airlight bench` (cost per stage as one kind of work grows, everything else
// fixed), the power-law fit of each series (cost ~ work^k) and the files written from them: bench.csv
// and bench.html. Pure CPU; the runner that measures lives in the app (app/bench_command.cpp).
#pragma once

#include <string>
#include <vector>

#include "report/run_spread.h"

namespace viz::report {

// One axis of growth: what is varied and the unit of the work it measures.
struct BenchAxis {
    std::string id;        // "size", "shadow_map", "vpls", "triangles"
    std::string workUnit;  // "pixels", "shadow-map texels", "VPLs", "triangles"
};
const std::vector<BenchAxis>& benchAxes();
const BenchAxis* findBenchAxis(const std::string& id);

// One stage's median time at one point of one axis. Stage "total" is the median of the per-run sums of
// the stages, "wall" the median steady-clock time of the whole run() (readbacks and CPU work included).
struct BenchRow {
    std::string scene, technique, axis;
    std::string value;  // the axis value as the user sets it: "640x480", "2048", "64", "10"
    double work = 0.0;  // in the axis's unit: pixels, texels, VPLs, triangles
    std::string stage;
    double milliseconds = 0.0;
    std::string clock, renderer;
    int runs = 0;
    // Median CPU wall time of the stage, from its start until its GPU time was known: far above `milliseconds`
    // where the stage does CPU work the GPU clock does not see (StageTiming::wallMilliseconds).
    double wallMilliseconds = 0.0;
    // The fastest and slowest of the runs behind `milliseconds` (for "wall", behind the wall time).
    RunSpread spread{};
};

// Least-squares fit of log(ms) = log(c) + k log(work) over the points with positive work and time.
struct PowerFit {
    double exponent = 0.0;     // k
    double coefficient = 0.0;  // c, ms at work = 1
    double r2 = 0.0;           // of the log-log fit; 1 when the points lie on a line
    int points = 0;            // used; the fit needs 2 distinct work values, else exponent is NaN
};
PowerFit fitPowerLaw(const std::vector<double>& work, const std::vector<double>& milliseconds);

// The fit of every (scene, technique, axis, stage) series in `rows`, in first-seen order.
struct BenchFit {
    std::string scene, technique, axis, stage;
    PowerFit fit;
};
std::vector<BenchFit> fitSeries(const std::vector<BenchRow>& rows);

struct BenchMeta {
    std::string date, command, machine, renderer, clock;
    std::string arithmeticNote;  // gl::describeArithmeticRatio's line ("": not measured)
    int runs = 0;
    bool quick = false;
    std::string fixed;  // what stayed fixed, in words
};

// A plot next to bench.html: one per (scene, axis) with the techniques' totals, one per (scene, axis,
// technique) with its stages.
struct BenchPlot {
    std::string scene, axis, technique;  // technique empty: the totals of every technique
    std::string file;
};

// Columns: scene,technique,axis,value,stage,ms,clock,renderer,work,runs,wall_ms,ms_min,ms_max.
// The page marks a time whose runs spread by more than kNoisySpread of it (report/run_spread.h).
void writeBenchCsv(const std::string& path, const std::vector<BenchRow>& rows);
void writeBenchHtml(const std::string& path, const BenchMeta& meta, const std::vector<BenchRow>& rows,
                    const std::vector<BenchFit>& fits, const std::vector<BenchPlot>& plots);

}  // namespace viz::report
