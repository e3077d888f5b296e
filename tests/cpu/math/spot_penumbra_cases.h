// Cases for a spot light's penumbra segment integral (spotPenumbraSegment in viz/shared/airlight.h), shared
// by the CPU test and the GLSL test: spots beside the ray, next to it and far from it, axes across, along
// and against the ray, narrow and wide cones, media from thin to thick with isotropic, forward and backward
// phase functions, plus a fixed random sample. Each case is one penumbra part of its ray: the stretch
// where 0 < cd scale + offset < 1, found here by sampling the ray densely in the angle seen from the light
// and bisecting in long double (no cone quadric, unlike the shaders' coneRoots).
#pragma once

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "cpu/math/case_media.h"

namespace viz::airlight::test {

struct SpotCase {
    std::string name;
    glm::dvec3 D;     // light - eye
    glm::dvec3 w;     // unit ray direction
    glm::dvec3 axis;  // unit spot axis (the direction the light travels)
    double scale, offset;  // KHR: A_spot = clamp(cd scale + offset, 0, 1)^2
    double x0, x1, sigma_s, sigma_t, g, I0;
};

// cd scale + offset at x on the ray, in long double from 3D vectors.
inline long double spotLinear(const SpotCase& c, long double x) {
    const long double vx = x * c.w.x - c.D.x, vy = x * c.w.y - c.D.y, vz = x * c.w.z - c.D.z;
    const long double r = std::sqrt(vx * vx + vy * vy + vz * vz);
    const long double cd = (c.axis.x * vx + c.axis.y * vy + c.axis.z * vz) / r;
    return cd * c.scale + c.offset;
}

// The penumbra parts of [x0, x1] of `ray`: sampled at 4,000 equal steps of the angle phi = atan((x - tP) / h)
// seen from the light (the direction from the light is a function of phi alone), each change of the
// classification (dark, penumbra, fully lit) bisected in phi to long double's precision.
inline void appendPenumbraParts(const SpotCase& ray, std::vector<SpotCase>& cases) {
    const long double tP = ray.D.x * ray.w.x + ray.D.y * ray.w.y + ray.D.z * ray.w.z;
    const long double mx = ray.D.x - tP * ray.w.x, my = ray.D.y - tP * ray.w.y, mz = ray.D.z - tP * ray.w.z;
    const long double h = std::sqrt(mx * mx + my * my + mz * mz);
    auto xAt = [&](long double phi) { return tP + h * std::tan(phi); };
    auto zone = [&](long double phi) {
        const long double l = spotLinear(ray, xAt(phi));
        return l <= 0 ? 0 : (l >= 1 ? 2 : 1);
    };
    const long double phi0 = std::atan((ray.x0 - tP) / h), phi1 = std::atan((ray.x1 - tP) / h);
    const int steps = 4000;
    std::vector<long double> cuts{phi0};
    for (int i = 0; i < steps; ++i) {
        long double a = phi0 + (phi1 - phi0) * i / steps, b = phi0 + (phi1 - phi0) * (i + 1) / steps;
        const int za = zone(a);
        if (zone(b) == za) continue;
        for (int k = 0; k < 80; ++k) {
            const long double mid = 0.5L * (a + b);
            (zone(mid) == za ? a : b) = mid;
        }
        cuts.push_back(0.5L * (a + b));
    }
    cuts.push_back(phi1);
    int part = 0;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        if (zone(0.5L * (cuts[i] + cuts[i + 1])) != 1) continue;
        SpotCase c = ray;
        c.x0 = double(i == 0 ? ray.x0 : xAt(cuts[i]));
        c.x1 = double(i + 2 == cuts.size() ? ray.x1 : xAt(cuts[i + 1]));
        if (!(c.x1 > c.x0)) continue;
        c.name += ", part " + std::to_string(part++);
        cases.push_back(c);
    }
}

// KHR_lights_punctual's scale and offset for inner and outer cone angles (radians).
inline void spotScaleOffset(double inner, double outer, double& scale, double& offset) {
    scale = 1.0 / std::max(std::cos(inner) - std::cos(outer), 1e-3);
    offset = -std::cos(outer) * scale;
}

inline std::vector<SpotCase> spotPenumbraCases() {
    struct Geometry {
        const char* name;
        glm::dvec3 D;
        double x0, x1;
    };
    const Geometry geometries[] = {
        {"beside", {5.0, 1.0, 0.0}, 0.0, 10.0},
        {"next to the ray", {5.0, 1e-2, 0.0}, 0.0, 10.0},
        {"grazing the light", {5.0, 1e-4, 0.0}, 0.0, 10.0},
        {"behind the camera", {-3.0, 0.5, 0.2}, 0.0, 20.0},
        {"ahead of the segment", {50.0, 2.0, 1.0}, 0.0, 10.0},
    };
    const glm::dvec3 w(1.0, 0.0, 0.0);
    struct Axis {
        const char* name;
        glm::dvec3 axis;
    };
    // The foot point P lies at +y of the light for the geometries above: -y points the spot at the ray.
    const Axis axes[] = {
        {"down across the ray", glm::normalize(glm::dvec3(0.3, -1.0, 0.0))},
        {"along the ray", glm::normalize(glm::dvec3(1.0, -0.2, 0.05))},
        {"against the ray", glm::normalize(glm::dvec3(-1.0, -0.3, 0.0))},
        {"oblique", glm::normalize(glm::dvec3(0.6, -0.48, 0.64))},
    };
    struct Cone {
        const char* name;
        double inner, outer;
    };
    const Cone cones[] = {{"narrow", 0.15, 0.3}, {"wide", 0.5, 1.2}, {"hard edge", 0.40, 0.41}};
    std::vector<SpotCase> cases;
    for (const Geometry& geometry : geometries)
        for (const Axis& axis : axes)
            for (const Cone& cone : cones)
                for (const CaseMedium& medium : caseMedia()) {
                    SpotCase c{std::string(geometry.name) + ", " + axis.name + ", " + cone.name + ", " + medium.name,
                               geometry.D, w, axis.axis, 0.0, 0.0, geometry.x0, geometry.x1,
                               medium.sigma_s, medium.sigma_t, medium.g, 1.0};
                    spotScaleOffset(cone.inner, cone.outer, c.scale, c.offset);
                    appendPenumbraParts(c, cases);
                }
    // A fixed random sample: any light position, ray, axis and cone.
    std::mt19937 rng(20261202u);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), length(0.5, 30.0), logSigma(-3.0, 1.0),
        phase(-0.9, 0.9), angle(0.05, 1.0);
    for (int i = 0; i < 120; ++i) {
        const glm::dvec3 D = 10.0 * glm::dvec3(unit(rng), unit(rng), unit(rng));
        const glm::dvec3 ray = randomUnitDirection(rng);
        // The axis toward a random point of the ray's first 20 units, tilted: most rays cross the cone.
        const glm::dvec3 axis = glm::normalize(glm::normalize(20.0 * (unit(rng) + 1.0) * 0.5 * ray - D) +
                                               0.3 * randomUnitDirection(rng));
        const double inner = angle(rng), outer = inner + 0.02 + 0.5 * (unit(rng) + 1.0) * 0.5;
        const double sigma_t = std::pow(10.0, logSigma(rng));
        SpotCase c{"random " + std::to_string(i), D, ray, axis, 0.0, 0.0, 0.0, length(rng), 0.8 * sigma_t, sigma_t,
                   phase(rng), 1.0};
        spotScaleOffset(inner, outer, c.scale, c.offset);
        appendPenumbraParts(c, cases);
    }
    return cases;
}

}  // namespace viz::airlight::test
