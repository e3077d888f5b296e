// Technique `ivsv`: imperfect voxelized shadow volumes (Wyman and Dai 2013) for one area light. The
// light becomes VPLs (grid cells or Halton points); imperfect shadow maps for all of them come from one point cloud;
// every VPL gets its own epipolar grid tile, all rectified, scanned and gathered in single passes
// (mode=naive runs a full VSV per VPL instead). See README.md.
#pragma once

#include <memory>

#include "debug/technique.h"

namespace viz {

std::unique_ptr<Technique> makeIvsvTechnique();

}  // namespace viz
