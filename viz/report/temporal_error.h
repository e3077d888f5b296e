// Temporal error: the part of a technique's error that changes from frame to frame along a motion path
// (scene/motion_path.h), against the reference rendered on the same frames.
//
// For frame t, pixel p and channel c: e_t = T_t - R_t (technique minus reference) and d_t = e_t - e_{t-1}
// (t = 1 .. N-1). A pixel's flicker is
//     f(p) = sqrt(mean over t and c of d_t(p, c)^2) / 2,
// in the images' units (radiance). The halving makes an error that alternates +e, -e, +e, ... (d = +-2e)
// score e, the size of the error that jumps; an error constant in time scores exactly 0 (d = 0 however
// large the error), and so does the reference against itself. The figures:
//     temporal RMS  = sqrt(mean over p, t and c of d_t^2) / 2 / mean(R)
//     worst flicker = 99th percentile over pixels of f(p) / mean(R)
// with mean(R) the mean of the reference over every pixel, channel and frame; both are relative, like
// the relative L2 of a single frame (report/error_metrics.h), which the mean per-frame error averages.
//
// NaN and Inf: a pixel of a frame whose technique or reference value is NaN or Inf in any channel has no
// error e_t there; the differences that need it are left out and counted, never propagated into the
// figures. A pixel left with no difference at all is NaN in the flicker image (the heat map shows it in
// magenta) and counted. A figure with nothing to average (fewer than two frames, every pixel left out) is
// NaN, which writers print as empty / null.
#pragma once

#include <cstddef>
#include <vector>

#include "core/image.h"

namespace viz::report {

struct TemporalMetrics {
    int frames = 0;
    double meanFrameError = 0.0;  // mean over frames with a finite figure of their relative L2
    double temporalRms = 0.0;     // relative to mean(R), above
    double worstFlicker = 0.0;    // 99th percentile over pixels of f(p), relative to mean(R)
    double referenceMean = 0.0;   // mean(R) over the finite reference values of every frame
    Image flicker;                // f(p), one channel, absolute; NaN where a pixel has no difference
    std::vector<double> frameError;     // relative L2 of each frame (NaN where it holds NaN or Inf)
    std::vector<double> frameTemporal;  // sqrt(mean over p and c of d_t^2) / 2 / mean(R); [0] is NaN
    // What was left out: frames, pixel-frames and differences.
    std::size_t framesWithoutError = 0;         // frames whose relative L2 is NaN (not in the mean)
    std::size_t nonFiniteTestPixels = 0;        // pixel-frames with a NaN or Inf channel in the technique
    std::size_t nonFiniteReferencePixels = 0;   // ... in the reference
    std::size_t excludedDifferences = 0;        // (p, t) pairs whose d_t needs a left-out e
    std::size_t pixelsWithoutDifference = 0;    // pixels NaN in `flicker`
    bool complete() const {
        return framesWithoutError == 0 && nonFiniteTestPixels == 0 && nonFiniteReferencePixels == 0;
    }
};

// Takes the frames one at a time (a sequence need not fit in memory): keeps the previous error and the
// per-pixel sums.
class TemporalAccumulator {
public:
    // Frames in path order; every frame the size and channel count of the first (VIZ_CHECK).
    void add(const Image& test, const Image& reference);
    // The next frame does not follow the last one added (the frames between them have no reference): it
    // takes no difference, as if every pixel's previous error were left out (counted in excludedDifferences).
    void gap();
    TemporalMetrics finish() const;
    // finish()'s temporalRms and referenceMean alone, without the flicker image and its percentile (a
    // window updates them every frame).
    double temporalRms() const;
    double referenceMean() const;
    int frames() const { return mFrames; }

private:
    int mFrames = 0, mWidth = 0, mHeight = 0, mChannels = 0;
    std::vector<double> mPrevious;        // e_{t-1}, per value
    std::vector<unsigned char> mValid;    // e_{t-1} exists, per pixel
    std::vector<double> mSumSquares;      // sum over t and c of d_t^2, per pixel
    std::vector<unsigned> mCount;         // how many t, per pixel
    std::vector<double> mFrameError;
    std::vector<double> mFrameSquares;    // sum over p and c of d_t^2, per frame
    std::vector<std::size_t> mFrameCount; // how many pixels entered it
    double mReferenceSum = 0.0;
    std::size_t mReferenceValues = 0;
    std::size_t mNonFiniteTest = 0, mNonFiniteReference = 0, mExcluded = 0;
};

// The same over whole sequences (same length).
TemporalMetrics temporalMetrics(const std::vector<Image>& test, const std::vector<Image>& reference);

}  // namespace viz::report
