// Epipolar coordinates: the law-of-sines relations, monotonicity, and range selection.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "scene/builtin_scenes.h"
#include "techniques/vsv/epipolar_setup.h"

namespace viz::vsv {
namespace {

TEST(Epipolar, PointsRoundTripThroughAlphaThetaPhi) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-5.0, 5.0);
    for (int trial = 0; trial < 200; ++trial) {
        const EpipolarFrame f = makeFrame({u(rng), u(rng), u(rng)});
        const glm::dvec3 p{u(rng), u(rng), u(rng)};
        const double t = glm::length(p);
        const glm::dvec3 w = p / t;
        const double alpha = alphaOf(f, w), theta = thetaOf(f, w);
        EXPECT_LT(glm::length(eyeRay(f, alpha, theta) - w), 1e-9);
        // phi seen from the light, from the geometry directly.
        const glm::dvec3 fromLight = p - f.light;
        const double r = glm::length(fromLight);
        const double phiDirect = std::acos(std::clamp(glm::dot(fromLight / r, -f.b), -1.0, 1.0));
        EXPECT_NEAR(phiOnEyeRay(f, alpha, t), phiDirect, 1e-9);
        EXPECT_NEAR(alphaOnLightRay(f, phiDirect, r), alpha, 1e-9);
        EXPECT_NEAR(tOnEyeRay(f, alpha, phiDirect), t, 1e-7 * (1.0 + t));
        // The light ray of (theta, phi) passes through p.
        EXPECT_LT(glm::length(f.light + r * lightRay(f, theta, phiDirect) - p), 1e-7);
    }
}

TEST(Epipolar, PhiGrowsAlongEyeRaysAndAlphaAlongLightRays) {
    const EpipolarFrame f = makeFrame({1.0, 3.0, -2.0});
    for (double a = 0.05; a < 3.1; a += 0.3) {
        double last = -1.0;
        for (double t = 0.0; t < 50.0; t += 0.25) {
            const double phi = phiOnEyeRay(f, a, t);
            EXPECT_GT(phi, last);
            EXPECT_LT(phi, std::numbers::pi - a + 1e-12);
            last = phi;
        }
        last = -1.0;
        for (double r = 0.0; r < 50.0; r += 0.25) {
            const double alpha = alphaOnLightRay(f, a, r);
            EXPECT_GT(alpha, last);
            last = alpha;
        }
    }
}

// Every pixel ray of the image falls inside the selected alpha and theta ranges, and the phi of every
// visible point of a spot's cone falls inside the phi range.
TEST(Epipolar, DynamicRangeCoversEveryPixelRay) {
    for (const char* name : {"grate", "stained-glass", "grate-point"}) {
        const bool point = std::string(name) == "grate-point";
        scene::Scene scene = scene::makeBuiltinScene(point ? "grate" : name);
        if (point) scene.lights[0].type = scene::LightType::Point;
        const scene::Light& light = scene.lights[0];
        const EpipolarFrame f = frameForLight(scene, light);
        const EpipolarGrid g = gridForLight(scene, light, 160, 120, 64, 64, 128, true);
        EXPECT_LT(g.alpha1 - g.alpha0, std::numbers::pi) << name;
        for (int y = 0; y < 120; y += 7)
            for (int x = 0; x < 160; x += 7) {
                const glm::dvec3 w = scene::pixelRay(scene.camera, 160, 120, x, y);
                const double ca = alphaCoord(g, alphaOf(f, w));
                const double ct = thetaCoord(g, thetaOf(f, w));
                EXPECT_GE(ca, 0.0);
                EXPECT_LT(ca, g.nAlpha);
                EXPECT_GE(ct, 0.0);
                EXPECT_LT(ct, g.nTheta);
                for (double t : {0.5, 2.0, 8.0, 30.0, scene.camera.zfar}) {
                    const glm::dvec3 p = t * w;
                    const glm::dvec3 dir = glm::normalize(p - f.light);
                    if (!point && glm::dot(dir, light.direction) < std::cos(light.outerConeAngle)) continue;  // outside the cone
                    const double cp = phiCoord(g, phiOnEyeRay(f, alphaOf(f, w), t));
                    EXPECT_GE(cp, 0.0) << name;
                    EXPECT_LT(cp, g.nPhi) << name;
                }
            }
    }
}

TEST(Epipolar, EpipoleInViewMakesThetaWrap) {
    scene::Scene scene = scene::makeBuiltinScene("grate");
    scene.camera.forward = glm::normalize(scene.lights[0].position - scene.camera.position);
    scene.camera.up = glm::normalize(glm::cross(glm::cross(scene.camera.forward, glm::dvec3(0, 1, 0)),
                                                scene.camera.forward));
    const EpipolarGrid g = gridForLight(scene, scene.lights[0], 160, 120, 64, 64, 128, true);
    EXPECT_TRUE(g.epipoleToward);
    EXPECT_TRUE(g.thetaFull);
    EXPECT_EQ(g.alpha0, 0.0);
}

TEST(Epipolar, OccluderCellAppliesTheBiasAndClamps) {
    const EpipolarFrame f = makeFrame({0.0, 5.0, -5.0});
    EpipolarGrid g;
    g.nAlpha = 100;
    g.alpha0 = 0.2;
    g.alpha1 = 1.2;
    const double phi = 0.6;
    const double r = 3.0;
    const double c = alphaCoord(g, alphaOnLightRay(f, phi, r));
    EXPECT_EQ(occluderCell(f, g, phi, r, 0.0), int(std::floor(c)));
    EXPECT_EQ(occluderCell(f, g, phi, r, -2.25), int(std::floor(c + 2.25)));
    EXPECT_EQ(occluderCell(f, g, phi, 0.01, 0.0), 0);      // before the range: the whole column
    EXPECT_EQ(occluderCell(f, g, phi, 1e6, 0.0), -1);      // beyond it: nothing
}

}  // namespace
}  // namespace viz::vsv
