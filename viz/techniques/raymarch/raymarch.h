// Technique `raymarch`: brute-force ray marching through shadow maps, the baseline every technique is
// compared with. N samples per pixel over [0, d], optional jitter, optional exact integration of the
// unshadowed airlight between samples.
#pragma once

#include <memory>

#include "debug/technique.h"

namespace viz {

std::unique_ptr<Technique> makeRaymarchTechnique();

}  // namespace viz
