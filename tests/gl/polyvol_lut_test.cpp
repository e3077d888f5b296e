// polyvol's airlight lookup table through the GPU shader path (shaders/polyvol/airlight_lut.glsl,
// lutPointSegment, reading the technique's table) against an independent reference: the adaptive
// Boost.Math quadrature of tests/cpu/math/airlight_reference.h in long double, on rays passing the light
// at 1e-6 .. 1e-2 and on segments that contain, end at or start at the light's foot point.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "cpu/math/airlight_reference.h"
#include "gl/buffer.h"
#include "gl/gl_test_fixture.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "techniques/polyvol/airlight_lut.h"
#include "temp_dir.h"

namespace {

using PolyvolLut = viz::gl::GlTest;

// Evaluates lutPointSegment for a list of segments: two vec4 per case (tP h x0 x1 | sigma_s sigma_t g -).
const char* kProbeShader = R"(#version 450 core
layout(local_size_x = 64) in;
#include "common/host_device.glsl"
#include "common/airlight.glsl"
#include "polyvol/airlight_lut.glsl"
layout(std430, binding = 0) readonly buffer Inputs { vec4 inputs[]; };
layout(std430, binding = 1) writeonly buffer Outputs { float outputs[]; };
uniform int uCount;
void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= uCount) return;
    vec4 a = inputs[2 * i];
    vec4 b = inputs[2 * i + 1];
    outputs[i] = lutPointSegment(a.x, a.y, a.z, a.w, b.x, b.y, b.z);
}
)";

struct Segment {
    float tP, h, x0, x1, sigma_t;
    const char* kind;
};

// The probe shader lives in a temporary file (shader includes resolve against the shader directory).
viz::gl::Program probeProgram() {
    const viz::testing::TempDir temp("polyvol_lut_probe");
    const std::filesystem::path path = temp / "probe.comp";
    std::ofstream(path) << kProbeShader;
    return viz::gl::Program::compile(
        {.stages = {path.string()}, .defines = {{"AIRLIGHT_LUT", "1"}}, .label = "test.polyvol_lut_probe"});
}

std::vector<float> runProbe(const std::vector<Segment>& cases, double g) {
    const viz::polyvol::AirlightLut table =
        viz::polyvol::buildAirlightLut(g, viz::polyvol::AirlightLut::kWidth, viz::polyvol::AirlightLut::kHeight);
    viz::gl::Texture lut = viz::gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_RGB32F,
                                                     .size = {table.width, table.height, 1}, .levels = 1,
                                                     .label = "test.polyvol_lut"});
    lut.upload(GL_RGB, GL_FLOAT, table.texels.data());
    std::vector<glm::vec4> inputs;
    for (const Segment& c : cases) {
        inputs.emplace_back(c.tP, c.h, c.x0, c.x1);
        inputs.emplace_back(1.0f, c.sigma_t, float(g), 0.0f);
    }
    viz::gl::Buffer in = viz::gl::Buffer::create(
        {.bytes = inputs.size() * sizeof(glm::vec4), .data = inputs.data(), .label = "test.polyvol_lut_inputs"});
    viz::gl::Buffer out =
        viz::gl::Buffer::create({.bytes = cases.size() * sizeof(float), .label = "test.polyvol_lut_outputs"});
    viz::gl::Program program = probeProgram();
    program.use();
    program.set("uCount", int(cases.size()));
    lut.bindUnit(8 + 1);  // kFirstFreeTextureUnit + 1, as in airlight_lut.glsl
    in.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
    out.bindBase(GL_SHADER_STORAGE_BUFFER, 1);
    glDispatchCompute(GLuint((cases.size() + 63) / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    return out.download<float>();
}

// Segments along rays passing the light at h: [0, d] through the foot point P, and segments ending or
// starting within a few h of P (the crossing terms of a ray next to the light). Ends in float, as the GPU
// gets them; the reference integrates exactly those float values.
std::vector<Segment> segmentsNearTheLight() {
    std::vector<Segment> cases;
    for (float h : {1e-6f, 3e-6f, 1e-5f, 3e-5f, 1e-4f, 3e-4f, 1e-3f, 3e-3f, 1e-2f})
        for (float sigma : {0.01f, 0.1f, 1.0f})
            for (float tP : {0.7f, 5.0f, 23.0f}) {
                for (float d : {tP * 1.5f, tP * 4.0f, std::numeric_limits<float>::infinity()})
                    cases.push_back({tP, h, 0.0f, d, sigma, "[0, d] through P"});
                for (float k : {-30.0f, -3.0f, -1.0f, -0.3f, 0.0f, 0.3f, 1.0f, 3.0f, 30.0f}) {
                    const float x = tP + k * h;
                    if (x == tP && k != 0.0f) continue;  // h below float resolution at tP
                    cases.push_back({tP, h, 0.0f, x, sigma, "[0, x], x near P"});
                    cases.push_back({tP, h, x, 4.0f * tP, sigma, "[x, d], x near P"});
                }
            }
    return cases;
}

double relativeError(double value, double reference) { return std::abs(value - reference) / std::abs(reference); }

}  // namespace

// The table's running sums against each channel evaluated on its own (the shared double segment integral,
// a different quadrature from the table's panels): every channel, from the foot point to kTauMax, thin rows
// to thick.
TEST(PolyvolLutTable, EveryChannelMatchesItsDirectEvaluation) {
    using viz::polyvol::AirlightLut;
    for (double g : {0.0, 0.9}) {
        const AirlightLut table = viz::polyvol::buildAirlightLut(g, AirlightLut::kWidth, AirlightLut::kHeight);
        double worst[3] = {0.0, 0.0, 0.0};
        for (int j = 0; j < table.height; j += 37)
            for (int i = 0; i < table.width; i += 53) {
                const double tauH = AirlightLut::tauAt(j, table.height), u = AirlightLut::uAt(i, table.width, tauH);
                const double direct[3] = {viz::polyvol::lutChannelA(u, tauH, g), viz::polyvol::lutChannelB(u, tauH, g),
                                          viz::polyvol::lutChannelC(u, tauH, g)};
                for (int c = 0; c < 3; ++c) {
                    const double stored = table.texels[(std::size_t(j) * std::size_t(table.width) + std::size_t(i)) * 3 + std::size_t(c)];
                    if (direct[c] == 0.0 && stored == 0.0) continue;  // A at kTauMax, C at the foot point
                    ASSERT_GT(direct[c], 1e-30) << "channel " << c << " tau_h " << tauH << " u " << u;
                    const double e = std::abs(stored - direct[c]) / direct[c];
                    worst[c] = std::max(worst[c], e);
                    EXPECT_LT(e, 1e-6) << "channel " << c << " g " << g << " tau_h " << tauH << " u " << u << ": table "
                                       << stored << " direct " << direct[c];
                }
            }
        std::printf("lut table, g = %.1f: worst relative A %.1e, B %.1e, C %.1e\n", g, worst[0], worst[1], worst[2]);
    }
}

// The table covers the foot point (its first column) and every tau_h down to 1e-9 (below that the
// shader takes the closed form): relative error below 1e-3 wherever the reference is a normal float,
// for g = 0, the grate's 0.2 and a forward lobe of 0.9. (With the first table, whose axis was log |u|
// clamped at 1e-5, the stretch |u| < 1e-5 around P was missing and tau_h < 1e-5 was divided by the true
// tau_h but premultiplied by 1e-5: up to 2.3e1 relative here.)
TEST_F(PolyvolLut, MatchesAnIndependentQuadratureOnRaysPassingTheLight) {
    const std::vector<Segment> cases = segmentsNearTheLight();
    const double floatMin = double(std::numeric_limits<float>::min());
    for (double g : {0.0, 0.2, 0.9}) {
        const std::vector<float> lut = runProbe(cases, g);
        ASSERT_EQ(lut.size(), cases.size());
        double worst = 0.0;
        std::string where;
        std::vector<double> worstPerH(9, 0.0);
        int checked = 0;
        for (std::size_t i = 0; i < cases.size(); ++i) {
            const Segment& c = cases[i];
            const viz::airlight::test::ReferenceValue ref =
                viz::airlight::test::referencePointSegment(c.tP, c.h, c.x0, c.x1, 1.0, c.sigma_t, g, 1.0);
            const double r = double(ref.value);
            ASSERT_TRUE(std::isfinite(lut[i])) << c.kind;
            if (!(r >= floatMin) || r > double(std::numeric_limits<float>::max())) continue;
            ++checked;
            const double e = relativeError(lut[i], r);
            EXPECT_LT(e, 1e-3) << c.kind << ": g " << g << " tP " << c.tP << " h " << c.h << " x0 " << c.x0 << " x1 "
                               << c.x1 << " sigma_t " << c.sigma_t << ": lut " << lut[i] << " reference " << r;
            if (e > worst) {
                worst = e;
                char text[160];
                std::snprintf(text, sizeof text, "%s, tP %g h %g x0 %.9g x1 %.9g sigma_t %g", c.kind, c.tP, c.h,
                              c.x0, c.x1, c.sigma_t);
                where = text;
            }
            const int hIndex = int(std::lround(2.0 * std::log10(double(c.h)) + 12.0));
            if (hIndex >= 0 && hIndex < 9) worstPerH[std::size_t(hIndex)] = std::max(worstPerH[std::size_t(hIndex)], e);
        }
        std::printf("polyvol lut vs quadrature, g = %.1f: %d segments, worst relative %.2e (%s)\n  per h (1e-6 .. 1e-2):",
                    g, checked, worst, where.c_str());
        for (double e : worstPerH) std::printf(" %.1e", e);
        std::printf("\n");
        EXPECT_GT(checked, int(cases.size()) / 2);
    }
}

// The full airlight of rays through the foot point at tau_h from 1e-10 to 30 (one per decade, then 3, 10
// and 30; tP = 1, d = 3; h = 1e-3 with sigma_t = tau_h / h up to tau_h = 1e-3, then sigma_t = 1 and h =
// tau_h). Below 1e-9 the shader's closed form answers, from 1e-9 up the table. In the thick rows the part
// before P comes from channel C (with A alone: 2.1e-3 at tau_h = 3, 1.2e-2 at 10, 0.67 at 30).
TEST_F(PolyvolLut, CoversTauHFromBelowTheTableToOne) {
    std::vector<Segment> cases;
    std::vector<double> taus;
    for (int k = -10; k <= 0; ++k) taus.push_back(std::pow(10.0, k));
    for (double tau : {3.0, 10.0, 30.0}) taus.push_back(tau);
    for (double tau : taus) {
        const double h = tau <= 1e-3 ? 1e-3 : tau;
        cases.push_back({1.0f, float(h), 0.0f, 3.0f, float(tau / h), "[0, 3] through P"});
    }
    const std::vector<float> lut = runProbe(cases, 0.0);
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const Segment& c = cases[i];
        const double r = double(viz::airlight::test::referencePointSegment(c.tP, c.h, c.x0, c.x1, 1.0, c.sigma_t, 0.0,
                                                                            1.0).value);
        const double e = relativeError(lut[i], r);
        std::printf("  tau_h %.0e: lut %.6e reference %.6e relative %.1e\n", double(c.sigma_t) * c.h, double(lut[i]), r,
                    e);
        EXPECT_LT(e, 1e-3) << "tau_h " << double(c.sigma_t) * c.h;
    }
}
