// Technique `minmax`: Chen, Baran, Durand, Jarosz 2011, "Real-Time Volumetric Shadows using 1D Min-Max
// Mipmaps". The shadow map is rectified into epipolar slices; each slice row becomes a 1D heightfield
// with a min-max tree, and every pixel walks its slice's tree to find the lit segments of its ray.
#pragma once

#include <memory>

#include "debug/technique.h"

namespace viz {

std::unique_ptr<Technique> makeMinmaxTechnique();

}  // namespace viz
