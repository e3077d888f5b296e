// The light gizmo's handles and drags (app/light_gizmo.h): handles sit where the light projects, and a
// drag leaves the dragged handle under the cursor without changing what it must not change.
#include <gtest/gtest.h>

#include <cmath>

#include "light_gizmo.h"
#include "scene/camera.h"

namespace airlight {
namespace {

using viz::scene::Light;
using viz::scene::LightType;

viz::scene::Camera testCamera() {
    viz::scene::Camera c;
    c.position = {1.0, 2.0, 10.0};
    c.forward = glm::normalize(glm::dvec3(-0.1, -0.2, -1.0));
    c.up = glm::normalize(glm::cross(glm::cross(c.forward, glm::dvec3(0, 1, 0)), c.forward));
    c.yfov = 0.9;
    return c;
}

const glm::ivec2 kFrame{160, 120};

Light spot() {
    Light l{.type = LightType::Spot,
            .position = {0.5, 3.0, 2.0},
            .direction = glm::normalize(glm::dvec3(0.2, -1.0, -0.3))};
    return l;
}

void expectNear(glm::dvec2 a, glm::dvec2 b, double tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
}

TEST(LightGizmo, ProjectionIsTheInverseOfThePixelRay) {
    const auto cam = testCamera();
    const LightGizmo gizmo(cam, kFrame, 1.0, {});
    for (const glm::ivec2 px : {glm::ivec2(0, 0), glm::ivec2(80, 60), glm::ivec2(159, 7), glm::ivec2(3, 119)}) {
        const glm::dvec3 p = cam.position + 7.5 * viz::scene::pixelRay(cam, kFrame.x, kFrame.y, px.x, px.y);
        const auto projected = gizmo.project(p);
        ASSERT_TRUE(projected);
        expectNear(*projected, glm::dvec2(px) + 0.5, 1e-9);
    }
    EXPECT_FALSE(gizmo.project(cam.position - cam.forward));  // behind the eye
    EXPECT_FALSE(gizmo.project(cam.position));
}

TEST(LightGizmo, DraggingThePositionKeepsTheDepthAndFollowsTheCursor) {
    const auto cam = testCamera();
    const LightGizmo gizmo(cam, kFrame, 1.0, {});
    Light light = spot();
    const double depth = glm::dot(light.position - cam.position, cam.forward);
    const glm::dvec3 direction = light.direction;
    ASSERT_TRUE(gizmo.dragPosition(light, {20.25, 100.5}));
    expectNear(*gizmo.handles(light).position, {20.25, 100.5}, 1e-9);
    EXPECT_NEAR(glm::dot(light.position - cam.position, cam.forward), depth, 1e-12);
    EXPECT_EQ(light.direction, direction);

    Light behind = spot();
    behind.position = cam.position - 3.0 * cam.forward;
    const glm::dvec3 before = behind.position;
    EXPECT_FALSE(gizmo.handles(behind).position);
    EXPECT_FALSE(gizmo.dragPosition(behind, {80.0, 60.0}));
    EXPECT_EQ(behind.position, before);
}

TEST(LightGizmo, DraggingTheTipTurnsTheSpotAboutItsPosition) {
    const auto cam = testCamera();
    const double arm = 1.5;
    const LightGizmo gizmo(cam, kFrame, arm, {});
    Light light = spot();
    const glm::dvec3 position = light.position;
    const auto h = gizmo.handles(light);
    ASSERT_TRUE(h.tip && h.root && h.position);
    expectNear(*h.tip, *gizmo.project(position + arm * light.direction), 1e-9);
    expectNear(*h.root, *h.position, 1e-12);
    // A small drag (the ray meets the arm's sphere): the tip lands under the cursor.
    const glm::dvec2 target = *h.tip + glm::dvec2(6.0, -4.0);
    ASSERT_TRUE(gizmo.dragDirection(light, target));
    EXPECT_NEAR(glm::length(light.direction), 1.0, 1e-12);
    EXPECT_EQ(light.position, position);
    expectNear(*gizmo.handles(light).tip, target, 1e-6);
    // Far outside the sphere's silhouette: the tip goes to the silhouette, still a unit direction.
    ASSERT_TRUE(gizmo.dragDirection(light, {159.0, 0.0}));
    EXPECT_NEAR(glm::length(light.direction), 1.0, 1e-12);
    const glm::dvec3 tip = position + arm * light.direction;
    const glm::dvec3 ray = gizmo.rayThrough({159.0, 0.0});
    const glm::dvec3 toTip = tip - cam.position;
    // On the outline the line of sight to the tip is tangent to the sphere, and the tip lies towards
    // the cursor: in the plane of the eye, the arm's root and the cursor's ray.
    EXPECT_NEAR(glm::dot(tip - position, toTip), 0.0, 1e-9 * glm::length(toTip));
    EXPECT_NEAR(glm::dot(glm::cross(position - cam.position, ray), toTip), 0.0, 1e-9 * glm::length(toTip));
    EXPECT_GT(glm::dot(glm::normalize(toTip), ray), glm::dot(glm::normalize(position - cam.position), ray));
}

TEST(LightGizmo, ASpotBehindTheCameraIsTurnedByItsTipAlone) {
    const auto cam = testCamera();
    const double arm = 2.0;
    const LightGizmo gizmo(cam, kFrame, arm, {});
    Light light = spot();
    light.position = cam.position - 0.5 * cam.forward;  // just behind the eye, shining forward
    light.direction = cam.forward;
    const auto h = gizmo.handles(light);
    EXPECT_FALSE(h.position);
    EXPECT_FALSE(h.root);
    ASSERT_TRUE(h.tip);
    const glm::dvec2 target = *h.tip + glm::dvec2(3.0, 2.0);
    ASSERT_TRUE(gizmo.dragDirection(light, target));
    expectNear(*gizmo.handles(light).tip, target, 1e-6);
    EXPECT_NEAR(glm::length(light.direction), 1.0, 1e-12);
}

TEST(LightGizmo, ADirectionalLightsHandleIsWhereItsLightComesFrom) {
    const auto cam = testCamera();
    const glm::dvec3 anchor{0.0, 0.0, 0.0};
    const double arm = 3.0;
    const LightGizmo gizmo(cam, kFrame, arm, anchor);
    Light sun{.type = LightType::Directional, .direction = glm::normalize(glm::dvec3(0.3, -1.0, 0.2))};
    const auto h = gizmo.handles(sun);
    EXPECT_FALSE(h.position);
    ASSERT_TRUE(h.tip && h.root);
    expectNear(*h.tip, *gizmo.project(anchor - arm * sun.direction), 1e-9);
    expectNear(*h.root, *gizmo.project(anchor), 1e-9);
    const glm::dvec2 target = *h.tip + glm::dvec2(-5.0, 3.0);
    ASSERT_TRUE(gizmo.dragDirection(sun, target));
    expectNear(*gizmo.handles(sun).tip, target, 1e-6);
    // The light still travels towards the anchor from its handle: downwards here.
    EXPECT_LT(sun.direction.y, 0.0);
    EXPECT_FALSE(gizmo.dragPosition(sun, target));
}

TEST(LightGizmo, PointLightsHaveNoArmAndAreaLightsNoHandles) {
    const LightGizmo gizmo(testCamera(), kFrame, 1.0, {});
    Light point = spot();
    point.type = LightType::Point;
    const glm::dvec3 direction = point.direction;
    EXPECT_TRUE(gizmo.handles(point).position);
    EXPECT_FALSE(gizmo.handles(point).tip);
    EXPECT_FALSE(gizmo.dragDirection(point, {10.0, 10.0}));
    EXPECT_EQ(point.direction, direction);
    Light area = spot();
    area.type = LightType::Area;
    EXPECT_FALSE(LightGizmo::hasHandles(area));
    EXPECT_FALSE(gizmo.handles(area).position || gizmo.handles(area).tip);
}

}  // namespace
}  // namespace airlight
