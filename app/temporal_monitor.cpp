#include "temporal_monitor.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace airlight {

namespace {

bool sameShape(const viz::Image& a, const viz::Image& b) {
    return a.width == b.width && a.height == b.height && a.channels == b.channels;
}

// The Rec. 709 luminance of d = (now - nowReference) - (before - beforeReference) per pixel (the
// references taken as zero when null); NaN where any value is not finite. With `sums`, the squares of d per
// channel add to sums->squares and their count to sums->count (finite pixels only).
struct SquareSums {
    double& squares;
    long long& count;
};
std::shared_ptr<viz::Image> luminanceOfChange(const viz::Image& now, const viz::Image& before, const viz::Image* nowReference,
                                              const viz::Image* beforeReference, const SquareSums* sums) {
    static constexpr double kLuminance[3] = {0.2126, 0.7152, 0.0722};
    const int w = now.width, h = now.height, c = now.channels;
    auto change = std::make_shared<viz::Image>(w, h, 1);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double luminance = 0.0;
            bool finite = true;
            for (int k = 0; k < c; ++k) {
                const double a = now.at(x, y, k), b = before.at(x, y, k);
                const double ar = nowReference ? nowReference->at(x, y, k) : 0.0;
                const double br = beforeReference ? beforeReference->at(x, y, k) : 0.0;
                if (!std::isfinite(a) || !std::isfinite(b) || !std::isfinite(ar) || !std::isfinite(br)) {
                    finite = false;
                    continue;
                }
                const double d = (a - ar) - (b - br);
                if (sums) sums->squares += d * d, ++sums->count;
                luminance += (c >= 3 && k < 3 ? kLuminance[k] : (c >= 3 ? 0.0 : 1.0 / c)) * d;
            }
            change->at(x, y, 0) = finite ? float(luminance) : std::numeric_limits<float>::quiet_NaN();
        }
    return change;
}

// A signed view of `image`, symmetric about 0 at the 99th percentile of |value| (the largest few are the
// light's own pixels).
viz::Intermediate signedView(const std::shared_ptr<viz::Image>& image, const char* id, const char* label,
                             const char* note) {
    viz::Intermediate i;
    i.id = id;
    i.label = label;
    i.note = note;
    i.units = "radiance";
    i.kind = viz::ViewKind::Signed;
    float bound = 0.0f;
    if (image) {
        std::vector<float> magnitudes;
        magnitudes.reserve(image->pixels.size());
        for (float v : image->pixels)
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
    i.image = image;
    if (image) i.extent = {image->width, image->height, 1};
    return i;
}

}  // namespace

void TemporalMonitor::reset() { *this = TemporalMonitor{}; }

bool TemporalMonitor::add(const viz::Image& airlight, std::shared_ptr<const viz::Image> reference) {
    if (airlight.empty()) return false;
    if (reference && !sameShape(*reference, airlight)) reference.reset();
    const bool comparable = !mPrevious.empty() && sameShape(mPrevious, airlight);
    if (!comparable) reset();
    if (comparable) {
        const SquareSums sums{mSumSquares, mCount};
        mChange = luminanceOfChange(airlight, mPrevious, nullptr, nullptr, &sums);
        ++mPairs;
        if (reference && mPreviousReference) {
            mErrorChange = luminanceOfChange(airlight, mPrevious, reference.get(), mPreviousReference.get(), nullptr);
            ++mErrorPairs;
        }
    }
    // The error's temporal figures: frames with a reference, no difference taken across one without.
    if (reference) {
        if (!mPreviousReference && mAgainst.frames() > 0) mAgainst.gap();
        mAgainst.add(airlight, *reference);
        if (mErrorPairs > 0) mErrorScore = mAgainst.temporalRms();
    }
    for (float v : airlight.pixels)
        if (std::isfinite(v)) mSumValues += v, ++mValues;
    mPrevious = airlight;
    mPreviousReference = std::move(reference);
    return comparable;
}

double TemporalMonitor::score() const {
    if (mCount == 0 || mValues == 0) return std::numeric_limits<double>::quiet_NaN();
    const double mean = mSumValues / double(mValues);
    const double rms = 0.5 * std::sqrt(mSumSquares / double(mCount));
    return mean > 0.0 ? rms / mean : (rms == 0.0 ? 0.0 : std::numeric_limits<double>::infinity());
}

double TemporalMonitor::errorScore() const { return mErrorScore; }

std::string TemporalMonitor::describe() const {
    if (mPairs == 0) return mPrevious.empty() ? "no frame yet" : "one frame so far";
    char text[128];
    std::snprintf(text, sizeof text, "RMS %.3g x mean (%d pair%s)", score(), mPairs, mPairs == 1 ? "" : "s");
    return text;
}

std::string TemporalMonitor::describeError() const {
    if (mErrorPairs == 0) return "no two frames with the reference yet";
    char text[160];
    std::snprintf(text, sizeof text, "flicker %.3g x mean(ref) (%d pair%s)", mErrorScore, mErrorPairs,
                  mErrorPairs == 1 ? "" : "s");
    return text;
}

viz::Intermediate TemporalMonitor::view() const {
    return signedView(mChange, kTemporalChangeId, "L_air change per frame",
                      "luminance of L_air(t) - L_air(t-1) while the animation plays (red: brighter, blue: darker); "
                      "the title's score includes the motion's own change (the error change view and report "
                      "--temporal measure against the reference)");
}

viz::Intermediate TemporalMonitor::errorView() const {
    return signedView(mErrorChange, kTemporalErrorChangeId, "Error change per frame",
                      "luminance of e(t) - e(t-1), e = L_air - reference on the same path frame: the flicker, "
                      "without the motion's own change (red: the error grew, blue: it fell); the title's flicker "
                      "is report --temporal's temporal RMS over the pairs of frames shown whose references are known");
}

}  // namespace airlight
