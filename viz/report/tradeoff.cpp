#include "report/tradeoff.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace viz::report {

namespace {
bool usable(const TradeoffPoint& p) {
    return std::isfinite(p.milliseconds) && std::isfinite(p.error) && p.milliseconds > 0.0 && p.error > 0.0;
}
}  // namespace

std::vector<int> paretoFront(const std::vector<TradeoffPoint>& points) {
    std::vector<int> order;
    for (int i = 0; i < int(points.size()); ++i)
        if (usable(points[std::size_t(i)])) order.push_back(i);
    // By time, then error: a point is on the front when its error is below every faster point's.
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        const TradeoffPoint &pa = points[std::size_t(a)], &pb = points[std::size_t(b)];
        return pa.milliseconds != pb.milliseconds ? pa.milliseconds < pb.milliseconds : pa.error < pb.error;
    });
    std::vector<int> front;
    double bestError = INFINITY;
    for (int i : order)
        if (points[std::size_t(i)].error < bestError) {
            front.push_back(i);
            bestError = points[std::size_t(i)].error;
        }
    return front;
}

std::optional<double> baselineTimeAtError(const std::vector<TradeoffPoint>& baseline, double error) {
    const TimeToTarget t = timeToReach(baseline, error);
    if (t.kind != TimeToTarget::Kind::Interpolated) return std::nullopt;
    return t.milliseconds;
}

std::optional<double> speedupAtEqualError(const std::vector<TradeoffPoint>& baseline, const TradeoffPoint& p) {
    if (!usable(p)) return std::nullopt;
    const auto t = baselineTimeAtError(baseline, p.error);
    if (!t) return std::nullopt;
    return *t / p.milliseconds;
}

TimeToTarget timeToReach(const std::vector<TradeoffPoint>& series, double target) {
    TimeToTarget t;
    const std::vector<int> front = paretoFront(series);  // time rising, error falling
    if (front.empty() || !(target > 0.0) || !std::isfinite(target)) {
        t.bestError = front.empty() ? NAN : series[std::size_t(front.back())].error;
        return t;
    }
    t.bestError = series[std::size_t(front.back())].error;
    const TradeoffPoint& cheapest = series[std::size_t(front.front())];
    if (cheapest.error <= target) {
        // On the target: its time exactly; below it: a bound.
        t.kind = cheapest.error == target ? TimeToTarget::Kind::Interpolated : TimeToTarget::Kind::AtMost;
        t.milliseconds = cheapest.milliseconds;
        t.above = t.below = front.front();
        return t;
    }
    if (t.bestError > target) return t;  // NotReached
    // The first front point at or below the target, and the one before it (above it).
    for (std::size_t k = 1; k < front.size(); ++k) {
        const TradeoffPoint& q = series[std::size_t(front[k])];
        if (q.error > target) continue;
        const TradeoffPoint& p = series[std::size_t(front[k - 1])];
        const double f = std::log(target / p.error) / std::log(q.error / p.error);
        t.kind = TimeToTarget::Kind::Interpolated;
        t.milliseconds = std::exp(std::log(p.milliseconds) + f * std::log(q.milliseconds / p.milliseconds));
        t.below = front[k];
        t.above = q.error == target ? front[k] : front[k - 1];
        return t;
    }
    return t;
}

TargetSpeedup speedupAtTarget(const std::vector<TradeoffPoint>& baseline, const std::vector<TradeoffPoint>& technique,
                              double target) {
    using Kind = TimeToTarget::Kind;
    TargetSpeedup s;
    s.target = target;
    s.technique = timeToReach(technique, target);
    s.baseline = timeToReach(baseline, target);
    if (s.technique.kind == Kind::NotReached || s.baseline.kind == Kind::NotReached) return s;
    s.ratio = s.baseline.milliseconds / s.technique.milliseconds;
    const bool techniqueBound = s.technique.kind == Kind::AtMost, baselineBound = s.baseline.kind == Kind::AtMost;
    s.bound = !techniqueBound && !baselineBound ? TargetSpeedup::Bound::Exact
              : techniqueBound && !baselineBound ? TargetSpeedup::Bound::AtLeast
              : !techniqueBound && baselineBound ? TargetSpeedup::Bound::AtMost
                                                 : TargetSpeedup::Bound::Unknown;
    return s;
}

}  // namespace viz::report
