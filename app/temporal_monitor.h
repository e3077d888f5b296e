// The window's temporal view (issue 19): while an animation plays (P), how much L_air changes from one
// frame to the next. Each run's L_air is compared with the previous one of the same size; the view
// "temporal.change" shows the signed change of its luminance, and its title the running score
//     change RMS = sqrt(mean over pixels, channels and frame pairs of d^2) / 2 / mean(L_air),
//     d = L_air(t) - L_air(t-1),
// the temporal RMS of report/temporal_error.h with the reference taken as zero: it includes the change
// the motion itself causes (the shafts moving with the light), which `report --temporal` subtracts by
// comparing with the reference on the same frames. A setting that moves nothing but its own noise
// (raymarch jitter_time=per-frame on a still scene) scores its noise alone; one that changes nothing
// scores 0 and makes no new frame.
#pragma once

#include <memory>
#include <string>

#include "core/image.h"
#include "debug/intermediate.h"

namespace airlight {

inline constexpr const char* kTemporalChangeId = "temporal.change";

class TemporalMonitor {
public:
    // Forgets every frame (play started or stopped).
    void reset();
    // The L_air of the next frame (RGB float). Returns true when it was compared with a previous frame
    // (false for the first, or after the size changed, which starts the count again).
    bool add(const viz::Image& airlight);
    // The view of the last change (valid once add has returned true).
    viz::Intermediate view() const;
    // The running score (NaN before two frames) and the frame pairs it averages.
    double score() const;
    int pairs() const { return mPairs; }
    // "RMS 0.0123 x mean (17 pairs)" (or "one frame so far"): the view's title.
    std::string describe() const;

private:
    viz::Image mPrevious;
    std::shared_ptr<viz::Image> mChange;
    double mSumSquares = 0.0, mSumValues = 0.0;
    long long mCount = 0, mValues = 0;
    int mPairs = 0;
};

}  // namespace airlight
