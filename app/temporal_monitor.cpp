#include "temporal_monitor.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace airlight {

void TemporalMonitor::reset() { *this = TemporalMonitor{}; }

bool TemporalMonitor::add(const viz::Image& airlight) {
    if (airlight.empty()) return false;
    const bool comparable = !mPrevious.empty() && mPrevious.width == airlight.width &&
                            mPrevious.height == airlight.height && mPrevious.channels == airlight.channels;
    if (!comparable) {
        reset();
        mPrevious = airlight;
        for (float v : airlight.pixels)
            if (std::isfinite(v)) mSumValues += v, ++mValues;
        return false;
    }
    const int w = airlight.width, h = airlight.height, c = airlight.channels;
    auto change = std::make_shared<viz::Image>(w, h, 1);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double luminanceChange = 0.0;
            bool finite = true;
            for (int k = 0; k < c; ++k) {
                const double now = airlight.at(x, y, k), before = mPrevious.at(x, y, k);
                if (!std::isfinite(now) || !std::isfinite(before)) {
                    finite = false;
                    continue;
                }
                const double d = now - before;
                mSumSquares += d * d;
                ++mCount;
                // Rec. 709 luminance of the change (one channel: its own value).
                static constexpr double kLuminance[3] = {0.2126, 0.7152, 0.0722};
                luminanceChange += (c >= 3 && k < 3 ? kLuminance[k] : (c >= 3 ? 0.0 : 1.0 / c)) * d;
            }
            change->at(x, y, 0) = finite ? float(luminanceChange) : std::numeric_limits<float>::quiet_NaN();
        }
    for (float v : airlight.pixels)
        if (std::isfinite(v)) mSumValues += v, ++mValues;
    mPrevious = airlight;
    mChange = std::move(change);
    ++mPairs;
    return true;
}

double TemporalMonitor::score() const {
    if (mCount == 0 || mValues == 0) return std::numeric_limits<double>::quiet_NaN();
    const double mean = mSumValues / double(mValues);
    const double rms = 0.5 * std::sqrt(mSumSquares / double(mCount));
    return mean > 0.0 ? rms / mean : (rms == 0.0 ? 0.0 : std::numeric_limits<double>::infinity());
}

std::string TemporalMonitor::describe() const {
    if (mPairs == 0) return mPrevious.empty() ? "no frame yet" : "one frame so far";
    char text[128];
    std::snprintf(text, sizeof text, "RMS %.3g x mean (%d pair%s)", score(), mPairs, mPairs == 1 ? "" : "s");
    return text;
}

viz::Intermediate TemporalMonitor::view() const {
    viz::Intermediate i;
    i.id = kTemporalChangeId;
    i.label = "L_air change per frame";
    i.note = "luminance of L_air(t) - L_air(t-1) while the animation plays (red: brighter, blue: darker); the "
             "title's score includes the motion's own change (report --temporal measures against the reference)";
    i.units = "radiance";
    i.kind = viz::ViewKind::Signed;
    // Symmetric about 0: the 99th percentile of |change| (the largest few are the light's own pixels).
    float bound = 0.0f;
    if (mChange) {
        std::vector<float> magnitudes;
        magnitudes.reserve(mChange->pixels.size());
        for (float v : mChange->pixels)
            if (std::isfinite(v)) magnitudes.push_back(std::abs(v));
        if (!magnitudes.empty()) {
            const std::size_t k = std::min(magnitudes.size() - 1, std::size_t(0.99 * double(magnitudes.size())));
            std::nth_element(magnitudes.begin(), magnitudes.begin() + std::ptrdiff_t(k), magnitudes.end());
            bound = magnitudes[k];
        }
    }
    if (!(bound > 0.0f)) bound = 1e-6f;
    i.rangeMin = -bound;
    i.rangeMax = bound;
    i.image = mChange;
    if (mChange) i.extent = {mChange->width, mChange->height, 1};
    return i;
}

}  // namespace airlight
