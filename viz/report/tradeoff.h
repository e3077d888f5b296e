// Error against run time: the Pareto front of a set of (time, error) points and the speed-up of a
// technique over the brute-force baseline at equal error, the figure the papers report.
#pragma once

#include <optional>
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
// points of the baseline's Pareto front that bracket it. Empty when `error` lies outside the front's
// error range (no extrapolation) or the front has fewer than one point.
std::optional<double> baselineTimeAtError(const std::vector<TradeoffPoint>& baseline, double error);

// baselineTimeAtError(error of p) / time of p, or empty as above.
std::optional<double> speedupAtEqualError(const std::vector<TradeoffPoint>& baseline, const TradeoffPoint& p);

}  // namespace viz::report
