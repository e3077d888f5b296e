// Error against run time: the Pareto front of a set of (time, error) points and the speed-up of a
// technique over the brute-force baseline at equal error, the figure the papers report.
#pragma once

#include <optional>
#include <limits>
#include <vector>

namespace viz::report {

struct TradeoffPoint {
    double milliseconds = 0.0;
    double error = 0.0;  // relative L2 against the reference
};

// Indices of the points no other point beats in both time and error (ties keep the first), sorted by
// time. Points with a non-finite or non-positive coordinate are never on the front.
std::vector<int> paretoFront(const std::vector<TradeoffPoint>& points);

// The baseline's time at `error`, interpolated linearly in log(time) against log(error) between the two
// points of the baseline's Pareto front that bracket it (timeToReach, below, when it is Interpolated).
// Empty when `error` lies outside the front's error range (no extrapolation) or the front is empty.
std::optional<double> baselineTimeAtError(const std::vector<TradeoffPoint>& baseline, double error);

// baselineTimeAtError(error of p) / time of p, or empty as above.
std::optional<double> speedupAtEqualError(const std::vector<TradeoffPoint>& baseline, const TradeoffPoint& p);

// The time a series of settings needs to reach the relative L2 `target`, along its own Pareto front.
struct TimeToTarget {
    enum class Kind {
        Interpolated,  // log(time) linear in log(error) between the two front points that bracket the target
                       // (exact on a front point)
        AtMost,        // even the cheapest setting is below the target: its time bounds the true one
        NotReached,    // no setting reaches the target
    };
    Kind kind = Kind::NotReached;
    double milliseconds = 0.0;  // Interpolated, AtMost
    double bestError = 0.0;     // the front's lowest error (NotReached says how close it came)
    // The points the time comes from, as indices into the series: the front point above the target and
    // the one at or below it when Interpolated; both the one point when the target falls on it or when
    // AtMost; -1 when NotReached. A reader can say which settings a figure lies between.
    int above = -1, below = -1;
};
TimeToTarget timeToReach(const std::vector<TradeoffPoint>& series, double target);

// A technique against the baseline at one error target: both times and their ratio (baseline time /
// technique time), which is exact when both were interpolated, a lower bound when only the technique's
// time is an upper bound, an upper bound when only the baseline's is, and unknown otherwise.
struct TargetSpeedup {
    enum class Bound { Exact, AtLeast, AtMost, Unknown };
    double target = 0.0;
    TimeToTarget technique, baseline;
    Bound bound = Bound::Unknown;
    double ratio = 0.0;  // when bound != Unknown
    // The same comparison made with the technique's slowest runs against the baseline's fastest, and the
    // reverse (ReportRow::totalSpread): how far the runs' spread could move the ratio. NaN when the runs'
    // spread was not measured or either comparison comes out of another kind.
    double ratioLow = std::numeric_limits<double>::quiet_NaN(), ratioHigh = std::numeric_limits<double>::quiet_NaN();
};
TargetSpeedup speedupAtTarget(const std::vector<TradeoffPoint>& baseline, const std::vector<TradeoffPoint>& technique,
                              double target);

}  // namespace viz::report
