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

#include "cpu/math/ray_parameter_quadrature.h"
#include "cpu/math/spot_penumbra_cases.h"
#include "shared/airlight.h"

namespace viz::airlight::test {
namespace {

using LongReal = long double;

// int_x0^x1 sigma_s p(u . -w) I0 A_spot(u) exp(-sigma_t (x + r)) / r^2 dx, u = (x w - D) / r.
RayParameterIntegral referenceSpotSegment(const SpotCase& c) {
    auto f = [&](LongReal x) -> LongReal {
        const LongReal vx = x * c.w.x - c.D.x, vy = x * c.w.y - c.D.y, vz = x * c.w.z - c.D.z;
        const LongReal r = std::sqrt(vx * vx + vy * vy + vz * vz);
        const LongReal a = std::clamp(spotLinear(c, x), LongReal(0), LongReal(1));
        if (a == 0) return 0;
        const LongReal cosTheta = -(vx * c.w.x + vy * c.w.y + vz * c.w.z) / r;
        return c.sigma_s * c.I0 * textbookPhase(cosTheta, c.g) * a * a * std::exp(-c.sigma_t * (x + r)) / (r * r);
    };
    return integrateAlongRay(f, c.D, c.w, c.x0, c.x1, c.sigma_t, c.g);
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
        const RayParameterIntegral ref = referenceSpotSegment(c);
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
