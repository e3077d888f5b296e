// Technique `vsv`: voxelized shadow volumes (Wyman 2011, as reviewed and extended in Wyman and Dai 2013)
// for point, spot and directional lights (area lights go through ivsv). Per light: an epipolar voxel
// grid (alpha, theta, phi) with 128 phi bits per RGBA32UI texel, filled by resampling the shadow map,
// extruded by a prefix OR along alpha, and gathered per pixel (one texel per eye ray). See README.md.
#pragma once

#include <memory>

#include "debug/technique.h"

namespace viz {

std::unique_ptr<Technique> makeVsvTechnique();

}  // namespace viz
