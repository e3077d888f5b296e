// An independent reference for the kernels with an angular factor (cosineLobeSegment, spotPenumbraSegment):
// the integral written in the ray's own parameter x, integrated in long double by Gauss-Kronrod rules of
// 61 and 31 points on pieces between break points at the segment ends, graded distances around the foot
// point P (the 1/r^2 peak of width h), the HG lobe's peak and optical depths from x0, plus any the caller
// adds (an emitter's plane). No log-tangent substitution, unlike the kernels and airlight_reference.h.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <glm/glm.hpp>

namespace viz::airlight::test {

struct RayParameterIntegral {
    long double value = 0;
    long double ruleDifference = 0;  // |Gauss-Kronrod 61 - Gauss-Kronrod 31| / value
};

// Henyey-Greenstein from the cosine as written in the textbook, cosTheta = u . -w (+1: forward).
inline long double textbookPhase(long double cosTheta, long double g) {
    const long double pi = boost::math::constants::pi<long double>();
    return (1 - g * g) / (4 * pi * std::pow(1 + g * g - 2 * g * cosTheta, 1.5L));
}

// int_x0^x1 f(x) dx for a light at D (camera-relative) seen along the unit ray w, medium (sigma_t, g).
template <typename F>
RayParameterIntegral integrateAlongRay(F f, const glm::dvec3& D, const glm::dvec3& w, long double x0, long double x1,
                                       long double sigma_t, long double g, std::vector<long double> points = {}) {
    const long double tP = D.x * w.x + D.y * w.y + D.z * w.z;
    const long double mx = D.x - tP * w.x, my = D.y - tP * w.y, mz = D.z - tP * w.z;
    const long double h = std::sqrt(mx * mx + my * my + mz * mz);
    auto add = [&](long double x) {
        if (x > x0 && x < x1) points.push_back(x);
    };
    std::vector<long double> inside;
    inside.swap(points);
    for (long double x : inside) add(x);
    for (long double k : {0.0L, 0.03L, 0.1L, 0.3L, 1.0L, 3.0L, 10.0L, 30.0L, 100.0L, 300.0L, 1e3L, 1e4L, 1e5L, 1e6L}) {
        add(tP + k * h);
        add(tP - k * h);
    }
    if (g != 0) {
        // The HG peak at scattering angle 0, graded around y = yPeak (s = h sinh(y)).
        const long double yPeak = std::log((1 - std::abs(g)) / 2) * (g > 0 ? 1 : -1);
        for (long double dy : {-2.0L, -1.0L, 0.0L, 1.0L, 2.0L}) add(tP + h * std::sinh(yPeak + dy));
    }
    if (sigma_t > 0)
        for (int k = 1; k <= 60; ++k) add(x0 + static_cast<long double>(k) / (2 * sigma_t));
    points.push_back(x0);
    std::sort(points.begin(), points.end());
    points.push_back(x1);
    RayParameterIntegral result;
    long double coarse = 0;
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        const long double a = points[i], b = points[i + 1];
        if (!(b > a)) continue;
        result.value += boost::math::quadrature::gauss_kronrod<long double, 61>::integrate(f, a, b, 0, 1e-14L);
        coarse += boost::math::quadrature::gauss_kronrod<long double, 31>::integrate(f, a, b, 0, 1e-14L);
    }
    result.ruleDifference = result.value > 0 ? std::abs(result.value - coarse) / result.value : std::abs(coarse);
    return result;
}

}  // namespace viz::airlight::test
