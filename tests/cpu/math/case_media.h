// What the segment kernels' case lists (cosine_lobe_cases.h, spot_penumbra_cases.h) share: the media every
// geometry is tried in, and a random unit direction for their random samples.
#pragma once

#include <random>
#include <vector>

#include <glm/glm.hpp>

namespace viz::airlight::test {

struct CaseMedium {
    const char* name;
    double sigma_s, sigma_t, g;
};

// Thin to thick, isotropic, forward and backward phase functions, and no extinction at all.
inline std::vector<CaseMedium> caseMedia() {
    return {{"thin isotropic", 0.1, 0.1, 0.0}, {"forward", 0.5, 2.0, 0.6},          {"backward", 0.05, 0.05, -0.8},
            {"thick", 1.0, 20.0, 0.3},         {"no extinction", 0.1, 0.0, 0.0}};
}

// A unit direction, uniform over the sphere (rejection from the cube).
inline glm::dvec3 randomUnitDirection(std::mt19937& rng) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    glm::dvec3 v;
    do v = {unit(rng), unit(rng), unit(rng)};
    while (glm::dot(v, v) < 0.05 || glm::dot(v, v) > 1.0);
    return glm::normalize(v);
}

}  // namespace viz::airlight::test
