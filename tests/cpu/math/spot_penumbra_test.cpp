// spotPenumbraSegment (viz/shared/airlight.h): the airlight of a spot light's penumbra, where KHR's
// A_spot = clamp(cd scale + offset, 0, 1)^2 is the square of a lobe in the integrand's own variable, against
// an independent long-double quadrature of the integral written in the ray's own parameter x, with A_spot
// and the phase function formed from 3D vectors; the float mirror against the double kernel; and the
// equal-angle pieces it replaced in polyvol, which converge to it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "cpu/math/spot_penumbra_cases.h"
#include "shared/airlight.h"

namespace viz::airlight::test {
namespace {

using LongReal = long double;

struct SpotReference {
    LongReal value = 0;
    LongReal ruleDifference = 0;  // |Gauss-Kronrod 61 - Gauss-Kronrod 31| / value
};

// int_x0^x1 sigma_s p(u . -w) I0 A_spot(u) exp(-sigma_t (x + r)) / r^2 dx, u = (x w - D) / r, in long double,
// piecewise between the segment ends, graded distances around the foot point P, the HG peak and optical
// depths from x0 (as the cosine-lobe test's reference).
SpotReference referenceSpotSegment(const SpotCase& c) {
    const LongReal sigma_s = c.sigma_s, sigma_t = c.sigma_t, g = c.g, I0 = c.I0;
    const LongReal pi = boost::math::constants::pi<LongReal>();
    auto f = [&](LongReal x) -> LongReal {
        const LongReal vx = x * c.w.x - c.D.x, vy = x * c.w.y - c.D.y, vz = x * c.w.z - c.D.z;
        const LongReal r = std::sqrt(vx * vx + vy * vy + vz * vz);
        const LongReal a = std::clamp(spotLinear(c, x), LongReal(0), LongReal(1));
        if (a == 0) return 0;
        const LongReal cosTheta = -(vx * c.w.x + vy * c.w.y + vz * c.w.z) / r;
        const LongReal p = (1 - g * g) / (4 * pi * std::pow(1 + g * g - 2 * g * cosTheta, LongReal(1.5)));
        return sigma_s * I0 * p * a * a * std::exp(-sigma_t * (x + r)) / (r * r);
    };
    const LongReal tP = c.D.x * c.w.x + c.D.y * c.w.y + c.D.z * c.w.z;
    const LongReal mx = c.D.x - tP * c.w.x, my = c.D.y - tP * c.w.y, mz = c.D.z - tP * c.w.z;
    const LongReal h = std::sqrt(mx * mx + my * my + mz * mz);
    const LongReal x0 = c.x0, x1 = c.x1;
    std::vector<LongReal> points{x0};
    auto add = [&](LongReal x) {
        if (x > x0 && x < x1) points.push_back(x);
    };
    for (LongReal k : {0.0L, 0.03L, 0.1L, 0.3L, 1.0L, 3.0L, 10.0L, 30.0L, 100.0L, 300.0L, 1e3L, 1e4L, 1e5L}) {
        add(tP + k * h);
        add(tP - k * h);
    }
    if (g != 0) {
        const LongReal yPeak = std::log((1 - std::abs(g)) / 2) * (g > 0 ? 1 : -1);
        for (LongReal dy : {-2.0L, -1.0L, 0.0L, 1.0L, 2.0L}) add(tP + h * std::sinh(yPeak + dy));
    }
    if (sigma_t > 0)
        for (int k = 1; k <= 60; ++k) add(x0 + LongReal(k) / (2 * sigma_t));
    std::sort(points.begin(), points.end());
    points.push_back(x1);
    SpotReference ref;
    LongReal coarse = 0;
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        const LongReal a = points[i], b = points[i + 1];
        if (!(b > a)) continue;
        ref.value += boost::math::quadrature::gauss_kronrod<LongReal, 61>::integrate(f, a, b, 0, 1e-14L);
        coarse += boost::math::quadrature::gauss_kronrod<LongReal, 31>::integrate(f, a, b, 0, 1e-14L);
    }
    ref.ruleDifference = ref.value > 0 ? std::abs(ref.value - coarse) / ref.value : std::abs(coarse);
    return ref;
}

double spotDouble(const SpotCase& c) {
    return spotPenumbraSegment<double>(c.D, c.w, c.axis, c.scale, c.offset, c.x0, c.x1, c.sigma_s, c.sigma_t, c.g,
                                       c.I0);
}

TEST(SpotPenumbraSegment, DoubleMatchesAnIndependentQuadratureInTheRayParameter) {
    double worst = 0;
    std::string worstName;
    int compared = 0;
    const std::vector<SpotCase> cases = spotPenumbraCases();
    for (const SpotCase& c : cases) {
        SCOPED_TRACE(c.name);
        const double value = spotDouble(c);
        ASSERT_TRUE(std::isfinite(value)) << value;
        ASSERT_GE(value, 0.0);
        const SpotReference ref = referenceSpotSegment(c);
        if (double(ref.value) < 1e-300) {
            EXPECT_LT(value, 1e-300);
            continue;
        }
        EXPECT_LT(double(ref.ruleDifference), 1e-11) << "reference rules disagree";
        const double error = std::abs(value - double(ref.value)) / double(ref.value);
        EXPECT_LT(error, 1e-9) << "value " << value << " reference " << double(ref.value);
        if (error >= worst) worst = error, worstName = c.name;
        ++compared;
    }
    EXPECT_GT(compared, 200);
    std::printf("  double spotPenumbraSegment vs long-double quadrature in x: %d penumbra parts, worst %.2e (%s)\n",
                compared, worst, worstName.c_str());
}

// The float kernel on the same float-rounded inputs: 1e-4 relative, what the GPU's copy is held to,
// widened for hard-edged cones: cd scale + offset rounds to about |offset| float epsilons, which
// A_spot = (cd scale + offset)^2 doubles relative to its value (a 0.01 rad penumbra has |offset| ~ 240).
TEST(SpotPenumbraSegment, FloatMirrorMatchesDouble) {
    double worst = 0;
    std::string worstName;
    for (const SpotCase& c : spotPenumbraCases()) {
        SCOPED_TRACE(c.name);
        const glm::vec3 D(c.D), w(c.w), axis(c.axis);
        const float value = spotPenumbraSegment<float>(D, w, axis, float(c.scale), float(c.offset), float(c.x0),
                                                       float(c.x1), float(c.sigma_s), float(c.sigma_t), float(c.g),
                                                       float(c.I0));
        const double reference = spotPenumbraSegment<double>(
            glm::dvec3(D), glm::dvec3(w), glm::dvec3(axis), double(float(c.scale)), double(float(c.offset)),
            double(float(c.x0)), double(float(c.x1)), double(float(c.sigma_s)), double(float(c.sigma_t)),
            double(float(c.g)), double(float(c.I0)));
        ASSERT_TRUE(std::isfinite(value));
        if (reference < 1e-30) {
            EXPECT_LT(value, 1e-30f);
            continue;
        }
        const double error = std::abs(double(value) - reference) / reference;
        EXPECT_LT(error, 1e-4 * std::max(1.0, std::abs(c.offset) / 64.0)) << "float " << value << " double " << reference;
        if (error >= worst) worst = error, worstName = c.name;
    }
    std::printf("  float spotPenumbraSegment vs double: worst %.2e (%s)\n", worst, worstName.c_str());
}

// What polyvol did before: equal-angle pieces, each the point light's exact segment times A_spot at its
// middle angle. They converge to the penumbra segment as the pieces shrink (four times the pieces, at
// least eight times less error), but 8 pieces, the old default, are far off where the medium is thick: the
// integrand decays across a piece, and A_spot at its middle stands for a stretch lit mostly at its start.
TEST(SpotPenumbraSegment, EqualAnglePiecesConvergeToIt) {
    auto pieces = [](const SpotCase& c, int n) {
        const RayLightGeometry<double> geo = rayLightGeometry<double>(c.D, c.w);
        const double phi0 = std::atan((c.x0 - geo.tP) / geo.h), phi1 = std::atan((c.x1 - geo.tP) / geo.h);
        double sum = 0, xa = c.x0;
        for (int k = 0; k < n; ++k) {
            const double xb = k + 1 == n ? c.x1 : geo.tP + geo.h * std::tan(phi0 + (phi1 - phi0) * (k + 1) / n);
            const double xm = geo.tP + geo.h * std::tan(phi0 + (phi1 - phi0) * (k + 0.5) / n);
            const double a = std::clamp(double(spotLinear(c, xm)), 0.0, 1.0);
            sum += a * a * pointSegment<double>(geo.tP, geo.h, xa, xb, c.sigma_s, c.sigma_t, c.g, c.I0);
            xa = xb;
        }
        return sum;
    };
    double worst8 = 0, worst32 = 0;
    std::string worstName;
    int compared = 0;
    for (const SpotCase& c : spotPenumbraCases()) {
        const double exact = spotDouble(c);
        if (!(exact > 1e-250)) continue;
        const double e8 = std::abs(pieces(c, 8) - exact) / exact, e32 = std::abs(pieces(c, 32) - exact) / exact;
        if (e8 > worst8) worstName = c.name + " (32 pieces " + std::to_string(e32) + ")";
        worst8 = std::max(worst8, e8);
        worst32 = std::max(worst32, e32);
        ++compared;
    }
    EXPECT_GT(compared, 200);
    EXPECT_LT(worst32, worst8 / 8.0);
    std::printf("  equal-angle pieces vs the penumbra segment, %d parts: 8 pieces worst %.2e, 32 pieces %.2e\n",
                compared, worst8, worst32);
    std::printf("  worst: %s\n", worstName.c_str());
}

}  // namespace
}  // namespace viz::airlight::test
