// The window's temporal views (issue 19): while an animation plays (P), how much L_air changes from one
// frame to the next, and how much its error against the reference does when the reference's frames are
// known (a --path loop: path_reference.h). Each run's L_air is compared with the previous one of the
// same size.
//
// "temporal.change" shows the signed change of L_air's luminance, and its title the running score
//     change RMS = sqrt(mean over pixels, channels and frame pairs of d^2) / 2 / mean(L_air),
//     d = L_air(t) - L_air(t-1),
// the temporal RMS of report/temporal_error.h with the reference taken as zero: it includes the change
// the motion itself causes (the shafts moving with the light). A setting that moves nothing but its own
// noise (raymarch jitter_time=per-frame on a still scene) scores its noise alone; one that changes
// nothing scores 0 and makes no new frame.
//
// "temporal.error_change" ("Error change per frame") shows the signed change of the error's luminance, d = e(t) - e(t-1) with
// e = L_air - reference, and its title the temporal RMS of report/temporal_error.h itself (the same
// accumulator), over the pairs of consecutive frames shown whose references are both known: the motion's
// own change is gone, and what is left is the flicker `report --temporal` ranks techniques by.
#pragma once

#include <limits>
#include <memory>
#include <string>

#include "core/image.h"
#include "debug/intermediate.h"
#include "report/temporal_error.h"

namespace airlight {

inline constexpr const char* kTemporalChangeId = "temporal.change";
inline constexpr const char* kTemporalErrorChangeId = "temporal.error_change";

class TemporalMonitor {
public:
    // Forgets every frame (play started or stopped).
    void reset();
    // The L_air of the next frame (RGB float), with the reference's L_air on the same frame when it is
    // known (null otherwise; one of another size counts as unknown). Returns true when the frame was
    // compared with a previous one (false for the first, or after the size changed, which starts the
    // count again).
    bool add(const viz::Image& airlight, std::shared_ptr<const viz::Image> reference = nullptr);

    // The view of the last change (valid once add has returned true).
    viz::Intermediate view() const;
    // The running score (NaN before two frames) and the frame pairs it averages.
    double score() const;
    int pairs() const { return mPairs; }
    // "RMS 0.0123 x mean (17 pairs)" (or "one frame so far"): the view's title.
    std::string describe() const;

    // Against the reference: the view of the last pair of frames with both references (valid once
    // errorPairs() > 0), the temporal RMS over such pairs (NaN before one) and its title text.
    viz::Intermediate errorView() const;
    double errorScore() const;
    int errorPairs() const { return mErrorPairs; }
    std::string describeError() const;

private:
    viz::Image mPrevious;
    std::shared_ptr<const viz::Image> mPreviousReference;  // null: the previous frame's is not known
    std::shared_ptr<viz::Image> mChange, mErrorChange;
    double mSumSquares = 0.0, mSumValues = 0.0;
    long long mCount = 0, mValues = 0;
    int mPairs = 0, mErrorPairs = 0;
    viz::report::TemporalAccumulator mAgainst;  // frames with a known reference, a gap after one without
    double mErrorScore = std::numeric_limits<double>::quiet_NaN();                         // mAgainst's temporal RMS after the last add
};

}  // namespace airlight
