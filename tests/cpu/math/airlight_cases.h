// The grid of airlight segment cases shared by the CPU math tests and the GLSL test: every stiff input of
// docs/numerics.md#stiff-inputs-of-the-kernel (each with isotropic and Henyey-Greenstein phase functions)
// plus a fixed random sample. Inputs are plain doubles; the float and GLSL tests round them to float.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "shared/airlight.h"

namespace viz::airlight::test {

struct SegmentCase {
    std::string group;  // stiff-case family, for per-group error reports
    std::string name;
    double tP, h, x0, x1, sigma_s, sigma_t, g, I0;
    double cosTheta;  // for directionalSegment / phaseHG checks on the same grid
};

inline constexpr double kInf = std::numeric_limits<double>::infinity();

// The h actually used by pointSegment<Real> (its documented floor for rays through the light), so that
// an exact reference integrates the same problem.
template <typename Real = double>
inline double flooredH(double tP, double h, double x0, double x1) {
    const double s0 = x0 - tP, s1 = x1 - tP;
    const bool inside = s0 <= 0.0 && s1 >= 0.0;
    double scale = inside ? std::max(std::abs(s0), std::isinf(s1) ? 0.0 : s1)
                          : std::min(std::abs(s0), std::abs(s1));
    if (scale == 0.0) scale = std::abs(tP);
    return std::max(h, std::max(double(Precision<Real>::kMinRelativeH) * scale, kMinAbsoluteH));
}

inline std::vector<SegmentCase> airlightCaseGrid() {
    struct Geometry {
        const char* group;
        const char* name;
        double tP, h, x0, x1, sigma_t, sigma_s, I0;
    };
    // World-offset case: geometry from world coordinates, camera-relative in double
    // (docs/numerics.md#camera-relative-coordinates).
    const glm::dvec3 cam(1e4, 1e4, 0.0), light(1e4 + 5.0, 1e4 + 1e-2, 0.0), dir(1.0, 0.0, 0.0);
    const auto world = rayLightGeometry<double>(light - cam, dir);
    const double sliver = std::ldexp(1.0, -10);

    const Geometry geometries[] = {
        {"baseline", "baseline", 5, 1, 0, 10, 0.1, 0.1, 1},
        {"thin", "thin 1e-6", 5, 1, 0, 10, 1e-6, 1e-6, 1},
        {"thin", "thin 1e-20", 5, 1, 0, 10, 1e-20, 1e-20, 1e20},
        {"zero", "sigma 0", 5, 1, 0, 10, 0, 1, 1},
        {"zero", "sigma 0 grazing", 5, 0.05, 0, 10, 0, 1, 1},
        {"zero", "sigma 0 sky", 5, 1, 0, kInf, 0, 1, 1},
        {"thick", "thick side", 0.5, 4, 0, 10, 5, 5, 1e12},
        {"thick", "thick through P", 5, 1, 0, 10, 20, 20, 1e30},
        {"thick", "thick far light", 30, 0.2, 0, 60, 3, 3, 1e30},
        {"behind", "behind e^20", -20, 1, 0, 10, 1, 1, 1e12},
        {"behind", "behind e^100", -20, 1, 0, 10, 5, 5, 1e30},
        {"behind", "behind sky", -3, 2, 0, kInf, 0.01, 0.01, 1},
        {"near-inside", "h 1e-5", 5, 1e-5, 0, 10, 0.1, 0.1, 1},
        {"near-inside", "h at floor", 5, 5e-7, 0, 10, 0.1, 0.1, 1},
        {"near-inside", "h 1e-3 sky", 5, 1e-3, 0, kInf, 0.1, 0.1, 1},
        {"axis-outside", "axis ahead", 20, 2e-6, 0, 10, 0.1, 0.1, 1},
        {"axis-outside", "axis behind", -5, 1e-6, 0, 10, 0.5, 0.5, 1},
        {"axis-outside", "axis ahead h=0", 20, 0, 0, 10, 0.1, 0.1, 1},
        {"axis-outside", "axis behind h=0", -5, 0, 0, 10, 0.5, 0.5, 1},
        {"beyond", "P beyond", 100, 3, 0, 10, 0.05, 0.05, 1},
        {"beyond", "P far beyond", 1000, 10, 0, 10, 0.01, 0.01, 1},
        {"sky", "d 1e6", 5, 1, 0, 1e6, 0.1, 0.1, 1},
        {"sky", "d inf", 5, 1, 0, kInf, 0.1, 0.1, 1},
        {"sky", "d inf thin", 5, 1, 0, kInf, 1e-6, 1e-6, 1},
        {"large-u", "u 25", 5, 50, 0, 10, 0.5, 0.5, 1e12},
        {"large-u", "u 500", 5, 1000, 0, 10, 0.5, 0.5, 1e30},
        {"world", "world 1e4", world.tP, world.h, 0, 10, 0.1, 0.1, 1},
        {"sliver", "sliver 2^-10", 5, 1, 7, 7 + sliver, 0.1, 0.1, 1},
        {"sliver", "sliver at P", 5, 1e-3, 5 - 1e-4, 5 + 1e-4, 0.1, 0.1, 1},
        {"sliver", "sliver far from P", 100, 3, 50, 50 + 1e-4, 0.05, 0.05, 1},
        {"sliver", "sliver light behind", -20, 1, 3, 3 + sliver, 1, 1, 1e12},
    };
    const double gs[] = {0.0, 0.9, 0.99, -0.9};

    std::vector<SegmentCase> cases;
    for (const Geometry& geo : geometries) {
        for (double g : gs) {
            SegmentCase c;
            c.group = g == 0.0 ? geo.group : std::string(geo.group) + "/hg";
            c.name = std::string(geo.name) + " g=" + std::to_string(g).substr(0, 5);
            c.tP = geo.tP;
            c.h = geo.h;
            c.x0 = geo.x0;
            c.x1 = geo.x1;
            c.sigma_s = geo.sigma_s;
            c.sigma_t = geo.sigma_t;
            c.g = g;
            c.I0 = geo.I0;
            c.cosTheta = -0.3;
            cases.push_back(c);
        }
    }

    // Random sample: log-uniform scales, fixed seed. Uniform doubles are built from raw 64-bit draws so
    // the sequence is the same with every standard library.
    std::mt19937_64 rng(20261122u);
    auto uniform = [&rng](double lo, double hi) {
        const double u = double(rng() >> 11) * 0x1.0p-53;
        return lo + (hi - lo) * u;
    };
    for (int i = 0; i < 300; ++i) {
        SegmentCase c;
        c.group = "random";
        c.name = "random " + std::to_string(i);
        c.tP = uniform(-50.0, 80.0);
        c.h = std::pow(10.0, uniform(-5.0, 2.0));
        c.x0 = uniform(0.0, 1.0) < 0.5 ? 0.0 : uniform(0.0, 40.0);
        const double kind = uniform(0.0, 1.0);
        c.x1 = kind < 0.1 ? kInf : c.x0 + std::pow(10.0, uniform(-4.0, 3.0));
        c.sigma_t = uniform(0.0, 1.0) < 0.05 ? 0.0 : std::pow(10.0, uniform(-8.0, 1.3));
        c.sigma_s = c.sigma_t > 0.0 ? c.sigma_t * uniform(0.1, 1.0) : 0.5;
        c.g = uniform(0.0, 1.0) < 0.4 ? 0.0 : uniform(-0.95, 0.99);
        c.I0 = std::pow(10.0, uniform(-2.0, 6.0));
        c.cosTheta = uniform(-1.0, 1.0);
        cases.push_back(c);
    }
    return cases;
}

// Float-representable copy of a case (what a GPU receives), so double and float see the same problem.
inline SegmentCase roundedToFloat(SegmentCase c) {
    auto f = [](double v) { return double(float(v)); };
    c.tP = f(c.tP);
    c.h = f(c.h);
    c.x0 = f(c.x0);
    c.x1 = f(c.x1);
    c.sigma_s = f(c.sigma_s);
    c.sigma_t = f(c.sigma_t);
    c.g = f(c.g);
    c.I0 = f(c.I0);
    c.cosTheta = f(c.cosTheta);
    return c;
}

inline bool isNormalFloat(double v) {
    return v >= double(std::numeric_limits<float>::min()) && v <= double(std::numeric_limits<float>::max());
}

}  // namespace viz::airlight::test
