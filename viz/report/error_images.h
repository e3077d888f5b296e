// Pictures of error for the report: L_air at a shared exposure and the per-pixel error as a heat map.
#pragma once

#include "core/image.h"

namespace viz::report {

// Exposure that maps the 99.5th percentile of the brightest channel of `image` to 1 (1 when black).
float exposureFor(const Image& image);

// sum_c |test - reference| * scale on a sequential colour map (black, purple, orange, yellow at 1);
// NaN or Inf pixels in magenta. Returns linear RGB for writeImage.
Image errorHeatMap(const Image& test, const Image& reference, float scale);

// The same colour map over the first channel of a scalar image (a per-pixel figure such as the flicker of
// report/temporal_error.h): value * scale, clamped to [0, 1]; NaN or Inf pixels in magenta.
Image heatMap(const Image& scalar, float scale);

}  // namespace viz::report
