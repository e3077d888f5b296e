// Shadow visibility of the shared passes on tiny scenes: spot, directional, point (all six cube faces) and
// area-light VPL maps, evaluated at world points by shadowVisibility and checked against where the
// occluder's shadow falls by construction; the published maps' distances and their GPU minimum against the
// geometry and an exhaustive loop over the read-back texels; a shadowed floor in the surface pass.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "gl/gl.h"
#include "render/gpu_lights.h"
#include "render/gpu_scene.h"
#include "render/shadow_maps.h"
#include "render_pipeline_util.h"
#include "scene/camera.h"

namespace viz::render::test {
namespace {

TEST_F(RenderPipeline, SpotShadowMapOccludesBelowTheOccluderOnly) {
    scene::Scene s = occluderScene();
    const scene::Light spot = spotAboveOccluder();
    s.lights = {spot};
    // The occluder's shadow on the floor: scaled by 3 from the light: centre (0.75, 0, 0.75), half 0.45.
    const std::vector<glm::dvec3> pts = {{0.75, 0.0, 0.75}, {0.6, 0.0, 0.9}, {0.5, 1.0, 0.5},  // shadowed
                                         {-0.75, 0.0, 0.75}, {0.75, 0.0, -0.75}, {2.0, 0.0, 1.0},
                                         {0.0, 2.5, 0.0}, {0.9, 1.0, 0.9}};  // lit (the last: beside the cone of the occluder)
    const auto v = visibility(s, s.camera.position, 0, pts);
    const std::vector<float> expected = {0, 0, 0, 1, 1, 1, 1, 1};
    for (std::size_t i = 0; i < pts.size(); ++i) EXPECT_EQ(v[i], expected[i]) << "point " << i;
}

TEST_F(RenderPipeline, PublishedShadowMapsHoldDistancesToTheLight) {
    scene::Scene s = occluderScene();
    const scene::Light spot = spotAboveOccluder();
    scene::Light point = spot;
    point.type = scene::LightType::Point;
    s.lights = {spot, point};
    GpuScene gpuScene(s);
    GpuLights lights(s, s.camera.position, 1);
    ShadowMaps shadows;
    const int size = 128;
    shadows.build(gpuScene, lights, size, 32);
    std::vector<Intermediate> out;
    shadows.publish(out, "test");
    ASSERT_EQ(out.size(), 2u);
    EXPECT_EQ(out[0].id, "test.shadow_map");
    EXPECT_EQ(out[1].id, "test.shadow_map.1");
    EXPECT_EQ(out[0].kind, ViewKind::Depth);
    EXPECT_EQ(out[0].glTarget, unsigned(GL_TEXTURE_2D));
    EXPECT_EQ(out[1].glTarget, unsigned(GL_TEXTURE_CUBE_MAP));
    // Spot: the nearest occluder point is its corner (0.1, 2, 0.1), at sqrt(1.02) from the light; the
    // centre of the map looks straight down at the floor, 3 away.
    const Image spotMap = gl::readTexture(out[0].glTexture);
    ASSERT_EQ(spotMap.width, size);
    float nearest = 1e30f;
    for (float v : spotMap.pixels) nearest = std::min(nearest, v);
    const double corner = std::sqrt(1.02);
    EXPECT_GE(nearest, corner * (1.0 - 1e-5));
    EXPECT_LE(nearest, corner + 2.0 * 3.0 * std::tan(1.0) / size);  // within a texel's footprint
    EXPECT_NEAR(spotMap.at(size / 2, size / 2), 3.0, 3.0 * 1e-3);  // texel centre 1/2 texel off-axis
    // Point cube, -Y face (layer 3): the same geometry seen from the same place.
    const Image down = gl::readTexture(out[1].glTexture, 0, 3);
    float nearestCube = 1e30f;
    for (float v : down.pixels) nearestCube = std::min(nearestCube, v);
    EXPECT_GE(nearestCube, corner * (1.0 - 1e-5));
    EXPECT_LE(nearestCube, corner + 2.0 * 3.0 / size);
}

// ShadowMaps::nearest (a GPU reduction) against an exhaustive loop over the read-back texels of every
// face, and against the geometry: the occluder's nearest corner sqrt(1.02) from the light. A second
// light and the cube's six faces make the layer arithmetic matter; an upper bound below the value wins.
TEST_F(RenderPipeline, NearestStoredDistanceIsTheMinimumOverTheMapsTexels) {
    scene::Scene s = occluderScene();
    const scene::Light spot = spotAboveOccluder();
    scene::Light far = spot;
    far.position = {0.0, 6.0, 0.0};
    scene::Light point = spot;
    point.type = scene::LightType::Point;
    point.position = {0.25, 2.6, 0.25};  // 0.6 above the occluder's centre
    s.lights = {spot, far, point};
    GpuScene gpuScene(s);
    GpuLights lights(s, s.camera.position, 1);
    ShadowMaps shadows;
    const int size = 128;
    shadows.build(gpuScene, lights, size, 32);
    const double geometric[] = {std::sqrt(1.02), std::sqrt(4.0 * 4.0 + 0.02), 0.6};
    for (int i = 0; i < 3; ++i) {
        const GpuLightCpu& L = lights.lights()[std::size_t(i)];
        ASSERT_GE(L.info.z, 0) << i;
        float exhaustive = 1e30f;
        const int faces = L.info.x == hd::kLightPoint ? 6 : 1;
        for (int f = 0; f < faces; ++f)
            for (float v : shadows.texels(L, f)) exhaustive = std::min(exhaustive, std::max(v, 0.0f));
        EXPECT_EQ(shadows.nearest(L, 1e30f), exhaustive) << "light " << i;
        EXPECT_GE(exhaustive, geometric[i] * (1.0 - 1e-5)) << "light " << i;
        EXPECT_LE(exhaustive, geometric[i] + 0.1) << "light " << i;
        EXPECT_EQ(shadows.nearest(L, 0.25f), 0.25f) << "light " << i;
    }
}

TEST_F(RenderPipeline, DirectionalShadowMapOccludesAlongTheTravelDirection) {
    scene::Scene s = occluderScene();
    scene::Light sun{.type = scene::LightType::Directional, .direction = glm::normalize(glm::dvec3(0.3, -1.0, 0.2))};
    s.lights = {sun};
    // Shadow of the occluder centre on the floor: c + dir * (2 / |dir.y|) = (0.85, 0, 0.65); half 0.15.
    const glm::dvec3 c = glm::dvec3(0.25, 2.0, 0.25) + sun.direction * (2.0 / -sun.direction.y);
    const std::vector<glm::dvec3> pts = {c, c + glm::dvec3(0.08, 0.0, -0.08), 0.5 * (c + glm::dvec3(0.25, 2.0, 0.25)),
                                         c + glm::dvec3(-0.5, 0.0, 0.0), c + glm::dvec3(0.0, 0.0, -0.5),
                                         c + glm::dvec3(0.5, 0.0, 0.5), {-3.0, 0.0, -3.0}, {0.25, 2.5, 0.25}};
    const auto v = visibility(s, s.camera.position, 0, pts);
    const std::vector<float> expected = {0, 0, 0, 1, 1, 1, 1, 1};
    for (std::size_t i = 0; i < pts.size(); ++i) EXPECT_EQ(v[i], expected[i]) << "point " << i;
}

TEST_F(RenderPipeline, PointShadowCubeOccludesOnEveryFace) {
    // Light at the origin; on each axis (both signs) an occluder at distance 1, off-centre by +0.25 in
    // both tangent directions, covering [0.1, 0.4]^2. A point at distance 2 seen through (0.25, 0.25) is
    // shadowed; the mirror images in either tangent are lit: catches flipped or swapped face axes.
    scene::Scene s;
    for (int axis = 0; axis < 3; ++axis) {
        for (double sign : {1.0, -1.0}) {
            glm::dvec3 c(0.0);
            c[axis] = sign;
            c[(axis + 1) % 3] = 0.25;
            c[(axis + 2) % 3] = 0.25;
            s.meshes.push_back(quad(c, axis, {0.15, 0.15}));
        }
    }
    s.camera = lookCamera({0.1, 0.2, 0.3}, {0.0, 0.0, -1.0}, 50.0);
    scene::Light point{.type = scene::LightType::Point, .position = {0.0, 0.0, 0.0}};
    s.lights = {point};
    std::vector<glm::dvec3> pts;
    std::vector<float> expected;
    for (int axis = 0; axis < 3; ++axis) {
        for (double sign : {1.0, -1.0}) {
            for (auto [ta, tb] : {std::pair{0.5, 0.5}, {-0.5, 0.5}, {0.5, -0.5}, {-0.5, -0.5}}) {
                glm::dvec3 p(0.0);
                p[axis] = 2.0 * sign;
                p[(axis + 1) % 3] = ta;
                p[(axis + 2) % 3] = tb;
                pts.push_back(p);
                expected.push_back(ta > 0 && tb > 0 ? 0.0f : 1.0f);
            }
        }
    }
    const auto v = visibility(s, s.camera.position, 0, pts);
    for (std::size_t i = 0; i < pts.size(); ++i) {
        EXPECT_EQ(v[i], expected[i]) << "point " << pts[i].x << "," << pts[i].y << "," << pts[i].z;
    }
}

TEST_F(RenderPipeline, VplShadowCubeOccludesBelowTheOccluderOnly) {
    scene::Scene s = occluderScene();
    scene::Light area{.type = scene::LightType::Area,
                      .position = {0.0, 3.0, 0.0},
                      .direction = {0.0, -1.0, 0.0},
                      .halfU = {0.05, 0.0, 0.0},
                      .halfV = {0.0, 0.0, 0.05},
                      .radiance = {1.0, 1.0, 1.0}};
    s.lights = {area};
    // One VPL at the centre (visibility() uses area_samples = 1): the same shadow as the spot test.
    const std::vector<glm::dvec3> pts = {{0.75, 0.0, 0.75}, {0.6, 0.0, 0.9}, {0.5, 1.0, 0.5},
                                         {-0.75, 0.0, 0.75}, {0.75, 0.0, -0.75}, {2.0, 0.0, 1.0}};
    const auto v = visibility(s, s.camera.position, 0, pts, 64);
    const std::vector<float> expected = {0, 0, 0, 1, 1, 1};
    for (std::size_t i = 0; i < pts.size(); ++i) EXPECT_EQ(v[i], expected[i]) << "point " << i;
}

TEST_F(RenderPipeline, ShadowedFloorIsDarkInTheSurfacePass) {
    scene::Scene s = occluderScene();
    scene::Light point{.type = scene::LightType::Point, .position = {0.0, 3.0, 0.0}, .intensity = 10.0};
    s.lights = {point};
    // Looking down at the shadow centre (0.75, 0, 0.75); the view ray passes the occluder's height at
    // z = 1.17, beside it, so the centre pixel sees shadowed floor.
    s.camera = lookCamera({0.75, 6.0, 2.0}, {0.75, 0.0, 0.75}, 50.0);
    const Frame f = renderSurface(s, 32, 24);
    const glm::dvec3 d = scene::pixelRay(s.camera, 32, 24, 16, 12);
    const double t = (0.0 - s.camera.position.y) / d.y;
    const glm::dvec3 p = s.camera.position + t * d;
    // The pixel centre's floor point is inside the shadow (centre (0.75, 0.75), half 0.45).
    ASSERT_TRUE(std::abs(p.x - 0.75) < 0.2 && std::abs(p.z - 0.75) < 0.2);
    EXPECT_NEAR(f.distance.at(16, 12), t, 1e-4 * t);
    EXPECT_EQ(f.radiance.at(16, 12, 0), 0.0f);
    // A floor pixel far from the shadow is lit.
    EXPECT_GT(f.radiance.at(2, 2, 0), 0.0f);
}

}  // namespace
}  // namespace viz::render::test
