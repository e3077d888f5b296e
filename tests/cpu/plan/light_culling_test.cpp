// Culling lights whose lit volume misses the view volume: the obvious cases, and a property test that a
// culled spot's cone contains no point of the view volume (the test is conservative, never wrong).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "render/light_culling.h"
#include "scene/builtin_scenes.h"
#include "scene/camera.h"

namespace viz::render {
namespace {

scene::Light spot(glm::dvec3 position, glm::dvec3 direction, double outer) {
    scene::Light l{.type = scene::LightType::Spot,
                   .position = position,
                   .direction = glm::normalize(direction),
                   .innerConeAngle = outer * 0.5,
                   .outerConeAngle = outer};
    return l;
}

TEST(LightCulling, ObviousCases) {
    const scene::Scene grate = scene::makeBuiltinScene("grate");
    const scene::Camera& cam = grate.camera;  // at (0, 0.8, 7) looking towards (0, 2, 0)
    EXPECT_TRUE(lightReachesView(grate.lights[0], cam));
    // Behind the camera, shining away from the scene: nothing it lights is visible.
    EXPECT_FALSE(lightReachesView(spot({0, 1, 9}, {0, 0, 1}, 0.5), cam));
    // Behind the camera but shining past it into the scene: visible.
    EXPECT_TRUE(lightReachesView(spot({0, 3, 8.5}, {0, -0.5, -1}, 0.5), cam));
    // Far to the side, shining further away: culled by a side plane.
    EXPECT_FALSE(lightReachesView(spot({-60, 1, 0}, {-1, 0, 0}, 0.6), cam));
    // Beyond zfar (40), shining away: culled by the far plane.
    EXPECT_FALSE(lightReachesView(spot({0, 2, -80}, {0, 0, -1}, 0.3), cam));
    // A wide cone near the side plane that still leaks into view is kept.
    EXPECT_TRUE(lightReachesView(spot({-20, 1, 0}, {-1, 0, 0}, 1.5), cam));
    // Point and directional light fill all space.
    scene::Light point{.type = scene::LightType::Point, .position = {0, 1, 100}};
    EXPECT_TRUE(lightReachesView(point, cam));
    // An area light facing away from everything in view is culled; turned round, it is not.
    scene::Light area{.type = scene::LightType::Area, .position = {0, 1, 8}, .direction = {0, 0, 1}};
    EXPECT_FALSE(lightReachesView(area, cam));
    area.direction = {0, 0, -1};
    EXPECT_TRUE(lightReachesView(area, cam));
    EXPECT_TRUE(culledLightNames(grate).empty());
}

TEST(LightCulling, ACulledSpotNeverLightsAPointInView) {
    const scene::Camera cam = scene::makeBuiltinScene("grate").camera;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int culled = 0;
    for (int trial = 0; trial < 400; ++trial) {
        const scene::Light l = spot({30 * u(rng), 30 * u(rng), 30 * u(rng)}, {u(rng), u(rng), u(rng)},
                                    0.2 + 0.6 * (u(rng) + 1.0));
        if (lightReachesView(l, cam)) continue;
        ++culled;
        // Points of the view volume (at the widest aspect the test allows for): none inside the cone.
        for (int k = 0; k < 2000; ++k) {
            const double depth = cam.znear + (cam.zfar - cam.znear) * 0.5 * (u(rng) + 1.0);
            const double ty = std::tan(cam.yfov * 0.5), tx = ty * kCullingAspect;
            const glm::dvec3 p = cam.position + depth * (cam.forward + u(rng) * tx * scene::cameraRight(cam) +
                                                         u(rng) * ty * cam.up);
            const glm::dvec3 toP = glm::normalize(p - l.position);
            EXPECT_LT(glm::dot(toP, l.direction), std::cos(l.outerConeAngle)) << "trial " << trial;
        }
    }
    EXPECT_GT(culled, 40);  // the property was exercised
}

}  // namespace
}  // namespace viz::render
