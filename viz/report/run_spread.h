// The spread of a measurement's timed runs. The report and the bench quote the median of N runs; beside
// it they keep the fastest and the slowest run, so that a reader can tell a machine's cost from a busy
// moment (another process, a clock that changed mid-measurement) and see when the median itself is in
// doubt.
#pragma once

#include <limits>
#include <string>
#include <vector>

namespace viz::report {

struct RunSpread {
    double minMilliseconds = std::numeric_limits<double>::quiet_NaN();  // the fastest timed run
    double maxMilliseconds = std::numeric_limits<double>::quiet_NaN();  // the slowest; NaN: not measured
};

// The smallest and largest of `runs` (NaN, NaN for none).
RunSpread spreadOf(const std::vector<double>& runs);

// (max - min) / median: how far apart the fastest and slowest runs are, as a fraction of the median. NaN
// when the spread was not measured or the median is not positive.
double spreadFraction(double median, const RunSpread& spread);

// Runs further apart than this fraction of their median mark the time as noisy. On a quiet 2-core
// machine with llvmpipe, 3 runs of one setting lie within a few per cent of each other; a spread of a
// fifth means something else was running, or the clock moved, during the measurement.
constexpr double kNoisySpread = 0.2;
bool isNoisy(double median, const RunSpread& spread);

// "runs 2351 to 4620 ms, 92 % of the median" (for a tooltip or a terminal note); "" when not measured.
std::string spreadText(double median, const RunSpread& spread);

// How the pages show it. A table cell (<td>) holding `text`, a time of `median` ms: when its runs spread too
// far, marked with a dagger, the runs in its title and class "noisy", and `noisy` set.
std::string timeCellHtml(const std::string& text, double median, const RunSpread& spread, bool& noisy);
// The paragraph under a table whose times are marked; `advice` ends it ("Measure them again.").
std::string noisyFootnoteHtml(const std::string& advice);

// One measured time and what it is ("grate raymarch N=64").
struct TimedPoint {
    std::string name;
    double median = 0.0;
    RunSpread spread{};
};
// The terminal's note when some of `points` are noisy: "note: the timed runs of 3 of 40 PLURAL spread by
// more than 20 % of their median (widest: NAME, runs ...); ..."; "" when none is.
std::string noisyRunsNote(const std::vector<TimedPoint>& points, const std::string& plural);

}  // namespace viz::report
