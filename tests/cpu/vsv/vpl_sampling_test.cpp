// VPLs by Halton points and the point cloud of the imperfect shadow maps.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/builtin_scenes.h"
#include "techniques/vsv/vpl_sampling.h"

namespace viz::vsv {
namespace {

TEST(VplSampling, HaltonPointsAreTheRadicalInverses) {
    EXPECT_DOUBLE_EQ(radicalInverse(1, 2), 0.5);
    EXPECT_DOUBLE_EQ(radicalInverse(6, 2), 0.375);  // 110 -> 0.011
    EXPECT_NEAR(radicalInverse(5, 3), 7.0 / 9.0, 1e-15);  // 12 -> 0.21
}

// VPLs lie on the emitter, face its normal, and their weights sum to the emitted power per steradian
// along the normal: the integral of L_e over the rectangle (estimated on a fine grid of the texture).
TEST(VplSampling, VplsCoverTheEmitterAndCarryItsIntensity) {
    const scene::Scene scene = scene::makeBuiltinScene("tv-room");
    const scene::Light& light = scene.lights[0];
    const double area = 4.0 * glm::length(glm::cross(light.halfU, light.halfV));
    const std::vector<Vpl> vpls = sampleVpls(scene, light, 256);
    ASSERT_EQ(vpls.size(), 256u);
    glm::dvec3 sum(0.0);
    for (const Vpl& v : vpls) {
        const glm::dvec3 d = v.position - light.position;
        EXPECT_NEAR(glm::dot(d, glm::normalize(light.direction)), 0.0, 1e-9);
        EXPECT_LE(std::abs(glm::dot(d, light.halfU)) / glm::dot(light.halfU, light.halfU), 1.0 + 1e-9);
        EXPECT_LE(std::abs(glm::dot(d, light.halfV)) / glm::dot(light.halfV, light.halfV), 1.0 + 1e-9);
        EXPECT_NEAR(glm::length(v.normal - glm::normalize(light.direction)), 0.0, 1e-12);
        sum += v.weight;
    }
    const scene::Texture& tex = scene.textures[std::size_t(light.emissionTexture)];
    glm::dvec3 integral(0.0);
    const int n = 512;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            integral += light.radiance * glm::dvec3(scene::sampleLinearRgb(tex, {(i + 0.5) / n, (j + 0.5) / n}));
    integral *= area / (double(n) * n);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sum[c], integral[c], 0.05 * integral[c]) << c;
}

TEST(VplSampling, PointCloudLiesOnTheSceneButNotOnTheEmitter) {
    const scene::Scene scene = scene::makeBuiltinScene("tv-room");
    const int emitter = scene.lights[0].mesh;
    const std::vector<glm::dvec3> points = samplePointCloud(scene, 5000, emitter);
    ASSERT_EQ(points.size(), 5000u);
    // The room is the box [-3, 3] x [0, 2.8] x [-3, 3]; the screen is the plane z = -2.9 within the TV.
    int onScreen = 0;
    for (const glm::dvec3& p : points) {
        EXPECT_LE(std::abs(p.x), 3.0 + 1e-6);
        EXPECT_GE(p.y, -1e-6);
        EXPECT_LE(p.y, 2.8 + 1e-6);
        onScreen += std::abs(p.z + 2.9) < 1e-6 && std::abs(p.x) < 0.8 && p.y > 0.85 && p.y < 1.75 ? 1 : 0;
    }
    EXPECT_EQ(onScreen, 0);
    EXPECT_EQ(samplePointCloud(scene, 100, emitter, 3), samplePointCloud(scene, 100, emitter, 3));
}

TEST(VplSampling, ParaboloidMapsTheHemisphereOntoTheUnitDisc) {
    EXPECT_NEAR(glm::length(paraboloid({0, 0, 1})), 0.0, 1e-15);
    EXPECT_NEAR(glm::length(paraboloid({1, 0, 0})), 1.0, 1e-15);
    const glm::dvec3 d = glm::normalize(glm::dvec3(0.3, -0.4, 0.5));
    EXPECT_LT(glm::length(paraboloid(d)), 1.0);
}

}  // namespace
}  // namespace viz::vsv
