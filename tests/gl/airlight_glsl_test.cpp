// Runs shaders/common/airlight.glsl in a compute shader over the grid of stiff and random cases of
// tests/cpu/math/airlight_cases.h and compares with the double kernel of viz/shared/airlight.h evaluated
// on the same float inputs (camera-relative geometry computed in double on the CPU, then rounded).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "cpu/math/airlight_cases.h"
#include "cpu/math/cosine_lobe_cases.h"
#include "cpu/math/spot_penumbra_cases.h"
#include "case_shader.h"
#include "gl/gl_test_fixture.h"
#include "shared/airlight.h"

namespace viz::airlight::test {
namespace {

using AirlightGlsl = gl::GlTest;

double relativeError(double value, double reference) {
    if (value == reference) return 0.0;
    return std::abs(value - reference) / std::abs(reference);
}

using viz::testing::runCaseShader;

TEST_F(AirlightGlsl, MatchesDoubleKernelOnStiffGrid) {
    std::vector<SegmentCase> cases;
    for (const SegmentCase& c : airlightCaseGrid()) cases.push_back(roundedToFloat(c));
    const int count = int(cases.size());

    std::vector<glm::vec4> inputs;
    for (const SegmentCase& c : cases) {
        inputs.emplace_back(float(c.tP), float(c.h), float(c.x0), float(c.x1));
        inputs.emplace_back(float(c.sigma_s), float(c.sigma_t), float(c.g), float(c.I0));
        inputs.emplace_back(float(c.cosTheta), 0.0f, 0.0f, 0.0f);
    }
    const std::vector<glm::vec4> outputs = runCaseShader<glm::vec4>("airlight_glsl_test.comp", inputs, count);
    ASSERT_EQ(int(outputs.size()), count);

    const double floatMin = double(std::numeric_limits<float>::min());
    std::map<std::string, std::pair<double, std::string>> worstPoint;
    double worstDirectional = 0, worstPhase = 0, worstTransmittance = 0;
    for (int i = 0; i < count; ++i) {
        const SegmentCase& c = cases[size_t(i)];
        SCOPED_TRACE(c.name);
        const glm::vec4 out = outputs[size_t(i)];

        // pointSegment: never NaN/Inf, 1e-4 relative where the double value is a normal float. The double
        // kernel sees h raised to float's floor where that is the higher one (rays through the light:
        // each precision documents its own floor, viz/shared/airlight.h).
        const double hFloat = flooredH<float>(c.tP, c.h, c.x0, c.x1);
        const double point = pointSegment<double>(c.tP, hFloat, c.x0, c.x1, c.sigma_s, c.sigma_t, c.g, c.I0);
        ASSERT_TRUE(std::isfinite(out.x)) << out.x;
        EXPECT_GE(out.x, 0.0f);
        if (isNormalFloat(point)) {
            const double error = relativeError(out.x, point);
            EXPECT_LT(error, 1e-4) << "glsl " << out.x << " double " << point;
            auto& w = worstPoint[c.group];
            if (error >= w.first) w = {error, c.name};
        } else {
            EXPECT_LE(std::abs(double(out.x) - point), 2.0 * floatMin) << "glsl " << out.x << " double " << point;
        }

        // directionalSegment: infinite only for the genuinely infinite sigma_t = 0, x1 = inf.
        const double directional =
            directionalSegment<double>(c.cosTheta, c.x0, c.x1, c.sigma_s, c.sigma_t, c.g, c.I0);
        if (std::isinf(directional)) {
            EXPECT_TRUE(std::isinf(out.y));
        } else {
            ASSERT_TRUE(std::isfinite(out.y)) << out.y;
            if (isNormalFloat(directional)) {
                const double error = relativeError(out.y, directional);
                EXPECT_LT(error, 1e-4) << "glsl " << out.y << " double " << directional;
                worstDirectional = std::max(worstDirectional, error);
            }
        }

        const double phase = phaseHG<double>(c.cosTheta, c.g);
        const double phaseError = relativeError(out.z, phase);
        EXPECT_LT(phaseError, 1e-5);
        worstPhase = std::max(worstPhase, phaseError);

        const double trans = transmittance<double>(c.sigma_t, double(float(c.x0 + 1.0)));
        if (isNormalFloat(trans)) {
            const double error = relativeError(out.w, trans);
            EXPECT_LT(error, 1e-4);
            worstTransmittance = std::max(worstTransmittance, error);
        }
    }
    std::printf("  GLSL pointSegment vs double (relative error, normal-float values):\n");
    for (const auto& [group, w] : worstPoint) {
        std::printf("    %-20s worst %.2e  (%s)\n", group.c_str(), w.first, w.second.c_str());
    }
    std::printf("  GLSL directionalSegment %.2e, phaseHG %.2e, transmittance %.2e\n", worstDirectional,
                worstPhase, worstTransmittance);
}

// cosineLobeSegment (an area light's VPL) against the double kernel on the same float inputs, which
// tests/cpu/math/cosine_lobe_test.cpp holds to an independent quadrature.
TEST_F(AirlightGlsl, CosineLobeMatchesDoubleKernel) {
    const std::vector<LobeCase> cases = cosineLobeCases();
    const int count = int(cases.size());
    std::vector<glm::vec4> inputs;
    for (const LobeCase& c : cases) {
        inputs.emplace_back(glm::vec3(c.D), float(c.x0));
        inputs.emplace_back(glm::vec3(c.w), float(c.x1));
        inputs.emplace_back(glm::vec3(c.n), 0.0f);
        inputs.emplace_back(float(c.sigma_s), float(c.sigma_t), float(c.g), float(c.I0));
    }
    const std::vector<float> outputs = runCaseShader<float>("cosine_lobe_glsl_test.comp", inputs, count);
    ASSERT_EQ(int(outputs.size()), count);
    double worst = 0;
    std::string worstName;
    int compared = 0;
    for (int i = 0; i < count; ++i) {
        const LobeCase& c = cases[size_t(i)];
        SCOPED_TRACE(c.name);
        const float value = outputs[size_t(i)];
        ASSERT_TRUE(std::isfinite(value)) << value;
        EXPECT_GE(value, 0.0f);
        const glm::dvec3 D(glm::vec3(c.D)), w(glm::vec3(c.w)), n(glm::vec3(c.n));
        const double reference =
            cosineLobeSegment<double>(D, w, n, double(float(c.x0)), double(float(c.x1)), double(float(c.sigma_s)),
                                      double(float(c.sigma_t)), double(float(c.g)), double(float(c.I0)));
        if (!isNormalFloat(reference)) {
            EXPECT_LE(std::abs(double(value) - reference), 2.0 * double(std::numeric_limits<float>::min()));
            continue;
        }
        const double error = relativeError(value, reference);
        EXPECT_LT(error, 1e-4) << "glsl " << value << " double " << reference;
        if (error >= worst) worst = error, worstName = c.name;
        ++compared;
    }
    EXPECT_GT(compared, 120);  // the rest are below float's normal range (thick media far from the light)
    std::printf("  GLSL cosineLobeSegment vs double: %d cases, worst %.2e (%s)\n", compared, worst, worstName.c_str());
}

// spotPenumbraSegment (a spot's penumbra, A_spot the square of a lobe) against the double kernel on the same
// float inputs, which tests/cpu/math/spot_penumbra_test.cpp holds to an independent quadrature. The bound
// is the float kernel's 1e-4, widened for hard-edged cones: cd scale + offset rounds to about |offset|
// float epsilons, which A_spot = (cd scale + offset)^2 doubles relative to its value (a 0.01 rad penumbra
// has |offset| ~ 240).
TEST_F(AirlightGlsl, SpotPenumbraMatchesDoubleKernel) {
    const std::vector<SpotCase> cases = spotPenumbraCases();
    const int count = int(cases.size());
    std::vector<glm::vec4> inputs;
    for (const SpotCase& c : cases) {
        inputs.emplace_back(glm::vec3(c.D), float(c.x0));
        inputs.emplace_back(glm::vec3(c.w), float(c.x1));
        inputs.emplace_back(glm::vec3(c.axis), float(c.scale));
        inputs.emplace_back(float(c.offset), float(c.sigma_s), float(c.sigma_t), float(c.g));
    }
    const std::vector<float> outputs = runCaseShader<float>("spot_penumbra_glsl_test.comp", inputs, count);
    ASSERT_EQ(int(outputs.size()), count);
    double worst = 0;
    std::string worstName;
    int compared = 0;
    for (int i = 0; i < count; ++i) {
        const SpotCase& c = cases[size_t(i)];
        SCOPED_TRACE(c.name);
        const float value = outputs[size_t(i)];
        ASSERT_TRUE(std::isfinite(value)) << value;
        EXPECT_GE(value, 0.0f);
        const glm::dvec3 D(glm::vec3(c.D)), w(glm::vec3(c.w)), axis(glm::vec3(c.axis));
        const double reference = spotPenumbraSegment<double>(
            D, w, axis, double(float(c.scale)), double(float(c.offset)), double(float(c.x0)), double(float(c.x1)),
            double(float(c.sigma_s)), double(float(c.sigma_t)), double(float(c.g)), 1.0);
        if (!isNormalFloat(reference)) {
            EXPECT_LE(std::abs(double(value) - reference), 2.0 * double(std::numeric_limits<float>::min()));
            continue;
        }
        const double error = relativeError(value, reference);
        EXPECT_LT(error, 1e-4 * std::max(1.0, std::abs(c.offset) / 64.0)) << "glsl " << value << " double " << reference;
        if (error >= worst) worst = error, worstName = c.name;
        ++compared;
    }
    EXPECT_GT(compared, 200);
    std::printf("  GLSL spotPenumbraSegment vs double: %d cases, worst %.2e (%s)\n", compared, worst, worstName.c_str());
}

}  // namespace
}  // namespace viz::airlight::test
