// Cases for the cosine-lobe emitter's segment integral (cosineLobeSegment in viz/shared/airlight.h, an
// area light's VPL), shared by the CPU test and the GLSL test: geometries around the light's foot point
// (beside, next to the ray, behind the camera, ahead of the segment, a sliver, the sky), emitter normals
// facing every way (toward and away from the ray, along it both ways, perpendicular to it, oblique) and
// media from thin to thick with isotropic, forward and backward phase functions, plus a fixed random sample.
#pragma once

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "cpu/math/case_media.h"

namespace viz::airlight::test {

struct LobeCase {
    std::string name;
    glm::dvec3 D;  // light - eye
    glm::dvec3 w;  // unit ray direction
    glm::dvec3 n;  // unit emitter normal
    double x0, x1, sigma_s, sigma_t, g, I0;
};

inline std::vector<LobeCase> cosineLobeCases() {
    const double inf = std::numeric_limits<double>::infinity();
    struct Geometry {
        const char* name;
        glm::dvec3 D;
        double x0, x1;
    };
    const Geometry geometries[] = {
        {"beside", {5.0, 1.0, 0.0}, 0.0, 10.0},
        {"next to the ray", {5.0, 1e-3, 0.0}, 0.0, 10.0},
        {"grazing the light", {5.0, 1e-5, 0.0}, 0.0, 10.0},
        {"1e-6 from the light", {5.0, 1e-6, 0.0}, 0.0, 10.0},
        {"behind the camera", {-3.0, 0.5, 0.2}, 0.0, 20.0},
        {"ahead of the segment", {50.0, 2.0, 1.0}, 0.0, 10.0},
        {"sliver at the foot point", {5.0, 0.3, 0.0}, 4.9, 5.1},
        {"sky", {5.0, 1.0, 0.0}, 0.0, inf},
    };
    const glm::dvec3 w(1.0, 0.0, 0.0);
    struct Normal {
        const char* name;
        glm::dvec3 n;
    };
    // The foot point P lies at +y of the light for the geometries above (D.y > 0): -y faces the ray.
    const Normal normals[] = {
        {"facing the ray", {0.0, -1.0, 0.0}},  {"facing away", {0.0, 1.0, 0.0}},
        {"along the ray", {1.0, 0.0, 0.0}},    {"against the ray", {-1.0, 0.0, 0.0}},
        {"perpendicular", {0.0, 0.0, 1.0}},    {"oblique", glm::normalize(glm::dvec3(0.6, -0.48, 0.64))},
    };
    std::vector<LobeCase> cases;
    for (const Geometry& geometry : geometries)
        for (const Normal& normal : normals)
            for (const CaseMedium& medium : caseMedia()) {
                // Without extinction the sky's integral of 1/r^2 converges, but slowly: keep it finite.
                const double x1 = std::isinf(geometry.x1) && medium.sigma_t == 0.0 ? 1e6 : geometry.x1;
                cases.push_back({std::string(geometry.name) + ", " + normal.name + ", " + medium.name, geometry.D,
                                 w, normal.n, geometry.x0, x1, medium.sigma_s, medium.sigma_t, medium.g, 1.0});
            }
    // A fixed random sample: any light position, ray and normal.
    std::mt19937 rng(20261130u);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), length(0.5, 30.0), logSigma(-3.0, 1.0), phase(-0.9, 0.9);
    for (int i = 0; i < 60; ++i) {
        const glm::dvec3 D = 10.0 * glm::dvec3(unit(rng), unit(rng), unit(rng));
        const glm::dvec3 ray = randomUnitDirection(rng), n = randomUnitDirection(rng);
        const double x1 = length(rng), sigma_t = std::pow(10.0, logSigma(rng));
        cases.push_back({"random " + std::to_string(i), D, ray, n, 0.0, x1, 0.8 * sigma_t, sigma_t, phase(rng), 1.0});
    }
    return cases;
}

}  // namespace viz::airlight::test
