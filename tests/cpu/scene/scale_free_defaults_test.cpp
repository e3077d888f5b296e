// What the loader adds to a model that brings no camera, light or medium (the framing camera, the default
// spot light, the medium of optical depth 0.5) and the orbit distance the window starts at must not
// depend on the model's units: the same model scaled by s (a node scale) gets a camera and a light whose
// positions about the model's centre, near and far planes scale by s, a light intensity by s^2 (the same
// irradiance on the model) and a sigma_s by 1/s, so every technique renders the same image at any scale.
// A model 0.2 mm across was framed as if it were 2 mm (a floor of 1 mm on the framing radius).
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "scene/gltf_loader.h"
#include "scene/orbit_target.h"
#include "test_util.h"

namespace viz::scene {
namespace {

// box.gltf's cube alone, under a node scaled by `s`: no camera, no light, no medium.
std::string bareCube(const std::filesystem::path& dir, double s) {
    std::ifstream in(test::dataPath("box.gltf"));
    nlohmann::json j = nlohmann::json::parse(in);
    j["nodes"] = nlohmann::json::array({{{"name", "scaled"}, {"scale", {s, s, s}}, {"children", {1}}}, j["nodes"][0]});
    j["scenes"] = nlohmann::json::array({{{"name", "bare"}, {"nodes", {0}}}});
    j.erase("cameras");
    j.erase("extensions");
    j.erase("extensionsUsed");
    const std::filesystem::path file = dir / ("cube_" + std::to_string(std::log10(s)) + ".gltf");
    test::writeText(file, j.dump());
    return file.string();
}

void expectScaled(glm::dvec3 scaled, glm::dvec3 unit, double s, const std::string& what) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(scaled[k] / s, unit[k], 1e-5 * (1.0 + std::abs(unit[k]))) << what << "[" << k << "]";
}

TEST(ScaleFreeDefaults, AModelScaledBySGetsTheSameCameraLightAndMediumScaledByS) {
    const std::filesystem::path dir = test::freshTempDir("scale");
    const Scene unit = loadGltf(bareCube(dir, 1.0));
    ASSERT_TRUE(test::hasNote(unit, "no camera: framed the scene"));
    ASSERT_TRUE(test::hasNote(unit, "added a default spot light"));
    ASSERT_EQ(unit.lights.size(), 1u);
    const double unitOrbit = orbitDistance(unit);
    for (const double s : {1e-6, 1e-4, 1e-2, 1e2, 1e4}) {
        const std::string at = "scale " + std::to_string(s);
        const Scene scaled = loadGltf(bareCube(dir, s));
        ASSERT_EQ(scaled.lights.size(), 1u) << at;
        // The cube is centred on the origin, so positions scale about it.
        expectScaled(scaled.camera.position, unit.camera.position, s, at + " camera position");
        expectScaled(scaled.camera.forward * s, unit.camera.forward, s, at + " camera forward");
        EXPECT_DOUBLE_EQ(scaled.camera.yfov, unit.camera.yfov) << at;
        EXPECT_NEAR(scaled.camera.znear / s, unit.camera.znear, 1e-5 * unit.camera.znear) << at;
        EXPECT_NEAR(scaled.camera.zfar / s, unit.camera.zfar, 1e-5 * unit.camera.zfar) << at;
        const Light& l = scaled.lights[0];
        const Light& u = unit.lights[0];
        expectScaled(l.position, u.position, s, at + " light position");
        expectScaled(l.direction * s, u.direction, s, at + " light direction");
        EXPECT_NEAR(l.outerConeAngle, u.outerConeAngle, 1e-9) << at;
        EXPECT_NEAR(l.intensity / (s * s), u.intensity, 1e-5 * u.intensity) << at;
        EXPECT_NEAR(scaled.medium.sigma_s * s, unit.medium.sigma_s, 1e-5 * unit.medium.sigma_s) << at;
        EXPECT_NEAR(orbitDistance(scaled) / s, unitOrbit, 1e-5 * unitOrbit) << at;
    }
}

}  // namespace
}  // namespace viz::scene
