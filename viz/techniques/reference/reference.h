// `reference`: the ground truth of L_air and of the final image, on the CPU in double precision with
// exact triangle visibility (Embree 3). See README.md in this folder for stages, parameters and accuracy.
#pragma once

#include <memory>

#include "debug/technique.h"

namespace viz {

std::unique_ptr<Technique> makeReferenceTechnique();

}  // namespace viz
