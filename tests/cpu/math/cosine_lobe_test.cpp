// cosineLobeSegment (viz/shared/airlight.h): the airlight of an emitter with a cosine lobe (an area light's
// VPL) along a segment, against an independent long-double quadrature of the integral as written in the
// ray's own parameter x, with the lobe max(0, n . u) and the phase function formed from 3D vectors (no
// log-tangent substitution, no split of the lobe into sech and tanh parts); and the float mirror against
// the double kernel.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "cpu/math/cosine_lobe_cases.h"
#include "cpu/math/ray_parameter_quadrature.h"
#include "shared/airlight.h"

namespace viz::airlight::test {
namespace {

using LongReal = long double;
using LongVec = glm::vec<3, LongReal>;

// int_x0^x1 sigma_s p(u . -w) I0 max(0, n . u) exp(-sigma_t (x + r)) / r^2 dx, r = |x w - D|,
// u = (x w - D) / r the direction from the light, with a break point at the emitter's plane.
RayParameterIntegral referenceLobeSegment(const LobeCase& c) {
    const LongVec D(c.D), w(c.w), n(c.n);
    const LongReal sigma_s = c.sigma_s, sigma_t = c.sigma_t, g = c.g, I0 = c.I0;
    auto f = [&](LongReal x) -> LongReal {
        const LongVec v = x * w - D;
        const LongReal r = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
        const LongVec u = v / r;
        const LongReal lobe = std::max(LongReal(0), n.x * u.x + n.y * u.y + n.z * u.z);
        if (lobe == 0) return 0;
        const LongReal cosTheta = -(u.x * w.x + u.y * w.y + u.z * w.z);
        return sigma_s * I0 * textbookPhase(cosTheta, g) * lobe * std::exp(-sigma_t * (x + r)) / (r * r);
    };
    std::vector<LongReal> plane;
    const LongReal wn = w.x * n.x + w.y * n.y + w.z * n.z;
    if (wn != 0) plane.push_back((D.x * n.x + D.y * n.y + D.z * n.z) / wn);
    return integrateAlongRay(f, c.D, c.w, c.x0, c.x1, sigma_t, g, plane);
}

double lobeDouble(const LobeCase& c) {
    return cosineLobeSegment<double>(c.D, c.w, c.n, c.x0, c.x1, c.sigma_s, c.sigma_t, c.g, c.I0);
}

TEST(CosineLobeSegment, DoubleMatchesAnIndependentQuadratureInTheRayParameter) {
    double worst = 0;
    std::string worstName;
    int compared = 0, zero = 0;
    for (const LobeCase& c : cosineLobeCases()) {
        SCOPED_TRACE(c.name);
        const double value = lobeDouble(c);
        ASSERT_TRUE(std::isfinite(value)) << value;
        ASSERT_GE(value, 0.0);
        const RayParameterIntegral ref = referenceLobeSegment(c);
        if (ref.value == 0) {
            // The whole segment behind the emitter: nothing, exactly.
            EXPECT_EQ(value, 0.0);
            ++zero;
            continue;
        }
        if (double(ref.value) < 1e-300) {
            // Below double's range (a thick medium far from the light): the kernel flushes to 0 too.
            EXPECT_LT(value, 1e-300);
            continue;
        }
        EXPECT_LT(double(ref.ruleDifference), 1e-11) << "reference rules disagree";
        const double error = std::abs(value - double(ref.value)) / double(ref.value);
        EXPECT_LT(error, 1e-9) << "value " << value << " reference " << double(ref.value);
        if (error >= worst) worst = error, worstName = c.name;
        ++compared;
    }
    EXPECT_GT(compared, 150);
    EXPECT_GT(zero, 10);
    std::printf("  double cosineLobeSegment vs long-double quadrature in x: %d cases (and %d zero), worst %.2e (%s)\n",
                compared, zero, worst, worstName.c_str());
}

// The float kernel on the same float-rounded inputs: 1e-4 relative, what the GPU's copy is held to.
TEST(CosineLobeSegment, FloatMirrorMatchesDouble) {
    double worst = 0;
    std::string worstName;
    for (const LobeCase& c : cosineLobeCases()) {
        SCOPED_TRACE(c.name);
        const glm::vec3 D(c.D), w(c.w), n(c.n);
        const float value = cosineLobeSegment<float>(D, w, n, float(c.x0), float(c.x1), float(c.sigma_s),
                                                     float(c.sigma_t), float(c.g), float(c.I0));
        const double reference = cosineLobeSegment<double>(glm::dvec3(D), glm::dvec3(w), glm::dvec3(n), double(float(c.x0)),
                                                           double(float(c.x1)), double(float(c.sigma_s)),
                                                           double(float(c.sigma_t)), double(float(c.g)), c.I0);
        ASSERT_TRUE(std::isfinite(value));
        if (reference < 1e-30) {
            EXPECT_LT(value, 1e-30f);
            continue;
        }
        const double error = std::abs(double(value) - reference) / reference;
        EXPECT_LT(error, 1e-4) << "float " << value << " double " << reference;
        if (error >= worst) worst = error, worstName = c.name;
    }
    std::printf("  float cosineLobeSegment vs double: worst %.2e (%s)\n", worst, worstName.c_str());
}

// An emitter facing n and one facing -n together emit I0 (max(0, n . u) + max(0, -n . u)) = I0 |n . u| <= I0
// toward every u: each, and the two together, stay below the point light's integral (the kernel with A = 1,
// whose own accuracy airlight_test.cpp checks), up to the quadrature's rounding on different panels.
TEST(CosineLobeSegment, EachHalfOfTheSphereStaysBelowThePointLight) {
    for (const LobeCase& c : cosineLobeCases()) {
        SCOPED_TRACE(c.name);
        const RayLightGeometry<double> geometry = rayLightGeometry<double>(c.D, c.w);
        const double point =
            pointSegment<double>(geometry.tP, geometry.h, c.x0, c.x1, c.sigma_s, c.sigma_t, c.g, c.I0);
        LobeCase back = c;
        back.n = -c.n;
        const double front = lobeDouble(c), behind = lobeDouble(back);
        EXPECT_LE(front, point * (1 + 1e-10));
        EXPECT_LE(behind, point * (1 + 1e-10));
        EXPECT_LE(front + behind, point * (1 + 1e-10));
    }
}

}  // namespace
}  // namespace viz::airlight::test
