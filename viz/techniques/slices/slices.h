// Technique `slices`: Mitchell 2004, slice-based light shafts. N view-aligned planes fill the view-space
// bounding box of each light's frustum, are clipped to that frustum with gl_ClipDistance and added back to
// front into an accumulation target; `physical` weighting makes the sum a midpoint rule of L_air, `artistic`
// uses the paper's constants. The accumulation format is a knob (the paper's 8-bit precision lab).
#pragma once

#include <memory>

#include "debug/technique.h"

namespace viz {

// Numeric codes of the `weighting`, `accum` and `integration` parameters (Settings hold numbers).
enum class SlicesWeighting { Artistic = 0, Physical = 1 };
enum class SlicesAccum { Rgba8 = 0, Rgba8Mask = 1, Rgba16f = 2, Rgba32f = 3 };
enum class SlicesIntegration { Midpoint = 0, Equiangular = 1, Auto = 2 };

std::unique_ptr<Technique> makeSlicesTechnique();

}  // namespace viz
