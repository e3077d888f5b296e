// The ray inspector's ground truth for one pixel: where each light is visible along the eye ray
// (exact lit intervals), the integrand along it, and L_air for that pixel computed exactly as the
// full-frame reference computes it (the same functions, the same defaults).
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "techniques/reference/ray_integrals.h"

namespace viz::reference {

struct ProbeLight {
    int light = -1;            // index into Scene::lights
    std::string name;
    std::vector<Interval> lit;  // area lights: where any of their cells is visible
    glm::dvec3 airlight{0.0};   // this light's share of L_air
};

struct RayProbe {
    int x = 0, y = 0;
    glm::dvec3 direction{0.0};
    double d = 0.0;                 // distance to the first surface (zfar for the sky)
    std::vector<ProbeLight> lights;
    glm::dvec3 airlight{0.0};       // the pixel's L_air
    std::vector<double> t;          // curve points along [0, d] (uniform)
    std::vector<glm::dvec3> integrand;  // the integrand there, V included
};

struct ProbeOptions {
    int curvePoints = 256;
    int transitionSamples = 256;  // the reference's `transition_samples`
    int areaSamples = 8;          // the reference's `area_samples`
};

// Pixel (x, y) of a width x height image (row 0 at the top). Builds its own ray tracer (tens of ms).
RayProbe probePixel(const scene::Scene& scene, int width, int height, int x, int y, const ProbeOptions& options = {});

}  // namespace viz::reference
