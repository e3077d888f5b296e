// How far an image is from a reference: the figures `airlight report` and the stiff-case suite quote.
// All compare every channel of every pixel (RGB radiance, linear). A figure that is undefined (the test
// image holds NaN or Inf, or the reference is black where a ratio needs it) is NaN; writers print it
// as empty / null, never as a number.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>

#include "core/image.h"

namespace viz::report {

// An undefined figure (see above).
inline constexpr double kUndefined = std::numeric_limits<double>::quiet_NaN();

struct ErrorMetrics {
    double relativeL2 = 0.0;    // ||test - ref||_2 / ||ref||_2
    double rmse = 0.0;          // sqrt(mean over values of (test - ref)^2)
    double maxAbsolute = 0.0;   // max over values of |test - ref|
    double relativeP999 = 0.0;  // 99.9th percentile over pixels of the per-pixel relative error (below)
    double psnr = 0.0;          // dB, on the tone map below, peak 1; +inf for identical images
    std::size_t nanPixels = 0, infPixels = 0, negativePixels = 0;  // pixels with any such channel
    std::size_t pixels = 0;
    bool finite() const { return nanPixels == 0 && infPixels == 0; }
};

// Per-pixel relative error: sum_c |test - ref| / max(sum_c |ref|, kRelativeFloor * mean_pixels sum_c |ref|),
// so near-black pixels of a bright image do not dominate the percentile.
inline constexpr double kRelativeFloor = 0.01;

// Tone map for PSNR (stated in every report): both images are scaled by k = kToneKey / (mean over the
// reference's pixels of its channel mean), then each value v maps to v / (1 + v) (Reinhard).
inline constexpr double kToneKey = 0.18;
double toneMapScale(const Image& reference);
inline double toneMap(double v, double scale) {
    const double s = v * scale;
    return s / (1.0 + s);
}

// sqrt(diff2 / ref2) from the two sums of squares (over the differences, over the reference): 0 for two
// black images, undefined for a black reference under a non-zero difference.
inline double relativeL2FromSums(double diff2, double ref2) {
    return ref2 > 0.0 ? std::sqrt(diff2 / ref2) : (diff2 == 0.0 ? 0.0 : kUndefined);
}

// test and reference must have the same size and channel count (VIZ_CHECK).
ErrorMetrics compareImages(const Image& test, const Image& reference);

// Counts only (for images without a reference).
void countNonFinite(const Image& image, ErrorMetrics& into);

}  // namespace viz::report
