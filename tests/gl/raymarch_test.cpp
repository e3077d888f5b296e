// raymarch against the reference on `grate`, stage stepping, and what plan() leaves out.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <vector>

#include <nlohmann/json.hpp>

#include "technique_test_util.h"
#include "scene/gltf_writer.h"
#include "scene/scene_building.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_source.h"
#include "techniques/registry.h"

namespace {

class RaymarchTest : public viz::testing::TechniqueTest {};

using viz::testing::relativeL2;

}  // namespace

// The acceptance figure: error falls as N grows, and at N = 1024 with a 2048^2 shadow map the
// relative L2 error of L_air on grate at 160x120 is below 2 %.
TEST_F(RaymarchTest, ConvergesToTheReferenceOnGrate) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    const viz::FrameOutput reference = render(scene, "reference", {}, 160, 120);
    ASSERT_FALSE(reference.airlight.empty());
    std::vector<double> errors;
    for (int n : {4, 16, 64, 256, 1024}) {
        const viz::FrameOutput out = render(scene, "raymarch", {{"samples", n}, {"shadow_map", 2048}}, 160, 120);
        ASSERT_EQ(out.airlight.pixels.size(), reference.airlight.pixels.size());
        errors.push_back(relativeL2(out.airlight, reference.airlight));
        std::printf("raymarch samples=%4d shadow_map=2048: relative L2 = %.4f\n", n, errors.back());
    }
    for (std::size_t i = 1; i < errors.size(); ++i) EXPECT_LT(errors[i], errors[i - 1]) << "step " << i;
    EXPECT_LT(errors.back(), 0.02);
}

TEST_F(RaymarchTest, StoppingAfterEachStagePublishesOnlyWhatExists) {
    expectEachStageStopsCleanly("raymarch", viz::scene::makeBuiltinScene("grate"), {{"samples", 8}}, 2, 3);
}

// Exact integration between samples handles the 1/r^2 glow analytically, so at equal N it is closer to
// the reference than the midpoint rule where the glow matters: rays passing next to the light (the stiff
// case ray-near-light; on grate, whose spot is above the frame, both are limited by the shadow edges
// once the samples are kept inside the cone). Jitter trades banding for noise at a similar error.
TEST_F(RaymarchTest, ExactIntegrationBeatsTheMidpointRuleAtEqualSamples) {
    const viz::scene::Scene scene = viz::scene::loadScene("stiff/ray-near-light");
    const viz::FrameOutput reference = render(scene, "reference", {}, 160, 120);
    for (int n : {16, 64, 256}) {
        const viz::Settings base{{"samples", n}, {"shadow_map", 2048}};
        viz::Settings jitter = base, exact = base;
        jitter["jitter"] = 1;
        exact["exact"] = 1;
        const double ePlain = relativeL2(render(scene, "raymarch", base, 160, 120).airlight, reference.airlight);
        const double eJitter = relativeL2(render(scene, "raymarch", jitter, 160, 120).airlight, reference.airlight);
        const double eExact = relativeL2(render(scene, "raymarch", exact, 160, 120).airlight, reference.airlight);
        std::printf("samples=%4d relative L2: plain %.4f  jitter %.4f  exact %.4f\n", n, ePlain, eJitter, eExact);
        EXPECT_LT(eExact, ePlain) << n;
    }
}

// An area light's VPLs: exact integration takes each VPL's cosine lobe inside the segment integral
// (pointSegmentWithLobe), where the lobe at the sample times the whole interval's integral counted the part
// of an interval behind the emitter and missed the lobe's turn within the 1/r^2 peak next to the VPL.
// Against the midpoint rule at 4096 samples on the same VPLs and shadow maps (which never calls
// cosineLobeSegment): 16 exact samples were 16.5 % off at 80 x 60 with the lobe at the sample, 0.13 % with
// it integrated; 0.16 % (64 x 48; the midpoint rule 1.75 %) since each VPL stands for its cell of the
// emitter (vpl_kernel=cell, whose solid angle the segment integral takes: pointSegmentCell).
TEST_F(RaymarchTest, ExactIntegrationFollowsAnAreaLightsCosineLobe) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("tv-room");
    const viz::Settings base{{"area_samples", 2}, {"shadow_map", 64}};
    viz::Settings converged = base, exact = base, midpoint = base;
    converged["samples"] = 4096;
    exact["samples"] = midpoint["samples"] = 16;
    exact["exact"] = 1;
    const viz::FrameOutput reference = render(scene, "raymarch", converged, 64, 48);
    const double eExact = relativeL2(render(scene, "raymarch", exact, 64, 48).airlight, reference.airlight);
    const double eMidpoint = relativeL2(render(scene, "raymarch", midpoint, 64, 48).airlight, reference.airlight);
    std::printf("tv-room, 4 VPLs, 16 samples against 4096 midpoint samples: exact %.4f, midpoint %.4f\n", eExact,
                eMidpoint);
    EXPECT_LT(eExact, 0.01);
    EXPECT_LT(eExact, eMidpoint);
}

TEST_F(RaymarchTest, PlanLeavesOutWhatTheSceneDoesNotNeed) {
    auto technique = viz::makeTechnique("raymarch");
    const viz::Settings settings = viz::completeSettings(*technique, {});
    const viz::Plan grate = technique->plan(viz::scene::makeBuiltinScene("grate"), settings);
    const viz::Plan tv = technique->plan(viz::scene::makeBuiltinScene("tv-room"), settings);
    EXPECT_FALSE(feature(grate, "AREA_VPLS").enabled);
    EXPECT_FALSE(feature(grate, "AREA_VPLS").why.empty());
    EXPECT_TRUE(feature(tv, "AREA_VPLS").enabled);
    EXPECT_FALSE(feature(grate, "EXACT").enabled);
    // A feature the scene does not use is compiled out, and the plan names the define.
    const viz::Plan colonnade = technique->plan(viz::scene::makeBuiltinScene("colonnade"), settings);
    EXPECT_FALSE(feature(colonnade, "SPOT").enabled);
    EXPECT_NE(feature(colonnade, "SPOT").why.find("compiled out: LIGHTS_NO_SPOT"), std::string::npos);
    EXPECT_NE(feature(colonnade, "SHADOW_MAPS_CUBE").why.find("SHADOW_NO_CUBE"), std::string::npos);
    EXPECT_TRUE(feature(grate, "SPOT").enabled);
    viz::scene::Scene clear = viz::scene::makeBuiltinScene("grate");
    clear.medium.sigma_s = 0.0;
    const viz::Plan none = technique->plan(clear, settings);
    EXPECT_FALSE(none.stages[2].runs);
    EXPECT_NE(none.stages[2].why.find("sigma_s"), std::string::npos);
}

// llvmpipe stops every loop of an invocation after 65,535 iterations in total; a march of many exact
// samples over many lights must still integrate the whole ray (it is split over dispatches). Exact
// integration and the midpoint rule estimate the same integral: their means agree closely, at sample
// counts where one dispatch would run far past the cap (tv-room: 16 VPLs x 256 samples, ~100 loop
// iterations per exact segment: ~400,000; in one dispatch the mean came out at 0.25 of the midpoint's).
TEST_F(RaymarchTest, ManyExactSamplesOverManyLightsIntegrateTheWholeRay) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("tv-room");
    const viz::Settings common = {{"samples", 256}, {"area_samples", 4}, {"shadow_map", 256}};
    viz::Settings exact = common, midpoint = common;
    exact["exact"] = 1;
    const viz::FrameOutput a = render(scene, "raymarch", exact, 24, 18);
    const viz::FrameOutput b = render(scene, "raymarch", midpoint, 24, 18);
    double sumA = 0.0, sumB = 0.0;
    for (float v : a.airlight.pixels) sumA += v;
    for (float v : b.airlight.pixels) sumB += v;
    ASSERT_GT(sumB, 0.0);
    EXPECT_NEAR(sumA / sumB, 1.0, 0.01);
}

namespace {

// A model as public sample files come: meshes only (no light, no medium), millimetre scale, a camera of
// its own with the given zfar, zero-length normals on the occluder. Written as glTF and loaded, so the
// loader adds its default light and scale-aware medium.
viz::scene::Scene millimetreModel(double zfar, const std::filesystem::path& dir) {
    using namespace viz::scene;
    Scene s;
    s.name = "mm-model";
    s.materials.push_back(Material{});
    MeshBuilder ground("ground", 0), block("block", 0);
    ground.quad({-0.01, 0, 0.01}, {0.01, 0, 0.01}, {0.01, 0, -0.01}, {-0.01, 0, -0.01});
    block.box({0.0, 0.003, 0.0}, {0.0015, 0.0015, 0.0015});
    s.meshes.push_back(ground.take());
    s.meshes.push_back(block.take());
    for (glm::vec3& n : s.meshes[1].normals) n = glm::vec3(0.0f);
    s.camera = lookAt("own", {0.016, 0.009, 0.02}, {0.0, 0.003, 0.0}, 0.8, 1e-4, zfar);
    const std::filesystem::path file = dir / ("mm_" + std::to_string(int(std::log10(zfar))) + ".gltf");
    writeGltf(s, file.string());
    // Without its medium, as a model from elsewhere would be.
    nlohmann::json j = nlohmann::json::parse(std::ifstream(file));
    j["scenes"][0].erase("extras");
    std::ofstream(file) << j.dump();
    return loadScene(file.string());
}

}  // namespace

// Samples go where the light reaches (its cone, 60 mean free paths), never spread over [0, zfar]: a model
// with zfar 1e6 (common in public files) renders as with zfar 1, and both match the reference.
TEST_F(RaymarchTest, AMillimetreModelWithItsOwnFarCameraMatchesTheReference) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "airlight_raymarch_mm";
    std::filesystem::create_directories(dir);
    const viz::scene::Scene far = millimetreModel(1e6, dir), near = millimetreModel(1.0, dir);
    ASSERT_EQ(far.lights.size(), 1u);
    ASSERT_EQ(far.lights[0].type, viz::scene::LightType::Spot);
    const viz::FrameOutput refFar = render(far, "reference", {}, 80, 60);
    const viz::FrameOutput refNear = render(near, "reference", {}, 80, 60);
    const viz::FrameOutput rmFar = render(far, "raymarch", {}, 80, 60);
    const viz::FrameOutput rmNear = render(near, "raymarch", {}, 80, 60);
    const double eFar = relativeL2(rmFar.airlight, refFar.airlight), eNear = relativeL2(rmNear.airlight, refNear.airlight);
    std::printf("mm model, raymarch at its default samples: zfar 1e6 %.4f, zfar 1 %.4f\n", eFar, eNear);
    EXPECT_LT(eFar, 0.02);
    EXPECT_LT(eNear, 0.02);
    EXPECT_LT(relativeL2(rmFar.airlight, rmNear.airlight), 0.01);
    std::filesystem::remove_all(dir);
}
