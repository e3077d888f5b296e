// The mean of the bilinear texture filter over a uv rectangle by brute force: an n x n midpoint grid of
// scene::sampleLinearRgb. The independent side of the tests of averageLinearRgb and of the VPLs' cell
// colours (error O(1/n^2) on the piecewise bilinear filter).
#pragma once

#include <glm/glm.hpp>

#include "scene/texture_sampling.h"

namespace viz::testing {

inline glm::dvec3 gridMeanLinearRgb(const scene::Texture& tex, glm::dvec2 a, glm::dvec2 b, int n) {
    glm::dvec3 sum(0.0);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            sum += glm::dvec3(
                scene::sampleLinearRgb(tex, {a.x + (b.x - a.x) * (i + 0.5) / n, a.y + (b.y - a.y) * (j + 0.5) / n}));
    return sum / double(n * n);
}

}  // namespace viz::testing
