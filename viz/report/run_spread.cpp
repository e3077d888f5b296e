#include "report/run_spread.h"

#include <algorithm>
#include <cmath>

#include "core/text.h"
#include "report/text_output.h"

namespace viz::report {

RunSpread spreadOf(const std::vector<double>& runs) {
    if (runs.empty()) return {};
    const auto [lo, hi] = std::minmax_element(runs.begin(), runs.end());
    return {*lo, *hi};
}

double spreadFraction(double median, const RunSpread& spread) {
    if (!(median > 0.0) || !std::isfinite(spread.minMilliseconds) || !std::isfinite(spread.maxMilliseconds))
        return std::numeric_limits<double>::quiet_NaN();
    return (spread.maxMilliseconds - spread.minMilliseconds) / median;
}

bool isNoisy(double median, const RunSpread& spread) { return spreadFraction(median, spread) > kNoisySpread; }

std::string spreadText(double median, const RunSpread& spread) {
    const double fraction = spreadFraction(median, spread);
    if (!std::isfinite(fraction)) return "";
    return "runs " + format("%.4g", spread.minMilliseconds) + " to " + format("%.4g", spread.maxMilliseconds) +
           " ms, " + format("%.3g", 100.0 * fraction) + " % of the median";
}

std::string timeCellHtml(const std::string& text, double median, const RunSpread& spread, bool& noisy) {
    if (!isNoisy(median, spread)) return "<td>" + text + "</td>";
    noisy = true;
    return "<td class=\"noisy\" title=\"" + escapeHtml(spreadText(median, spread)) + "\">" + text + "&dagger;</td>";
}

std::string noisyFootnoteHtml(const std::string& advice) {
    return "<p class=\"note\">&dagger; The timed runs behind this time lay more than " + format("%.0f", 100.0 * kNoisySpread) +
           " % of their median apart (its tooltip gives the fastest and slowest): something else was running, or the "
           "clock changed, while they were timed. " + advice + "</p>\n";
}

std::string noisyRunsNote(const std::vector<TimedPoint>& points, const std::string& plural) {
    int noisy = 0;
    const TimedPoint* widest = nullptr;
    for (const TimedPoint& p : points) {
        if (!isNoisy(p.median, p.spread)) continue;
        ++noisy;
        if (!widest || spreadFraction(p.median, p.spread) > spreadFraction(widest->median, widest->spread)) widest = &p;
    }
    if (!widest) return "";
    return "note: the timed runs of " + std::to_string(noisy) + " of " + std::to_string(points.size()) + " " + plural +
           " spread by more than " + format("%.0f", 100.0 * kNoisySpread) + " % of their median (widest: " + widest->name +
           ", " + spreadText(widest->median, widest->spread) +
           "); something else ran or the clock changed while they were timed: measure them again";
}

}  // namespace viz::report
