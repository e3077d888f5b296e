// An independent reference for pointSegment: adaptive Boost.Math quadrature in long double
// (docs/numerics.md#long-double-quadrature), written separately from the Gauss-Legendre kernel in
// viz/shared/airlight.h. Integrates in y = asinh(s/h) with break points at the segment ends, the closest
// approach, the HG peak, every 2 units of y and at optical depths 2^k from the segment start; tanh-sinh
// and Gauss-Kronrod (61 points) on every piece, so the two rules check each other.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>

namespace viz::airlight::test {

using LongReal = long double;

struct ReferenceValue {
    LongReal value = 0;
    LongReal ruleDifference = 0;  // |tanh-sinh - Gauss-Kronrod| / value
};

// Henyey-Greenstein in the textbook form (independent of the kernel's (1-g)^2 + 2g(1-cos) rewrite, but
// evaluated from 1 - cos to keep the forward peak accurate).
inline LongReal referencePhase(LongReal oneMinusCos, LongReal g) {
    const LongReal pi = boost::math::constants::pi<LongReal>();
    const LongReal denom = 1 + g * g - 2 * g * (1 - oneMinusCos);
    return (1 - g * g) / (4 * pi * std::pow(denom, LongReal(1.5)));
}

// L(x0, x1) for a point light at (tP, h), h > 0; x1 may be +inf.
inline ReferenceValue referencePointSegment(double tPd, double hd, double x0d, double x1d, double sigma_sd,
                                            double sigma_td, double gd, double I0d) {
    const LongReal tP = tPd, h = hd, x0 = x0d, x1 = x1d, sigma_s = sigma_sd, sigma_t = sigma_td, g = gd,
                   I0 = I0d;
    const LongReal inf = std::numeric_limits<LongReal>::infinity();
    const LongReal s0 = x0 - tP;
    const LongReal r0 = std::hypot(s0, h);
    const LongReal q0 = s0 >= 0 ? s0 + r0 : h * h / (r0 - s0);
    const LongReal y0 = std::asinh(s0 / h);
    LongReal y1 = inf;
    if (!std::isinf(x1)) {
        const LongReal s1 = x1 - tP;
        const LongReal r1 = std::hypot(s1, h);
        const LongReal q1 = s1 >= 0 ? s1 + r1 : h * h / (r1 - s1);
        y1 = y0 + std::log1p((x1 - x0) * (q1 + q0) / ((r1 + r0) * q0));
    }
    const LongReal nu = sigma_t * q0;

    // Integrand in y without the constant e^{-sigma_t (x0 + r0)}: sigma_s I0 p e^{-sigma_t (q - q0)} / r,
    // with q - q0 = q0 expm1(y - y0) and r = h cosh(y).
    auto f = [&](LongReal y) -> LongReal {
        const LongReal attenuation = nu > 0 ? std::exp(-nu * std::expm1(y - y0)) : LongReal(1);
        if (attenuation == 0) return 0;
        const LongReal c = std::cosh(y);
        if (std::isinf(c)) return 0;
        const LongReal oneMinusCos = 1 + std::tanh(y);
        const LongReal p = g == 0 ? 1 / (4 * boost::math::constants::pi<LongReal>())
                                  : referencePhase(oneMinusCos, g);
        return sigma_s * I0 * p * attenuation / (h * c);
    };

    std::vector<LongReal> points{y0};
    auto addPoint = [&](LongReal y) {
        if (y > y0 && y < y1) points.push_back(y);
    };
    addPoint(0);
    if (std::abs(g) > 0) {
        const LongReal yPeak = std::log((1 - std::abs(g)) / 2);
        addPoint(g > 0 ? yPeak : -yPeak);
    }
    for (int k = -40; k <= 40; ++k) addPoint(2 * LongReal(k));
    if (sigma_t > 0) {
        for (int k = -6; k <= 10; ++k) addPoint(std::log((q0 + std::ldexp(LongReal(1), k) / sigma_t) / h));
    }
    std::sort(points.begin(), points.end());
    if (!std::isinf(y1)) points.push_back(y1);
    // Merge break points that nearly coincide: a sliver piece only makes the adaptive rules chase
    // rounding noise.
    std::vector<LongReal> merged{points.front()};
    for (size_t i = 1; i < points.size(); ++i) {
        if (points[i] - merged.back() > 1e-6L || i + 1 == points.size()) merged.push_back(points[i]);
    }
    if (merged.size() > 2 && merged[merged.size() - 1] - merged[merged.size() - 2] <= 1e-6L) {
        merged.erase(merged.end() - 2);
    }
    points = merged;

    boost::math::quadrature::tanh_sinh<LongReal> tanhSinh;
    boost::math::quadrature::exp_sinh<LongReal> expSinh;
    const LongReal tol = 1e-14L;
    LongReal a = 0, b = 0;
    for (size_t i = 0; i + 1 < points.size(); ++i) {
        if (!(points[i + 1] > points[i])) continue;
        // Integrate over t = y - points[i] in [0, width]: tanh-sinh abscissae must not round onto the
        // end points, which happens for slivers whose width is tiny next to |y|.
        const LongReal start = points[i], width = points[i + 1] - points[i];
        auto shifted = [&](LongReal t) { return f(start + t); };
        a += tanhSinh.integrate(shifted, LongReal(0), width, tol);
        b += boost::math::quadrature::gauss_kronrod<LongReal, 61>::integrate(shifted, LongReal(0), width, 10,
                                                                            tol);
    }
    if (std::isinf(y1)) {
        a += expSinh.integrate(f, points.back(), inf, tol);
        b += boost::math::quadrature::gauss_kronrod<LongReal, 61>::integrate(f, points.back(), inf, 10, tol);
    }
    ReferenceValue result;
    const LongReal anchor = std::exp(-sigma_t * (x0 + r0));
    result.value = a * anchor;
    result.ruleDifference = a > 0 ? std::abs(a - b) / a : 0;
    return result;
}

}  // namespace viz::airlight::test
