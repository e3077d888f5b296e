// Tests of viz/shared/airlight.h: the double kernel against an independent long-double Boost.Math
// quadrature on every stiff input of docs/numerics.md#stiff-inputs-of-the-kernel, against closed forms
// (sigma_t = 0, h = 0, directional light), against mpmath values from airlight_ref.py, and the float
// mirror against double.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/special_functions/expint.hpp>

#include "cpu/math/airlight_cases.h"
#include "cpu/math/airlight_reference.h"
#include "shared/airlight.h"

namespace viz::airlight::test {
namespace {

double relativeError(double value, double reference) {
    if (value == reference) return 0.0;
    return std::abs(value - reference) / std::abs(reference);
}

// Worst relative error per case group, printed at the end of a test for the report.
class WorstByGroup {
public:
    void add(const std::string& group, const std::string& name, double error) {
        Entry& e = mWorst[group];
        ++e.count;
        if (error >= e.error) {
            e.error = error;
            e.name = name;
        }
    }
    void print(const char* title) const {
        std::printf("  %s\n", title);
        for (const auto& [group, e] : mWorst) {
            std::printf("    %-20s %4d cases  worst %.2e  (%s)\n", group.c_str(), e.count, e.error,
                        e.name.c_str());
        }
    }

private:
    struct Entry {
        double error = 0;
        int count = 0;
        std::string name;
    };
    std::map<std::string, Entry> mWorst;
};

double pointDouble(const SegmentCase& c) {
    return pointSegment<double>(c.tP, c.h, c.x0, c.x1, c.sigma_s, c.sigma_t, c.g, c.I0);
}

float pointFloat(const SegmentCase& c) {
    return pointSegment<float>(float(c.tP), float(c.h), float(c.x0), float(c.x1), float(c.sigma_s),
                               float(c.sigma_t), float(c.g), float(c.I0));
}

// ---- point light, double vs Boost ----------------------------------------------------------------

TEST(AirlightPointSegment, DoubleMatchesBoostQuadratureOnStiffGrid) {
    WorstByGroup worst;
    int compared = 0;
    for (const SegmentCase& c : airlightCaseGrid()) {
        SCOPED_TRACE(c.name);
        const double value = pointDouble(c);
        ASSERT_TRUE(std::isfinite(value));
        ASSERT_GE(value, 0.0);
        const ReferenceValue ref = referencePointSegment(c.tP, flooredH(c.tP, c.h, c.x0, c.x1), c.x0, c.x1,
                                                         c.sigma_s, c.sigma_t, c.g, c.I0);
        // The reference is only a reference if its two rules agree.
        EXPECT_LT(double(ref.ruleDifference), 1e-12);
        if (double(ref.value) > 1e-300) {
            const double error = relativeError(value, double(ref.value));
            EXPECT_LT(error, 1e-9) << "value " << value << " reference " << double(ref.value);
            worst.add(c.group, c.name, error);
            ++compared;
        }
    }
    EXPECT_GT(compared, 300);
    worst.print("double pointSegment vs Boost long-double quadrature (relative error):");
}

// ---- float mirror vs double -----------------------------------------------------------------------

TEST(AirlightPointSegment, FloatMirrorMatchesDoubleOnStiffGrid) {
    WorstByGroup worst;
    for (const SegmentCase& original : airlightCaseGrid()) {
        // Both precisions see the same float-representable problem (what a GPU receives), with h raised
        // to float's floor where float's is the higher one (rays through the light, where each
        // precision documents its own floor).
        const SegmentCase c = roundedToFloat(original);
        SCOPED_TRACE(c.name);
        SegmentCase forDouble = c;
        forDouble.h = flooredH<float>(c.tP, c.h, c.x0, c.x1);
        const double reference = pointDouble(forDouble);
        const float value = pointFloat(c);
        ASSERT_TRUE(std::isfinite(value));
        ASSERT_GE(value, 0.0f);
        if (isNormalFloat(reference)) {
            const double error = relativeError(value, reference);
            EXPECT_LT(error, 1e-4) << "float " << value << " double " << reference;
            worst.add(c.group, c.name, error);
        } else {
            EXPECT_LE(std::abs(double(value) - reference), 2.0 * double(std::numeric_limits<float>::min()));
        }
    }
    worst.print("float pointSegment vs double (relative error, normal-float values):");
}

TEST(AirlightPointSegment, NoNanOrInfOnDegenerateInputs) {
    const double inf = kInf;
    // tP, h, x0, x1, sigma_s, sigma_t, g, I0
    const double inputs[][8] = {
        {0, 0, 0, 10, 0.1, 0.1, 0, 1},         // light at the eye
        {0, 0, 0, inf, 0.1, 0.1, 0.9, 1},      // light at the eye, sky
        {5, 0, 0, 10, 0.1, 0.1, 0, 1},         // ray exactly through the light
        {5, 0, 0, inf, 0, 0.5, 0.99, 1},       // through the light, no extinction, sky
        {5, 0, 5, 10, 0.1, 0.1, -0.9, 1},      // segment starting at the light
        {5, 0, 0, 5, 0.1, 0.1, 0, 1},          // segment ending at the light
        {5, 1, 3, 3, 0.1, 0.1, 0, 1},          // empty segment
        {5, 1, 0, 10, 0, 0, 0, 1},             // no medium at all
        {5, 1, 0, 10, 0.1, 0.1, 0, 0},         // dark light
        {1e30, 1e30, 0, 1e30, 0.1, 0.1, 0, 1e30},  // huge scales (float overflow of squares)
        {1e-30, 1e-30, 0, 1e-29, 0.1, 0.1, 0, 1},  // tiny scales
        {5, 1, 0, 10, 1e3, 1e3, 0, 1e30},      // extremely thick: underflows to 0
        {-1e4, 1, 0, inf, 1, 1, 0, 1e30},      // light far behind, thick
        {5, 1, 0, 1e38, 0.1, 0.1, 0.5, 1},     // finite but enormous x1
    };
    for (const auto& in : inputs) {
        SCOPED_TRACE(::testing::Message() << "tP " << in[0] << " h " << in[1] << " x0 " << in[2] << " x1 "
                                          << in[3] << " sigma_t " << in[5]);
        const double d = pointSegment<double>(in[0], in[1], in[2], in[3], in[4], in[5], in[6], in[7]);
        const float f = pointSegment<float>(float(in[0]), float(in[1]), float(in[2]), float(in[3]),
                                            float(in[4]), float(in[5]), float(in[6]), float(in[7]));
        EXPECT_TRUE(std::isfinite(d));
        EXPECT_TRUE(std::isfinite(f));
        EXPECT_GE(d, 0.0);
        EXPECT_GE(f, 0.0f);
    }
}

// ---- closed forms and identities ---------------------------------------------------------------------

TEST(AirlightPointSegment, AdditiveOverSplitPoints) {
    const double fractions[] = {0.001, 0.25, 0.5, 0.9};
    int checked = 0;
    for (const SegmentCase& c : airlightCaseGrid()) {
        for (double u : fractions) {
            const double xm = std::isinf(c.x1) ? c.x0 + 1000.0 * u : c.x0 + (c.x1 - c.x0) * u;
            // The h floor depends on the segment; compare only where none of the three is floored.
            if (flooredH(c.tP, c.h, c.x0, c.x1) != c.h || flooredH(c.tP, c.h, c.x0, xm) != c.h ||
                flooredH(c.tP, c.h, xm, c.x1) != c.h) {
                continue;
            }
            const double whole = pointDouble(c);
            if (!(whole > 1e-300)) continue;
            SegmentCase left = c, right = c;
            left.x1 = xm;
            right.x0 = xm;
            SCOPED_TRACE(c.name + " split at " + std::to_string(xm));
            EXPECT_LT(relativeError(pointDouble(left) + pointDouble(right), whole), 1e-9);
            ++checked;
        }
    }
    EXPECT_GT(checked, 1000);
}

TEST(AirlightPointSegment, ZeroExtinctionMatchesAtan2Form) {
    // sigma_t = 0, isotropic: L = sigma_s I0 / (4 pi h) * (atan(s1/h) - atan(s0/h)), written as
    // atan2(h (s1 - s0), h^2 + s0 s1), valid also when P is inside the segment
    // (docs/numerics.md#closed-forms-for-zero-extinction).
    struct Case {
        double tP, h, x0, x1;
    };
    const Case cases[] = {{5, 1, 0, 10},   {5, 0.05, 0, 10}, {20, 1, 0, 10},     {-3, 0.2, 0, 10},
                          {5, 1e-4, 0, 10}, {5, 1, 7, 7.001}, {100, 3, 0, 10},   {5, 1, 0, kInf},
                          {-5, 2, 1, kInf}, {0, 1, 0, 1e6},   {1e3, 1e-2, 0, 2e3}};
    const long double pi = boost::math::constants::pi<long double>();
    for (const Case& c : cases) {
        SCOPED_TRACE(::testing::Message() << "tP " << c.tP << " h " << c.h << " [" << c.x0 << ", " << c.x1 << "]");
        const long double s0 = (long double)c.x0 - c.tP, s1 = (long double)c.x1 - c.tP, h = c.h;
        const long double angle = std::isinf(c.x1) ? std::atan2(h, s0) : std::atan2(h * (s1 - s0), h * h + s0 * s1);
        const double expected = double(2.5L * 3.0L / (4.0L * pi * h) * angle);
        const double value = pointSegment<double>(c.tP, c.h, c.x0, c.x1, 2.5, 0.0, 0.0, 3.0);
        EXPECT_LT(relativeError(value, expected), 1e-10) << value << " vs " << expected;
        const float valueF = pointSegment<float>(float(c.tP), float(c.h), float(c.x0), float(c.x1), 2.5f,
                                                 0.0f, 0.0f, 3.0f);
        EXPECT_LT(relativeError(valueF, expected), 1e-4);
    }
}

TEST(AirlightPointSegment, RayThroughLightMatchesClosedFormsWithFootPointOutside) {
    // h = 0 closed forms (isotropic; docs/numerics.md#closed-forms-for-a-ray-through-the-light). The kernel
    // floors h at kMinRelativeH (1e-13 in double) of the distance from the foot point to the nearer end,
    // which changes L by O((h / s)^2) relative: far below rounding.
    const long double pi = boost::math::constants::pi<long double>();
    struct Case {
        double tP, x0, x1, sigma;
    };
    // Light ahead of the segment: x + r = tP is constant, L = c e^{-sigma tP} (1/|s1| - 1/|s0|).
    for (const Case& c : {Case{20, 0, 10, 0.1}, Case{20, 3, 19, 1.0}, Case{1e3, 0, 10, 0.01}, Case{6, 0, 5.9, 2}}) {
        const long double s0 = (long double)c.x0 - c.tP, s1 = (long double)c.x1 - c.tP;
        const long double expected =
            0.3L * 2.0L / (4 * pi) * std::exp(-(long double)c.sigma * c.tP) * (1 / std::abs(s1) - 1 / std::abs(s0));
        const double value = pointSegment<double>(c.tP, 0.0, c.x0, c.x1, 0.3, c.sigma, 0.0, 2.0);
        EXPECT_LT(relativeError(value, double(expected)), 1e-9) << "ahead tP " << c.tP;
    }
    // Light behind the segment (s0 > 0): L = c e^{-sigma tP} [e^{-2 sigma s0}/s0 - e^{-2 sigma s1}/s1
    //                                                         - 2 sigma (E1(2 sigma s0) - E1(2 sigma s1))].
    for (const Case& c : {Case{-5, 0, 10, 0.5}, Case{-5, 0, kInf, 0.5}, Case{2, 3, 40, 0.05}, Case{-1, 0, 3, 2}}) {
        const long double sigma = c.sigma;
        const long double s0 = (long double)c.x0 - c.tP, s1 = (long double)c.x1 - c.tP;
        const long double far = std::isinf(c.x1) ? 0.0L : std::exp(-2 * sigma * s1) / s1;
        const long double farE1 = std::isinf(c.x1) ? 0.0L : boost::math::expint(1, 2 * sigma * s1);
        const long double bracket = std::exp(-2 * sigma * s0) / s0 - far -
                                    2 * sigma * (boost::math::expint(1, 2 * sigma * s0) - farE1);
        const long double expected = 0.3L * 2.0L / (4 * pi) * std::exp(-sigma * c.tP) * bracket;
        const double value = pointSegment<double>(c.tP, 0.0, c.x0, c.x1, 0.3, c.sigma, 0.0, 2.0);
        EXPECT_LT(relativeError(value, double(expected)), 1e-9) << "behind tP " << c.tP;
    }
}

TEST(AirlightPointSegment, RayThroughLightWithFootPointInsideIsFiniteAndFloored) {
    // The exact integral diverges like sigma_s I0 e^{-sigma tP} / (4 h); the kernel returns the value for
    // the floor distance h = kMinRelativeH * (segment extent around P): 1e-13 in double, 1e-7 in float.
    const double tP = 5, x0 = 0, x1 = 10, sigma = 0.1;
    for (const double hFloor : {Precision<double>::kMinRelativeH * 5.0, double(Precision<float>::kMinRelativeH) * 5.0}) {
        const bool isDouble = hFloor < 1e-9;
        const double atZero = isDouble ? pointSegment<double>(tP, 0.0, x0, x1, sigma, sigma, 0.0, 1.0)
                                       : double(pointSegment<float>(5.0f, 0.0f, 0.0f, 10.0f, 0.1f, 0.1f, 0.0f, 1.0f));
        ASSERT_TRUE(std::isfinite(atZero)) << hFloor;
        // Divergence rate: close to sigma_s I0 e^{-sigma tP} / (4 h) at the floor, against a long-double
        // tanh-sinh quadrature of the same problem (Boost).
        const ReferenceValue ref = referencePointSegment(tP, hFloor, x0, x1, sigma, sigma, 0.0, 1.0);
        EXPECT_LT(relativeError(atZero, double(ref.value)), isDouble ? 1e-9 : 1e-4) << hFloor;
        const double asymptote = sigma * std::exp(-sigma * tP) / (4.0 * hFloor);
        EXPECT_LT(relativeError(atZero, asymptote), 1e-3) << hFloor;
        if (isDouble) {
            EXPECT_EQ(atZero, pointSegment<double>(tP, hFloor, x0, x1, sigma, sigma, 0.0, 1.0));
            EXPECT_GT(atZero, pointSegment<double>(tP, 10.0 * hFloor, x0, x1, sigma, sigma, 0.0, 1.0));
        }
    }
}

TEST(AirlightPointSegment, RayPassingFarBelowTheFloatFloorKeepsItsOwnDistanceInDouble) {
    // The stiff case ray-near-light: a point light 1e-6 from a ray, 7 units in, the ray 40 long
    // (h / extent ~ 3e-8, below float's floor). Double must integrate the ray as it is: against a
    // long-double quadrature and the 1/h asymptote, and not the value at float's floor, 3.3 times darker.
    const double tP = 7.0, h = 1e-6, x0 = 0.05, x1 = 40.0, sigma_t = 0.08, sigma_s = 0.05, I0 = 60.0;
    const double value = pointSegment<double>(tP, h, x0, x1, sigma_s, sigma_t, 0.0, I0);
    const ReferenceValue ref = referencePointSegment(tP, h, x0, x1, sigma_s, sigma_t, 0.0, I0);
    EXPECT_LT(relativeError(value, double(ref.value)), 1e-9);
    const double asymptote = sigma_s * I0 * std::exp(-sigma_t * tP) / (4.0 * h);
    EXPECT_LT(relativeError(value, asymptote), 1e-4);
    const double atFloatFloor = pointSegment<double>(tP, double(Precision<float>::kMinRelativeH) * 33.0, x0, x1,
                                                     sigma_s, sigma_t, 0.0, I0);
    EXPECT_GT(value, 3.0 * atFloatFloor);
}

// ---- mpmath reference values (docs/numerics.md#reference-values) ---------------------------------------

struct TableCase {
    std::string name;
    glm::dvec3 cam, w, light;
    double sigma_t, sigma_s, I0, x0, x1, g, reference;
};

std::vector<TableCase> readReferenceValues() {
    const std::string path = std::string(VIZ_TEST_DATA_DIR) + "/math/airlight_ref_cases.txt";
    std::ifstream in(path);
    EXPECT_TRUE(in.good()) << "cannot read " << path;
    std::vector<TableCase> cases;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream fields(line);
        TableCase c;
        std::string relErr;
        fields >> c.name >> c.cam.x >> c.cam.y >> c.cam.z >> c.w.x >> c.w.y >> c.w.z >> c.light.x >> c.light.y >>
            c.light.z >> c.sigma_t >> c.sigma_s >> c.I0 >> c.x0 >> c.x1 >> c.g >> c.reference >> relErr;
        EXPECT_FALSE(fields.fail()) << line;
        cases.push_back(c);
    }
    return cases;
}

TEST(AirlightPointSegment, MatchesTheMpmathReferenceValuesOfDocsNumerics) {
    const std::vector<TableCase> cases = readReferenceValues();
    ASSERT_EQ(cases.size(), 16u);
    double worstDouble = 0, worstFloat = 0;
    for (const TableCase& c : cases) {
        SCOPED_TRACE(c.name);
        // Geometry camera-relative in double, as the renderer does it.
        const auto geo = rayLightGeometry<double>(c.light - c.cam, glm::normalize(c.w));
        const double value = pointSegment<double>(geo.tP, geo.h, c.x0, c.x1, c.sigma_s, c.sigma_t, c.g, c.I0);
        const double error = relativeError(value, c.reference);
        EXPECT_LT(error, 1e-10) << value << " vs " << c.reference;
        const float valueF = pointSegment<float>(float(geo.tP), float(geo.h), float(c.x0), float(c.x1),
                                                 float(c.sigma_s), float(c.sigma_t), float(c.g), float(c.I0));
        const double errorF = relativeError(valueF, c.reference);
        EXPECT_LT(errorF, 1e-4) << valueF << " vs " << c.reference;
        worstDouble = std::max(worstDouble, error);
        worstFloat = std::max(worstFloat, errorF);
    }
    std::printf("  docs/numerics.md#reference-values (mpmath): worst relative error double %.2e, float %.2e\n",
                worstDouble, worstFloat);
}

// ---- directional light ------------------------------------------------------------------------------

long double referenceDirectionalPhase(long double cosTheta, long double g) {
    const long double pi = boost::math::constants::pi<long double>();
    return (1 - g * g) / (4 * pi * std::pow(1 + g * g - 2 * g * cosTheta, 1.5L));
}

// Closed form sigma_s p E e^{-sigma x0} (1 - e^{-sigma len}) / sigma in long double, len = x1 - x0 as
// the kernel forms it from the same inputs.
long double closedDirectional(double cosTheta, double x0, double x1, double sigma_s, double sigma, double g,
                              double E) {
    const long double p = g == 0.0 ? 1 / (4 * boost::math::constants::pi<long double>())
                                   : referenceDirectionalPhase(cosTheta, g);
    const long double sl = sigma, length = (long double)x1 - x0;
    const long double path =
        sigma == 0.0 ? length : (std::isinf(x1) ? 1 / sl : -std::expm1(-sl * length) / sl);
    return (long double)sigma_s * p * E * std::exp(-sl * x0) * path;
}

TEST(AirlightDirectionalSegment, MatchesClosedFormAndQuadrature) {
    const double inf = kInf;
    double worstClosed = 0, worstQuad = 0, worstFloat = 0;
    for (double sigma : {0.0, 1e-20, 1e-8, 0.3, 50.0}) {
        for (double x0 : {0.0, 2.5, 100.0}) {
            for (double length : {1e-3, 10.0, inf}) {
                for (double g : {0.0, 0.7, -0.4}) {
                    const double x1 = x0 + length, cosTheta = 0.8, sigma_s = 0.6, E = 3.0;
                    SCOPED_TRACE(::testing::Message() << "sigma " << sigma << " x0 " << x0 << " len " << length);
                    const double value = directionalSegment<double>(cosTheta, x0, x1, sigma_s, sigma, g, E);
                    if (sigma == 0.0 && std::isinf(length)) {
                        EXPECT_TRUE(std::isinf(value));  // genuinely infinite
                        continue;
                    }
                    const long double expected = closedDirectional(cosTheta, x0, x1, sigma_s, sigma, g, E);
                    if (!(expected > 1e-300L)) {
                        EXPECT_GE(value, 0.0);
                        continue;
                    }
                    const double errClosed = relativeError(value, double(expected));
                    EXPECT_LT(errClosed, 1e-12);
                    worstClosed = std::max(worstClosed, errClosed);
                    // Independent quadrature of sigma_s p E e^{-sigma x} over a finite [x0, x1].
                    if (std::isfinite(x1)) {
                        const long double p = g == 0.0 ? 1 / (4 * boost::math::constants::pi<long double>())
                                                       : referenceDirectionalPhase(cosTheta, g);
                        const long double sl = sigma;
                        auto integrand = [&](long double x) { return sigma_s * p * E * std::exp(-sl * x); };
                        const long double quad = boost::math::quadrature::gauss_kronrod<long double, 61>::integrate(
                            integrand, (long double)x0, (long double)x1, 10, 1e-17L);
                        const double errQuad = relativeError(value, double(quad));
                        EXPECT_LT(errQuad, 1e-12);
                        worstQuad = std::max(worstQuad, errQuad);
                    }
                    // Float mirror against the closed form at the same (float-rounded) inputs.
                    const float xf0 = float(x0), xf1 = float(x1), sigmaF = float(sigma), gF = float(g);
                    const float valueF = directionalSegment<float>(float(cosTheta), xf0, xf1, float(sigma_s), sigmaF,
                                                                   gF, float(E));
                    ASSERT_TRUE(std::isfinite(valueF));
                    const long double expectedF =
                        closedDirectional(double(float(cosTheta)), xf0, xf1, double(float(sigma_s)), sigmaF, gF, E);
                    if (isNormalFloat(double(expectedF))) {
                        const double errF = relativeError(valueF, double(expectedF));
                        EXPECT_LT(errF, 1e-5);
                        worstFloat = std::max(worstFloat, errF);
                    }
                }
            }
        }
    }
    std::printf("  directionalSegment: worst vs closed form %.2e, vs quadrature %.2e, float vs closed %.2e\n",
                worstClosed, worstQuad, worstFloat);
}

// ---- phase function -----------------------------------------------------------------------------------

TEST(AirlightPhase, HenyeyGreensteinIntegratesToOneOverTheSphere) {
    for (double g : {0.0, 0.3, -0.5, 0.9, -0.95, 0.99}) {
        SCOPED_TRACE(g);
        // 2 pi int_{-1}^{1} p(mu) dmu, split towards the peak at mu = sign(g).
        auto p = [g](double mu) { return phaseHG<double>(mu, g); };
        double integral = 0;
        const double breaks[] = {-1.0, -0.999, -0.99, -0.9, 0.0, 0.9, 0.99, 0.999, 1.0};
        for (int i = 0; i + 1 < 9; ++i) {
            integral += boost::math::quadrature::gauss_kronrod<double, 61>::integrate(p, breaks[i], breaks[i + 1],
                                                                                    15, 1e-14);
        }
        EXPECT_NEAR(2.0 * boost::math::constants::pi<double>() * integral, 1.0, 1e-10);
    }
}

TEST(AirlightPhase, IsotropicIsExactAndForwardMeansTowardTheLight) {
    EXPECT_EQ(phaseHG<double>(0.3, 0.0), 0.25 / boost::math::constants::pi<double>());
    EXPECT_EQ(phaseHG<float>(-0.7f, 0.0f), float(0.25 / boost::math::constants::pi<double>()));
    // g > 0 favours cos = +1 (light behind the point as seen from the eye, i.e. looking at the light).
    EXPECT_GT(phaseHG<double>(1.0, 0.8), phaseHG<double>(-1.0, 0.8));
    // Mirror symmetry p(cos, g) = p(-cos, -g) and the textbook form 1 + g^2 - 2 g cos.
    for (double c : {-1.0, -0.3, 0.0, 0.5, 0.999}) {
        EXPECT_NEAR(phaseHG<double>(c, 0.6), phaseHG<double>(-c, -0.6), 1e-15);
        EXPECT_LT(relativeError(phaseHG<double>(c, 0.6), double(referenceDirectionalPhase(c, 0.6))), 1e-14);
    }
    // Sign convention in pointSegment: with a strong forward lobe, a segment in front of the light
    // (looking at it) scatters more than the same geometry behind it.
    const double ahead = pointSegment<double>(10.0, 0.5, 0.0, 9.0, 0.1, 0.1, 0.9, 1.0);
    const double behind = pointSegment<double>(-10.0, 0.5, 1.0, 10.0, 0.1, 0.1, 0.9, 1.0);
    EXPECT_GT(ahead, 10.0 * behind);
}

// ---- helpers -------------------------------------------------------------------------------------------

TEST(AirlightHelpers, StableFunctionsMatchTheStandardLibrary) {
    for (double x : {-0.9, -1e-3, -1e-9, -1e-300, 0.0, 1e-300, 1e-12, 1e-5, 3e-5, 0.1, 2.0, 1e3, 1e200}) {
        SCOPED_TRACE(x);
        EXPECT_LT(relativeError(stableLog1p(x), std::log1p(x)), 4e-16) << stableLog1p(x);
        EXPECT_LT(relativeError(stableLog1p(float(x)), std::log1p(double(float(x)))), 4e-7);
    }
    for (double x : {-700.0, -30.0, -1.0, -1e-3, -1e-6, -1e-300, 0.0, 1e-12, 9e-6, 2e-5, 0.5, 20.0, 700.0}) {
        SCOPED_TRACE(x);
        EXPECT_LT(relativeError(stableExpm1(x), std::expm1(x)), 4e-16) << stableExpm1(x);
        if (std::abs(x) < 80) {
            EXPECT_LT(relativeError(stableExpm1(float(x)), std::expm1(double(float(x)))), 4e-7);
        }
    }
    for (double x : {-1e30, -1e9, -3.0, -1e-4, -1e-200, 0.0, 1e-10, 0.5, 7.0, 1e5, 1e10, 1e300}) {
        SCOPED_TRACE(x);
        EXPECT_LT(relativeError(stableAsinh(x), std::asinh(x)), 4e-16) << stableAsinh(x);
        if (std::abs(x) < 1e30) {
            EXPECT_LT(relativeError(stableAsinh(float(x)), std::asinh(double(float(x)))), 4e-7);
        }
    }
    EXPECT_EQ(transmittance(0.0, kInf), 1.0);
    EXPECT_EQ(transmittance(0.5, kInf), 0.0);
    EXPECT_LT(relativeError(transmittance(0.3, 7.0), std::exp(-2.1)), 1e-15);
    const auto geo = rayLightGeometry<double>(glm::dvec3(3.0, 4.0, 0.0), glm::dvec3(1.0, 0.0, 0.0));
    EXPECT_EQ(geo.tP, 3.0);
    EXPECT_EQ(geo.h, 4.0);
}

}  // namespace
}  // namespace viz::airlight::test
