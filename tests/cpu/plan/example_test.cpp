// The worked example technique (viz/techniques/example/), registered the way a new technique is found:
// through the registry. Its L_air is checked against the closed form written out here (not the shared
// airlight header it uses), its midpoint rule converges to it, it steps stage by stage like every
// technique, and a run resumed after its first stage carries that stage over.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "scene/camera.h"
#include "techniques/example/example.h"
#include "techniques/registry.h"

namespace viz {
namespace {

// A sun-lit medium with nothing in it: every ray runs to zfar.
scene::Scene openSky() {
    scene::Scene s;
    s.camera.position = {0, 1, 0};
    s.camera.forward = glm::normalize(glm::dvec3(0, 0.1, -1));
    s.camera.up = glm::normalize(glm::cross(glm::cross(s.camera.forward, glm::dvec3(0, 1, 0)), s.camera.forward));
    s.camera.yfov = 0.9;
    s.camera.zfar = 40.0;
    s.medium = {0.05, 0.02, 0.6};
    scene::Light sun{.name = "sun",
                     .type = scene::LightType::Directional,
                     .direction = glm::normalize(glm::dvec3(0.3, -0.4, 1.0)),  // towards the camera: forward scattering
                     .colour = {1.0, 0.8, 0.6},
                     .intensity = 3.0};
    s.lights.push_back(sun);
    scene::Light lamp;  // the example shades suns only, and its plan says so
    lamp.name = "lamp";
    lamp.type = scene::LightType::Point;
    lamp.position = {0, 2, -5};
    s.lights.push_back(lamp);
    return s;
}

// sigma_s E p_HG(cos) (1 - exp(-sigma_t d)) / sigma_t, written out from the definitions.
double expected(const scene::Scene& s, const glm::dvec3& w, double irradiance) {
    const scene::Medium& m = s.medium;
    const double cosTheta = glm::dot(s.lights[0].direction, -w);
    const double g = m.g;
    const double phase = (1.0 - g * g) / (4.0 * std::numbers::pi * std::pow(1.0 + g * g - 2.0 * g * cosTheta, 1.5));
    const double sigmaT = m.sigma_s + m.sigma_a;
    return m.sigma_s * irradiance * phase * (1.0 - std::exp(-sigmaT * s.camera.zfar)) / sigmaT;
}

FrameOutput runExample(Technique& t, const scene::Scene& scene, const Settings& given, int stop = -1) {
    FrameInput in;
    in.scene = &scene;
    in.width = 24;
    in.height = 16;
    setRunSettings(in, completeSettings(t, given));
    in.stopAfterStage = stop;
    return t.run(in);
}

class ExampleTechniqueTest : public ::testing::Test {
protected:
    void SetUp() override { registerTechnique("example", makeExampleTechnique); }
};

TEST_F(ExampleTechniqueTest, TheRegistryFindsItAfterTheListedOnes) {
    const std::vector<std::string> ids = techniqueIds();
    ASSERT_FALSE(ids.empty());
    EXPECT_EQ(ids.back(), "example");
    EXPECT_EQ(makeTechnique("example")->id(), "example");
}

TEST_F(ExampleTechniqueTest, ItsAirlightIsTheClosedFormOfEachSun) {
    const scene::Scene scene = openSky();
    const auto t = makeTechnique("example");
    const FrameOutput out = runExample(*t, scene, {});
    ASSERT_EQ(out.airlight.width, 24);
    double worst = 0.0;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 24; ++x) {
            const glm::dvec3 w = scene::pixelRay(scene.camera, 24, 16, x, y);
            for (int c = 0; c < 3; ++c) {
                const double want = expected(scene, w, scene.lights[0].intensity * scene.lights[0].colour[c]);
                worst = std::max(worst, std::abs(double(out.airlight.at(x, y, c)) - want) / want);
            }
        }
    EXPECT_LT(worst, 1e-6) << "float storage is the only difference";
    // The point light is left out, and the plan says so.
    bool said = false;
    for (const FeaturePlan& f : out.plan.features) said = said || f.why.find("1 point, spot or area") != std::string::npos;
    EXPECT_TRUE(said);
}

TEST_F(ExampleTechniqueTest, TheMidpointRuleConvergesToTheClosedForm) {
    const scene::Scene scene = openSky();
    const auto t = makeTechnique("example");
    const Image closed = runExample(*t, scene, {}).airlight;
    double previous = 1.0;
    for (double samples : {4.0, 16.0, 64.0}) {
        const Image mid = runExample(*t, scene, {{"integration", 1.0}, {"samples", samples}}).airlight;
        double worst = 0.0;
        for (std::size_t i = 0; i < mid.pixels.size(); ++i)
            worst = std::max(worst, std::abs(double(mid.pixels[i]) - closed.pixels[i]) / double(closed.pixels[i]));
        EXPECT_LT(worst, previous / 10.0) << samples << " intervals: the midpoint error falls as 1/N^2";
        previous = worst;
    }
}

TEST_F(ExampleTechniqueTest, ItStepsStageByStageAndResumesAfterItsFirstStage) {
    const scene::Scene scene = openSky();
    const auto t = makeTechnique("example");
    const FrameOutput first = runExample(*t, scene, {}, 0);
    EXPECT_EQ(first.lastStageRun, 0);
    ASSERT_EQ(first.intermediates.size(), 1u);
    EXPECT_EQ(first.intermediates[0].id, "example.lengths");
    EXPECT_TRUE(first.airlight.empty());

    FrameInput in;
    in.scene = &scene;
    in.width = 24;
    in.height = 16;
    setRunSettings(in, completeSettings(*t, {{"integration", 1.0}}));
    in.resumeAtStage = 1;  // only the airlight's parameters changed
    const FrameOutput resumed = t->run(in);
    EXPECT_EQ(resumed.firstStageRun, 1) << "the lengths stage keeps its outputs";
    ASSERT_EQ(resumed.timing.stages.size(), 2u);
    EXPECT_EQ(resumed.timing.stages[0].stage, "example.airlight");
    EXPECT_EQ(resumed.timing.clock, "steady_clock");
    ASSERT_EQ(resumed.intermediates.size(), 3u);
    EXPECT_EQ(resumed.intermediates[0].id, "example.lengths") << "carried over and republished";
    const FrameOutput fresh = runExample(*makeTechnique("example"), scene, {{"integration", 1.0}});
    EXPECT_EQ(resumed.final.pixels, fresh.final.pixels);
}

}  // namespace
}  // namespace viz
