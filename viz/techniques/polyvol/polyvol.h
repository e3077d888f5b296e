// Technique `polyvol`: Billeter, Sintorn and Assarsson 2010, polygonal light volumes. The shadow map is
// turned into a closed mesh around the directly lit space; rendering it from the camera with additive
// blending sums signed unshadowed airlight terms L(0, x) at the crossings (see README.md).
#pragma once

#include <memory>

#include "debug/technique.h"

namespace viz {

std::unique_ptr<Technique> makePolyvolTechnique();

}  // namespace viz
