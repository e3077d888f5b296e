// CameraController: orbit keeps the distance to the target, reset restores the scene camera, fly
// moves along the view direction, and the camera frame stays orthonormal.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "camera_controller.h"

namespace {

constexpr double kEps = 1e-9;

viz::scene::Camera lookAt(glm::dvec3 eye, glm::dvec3 at, glm::dvec3 worldUp = {0, 1, 0}) {
    viz::scene::Camera cam;
    cam.position = eye;
    cam.forward = glm::normalize(at - eye);
    const glm::dvec3 right = glm::normalize(glm::cross(cam.forward, worldUp));
    cam.up = glm::cross(right, cam.forward);
    cam.yfov = 0.9;
    return cam;
}

void expectNear(glm::dvec3 a, glm::dvec3 b, double eps = kEps) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

void expectOrthonormal(const viz::scene::Camera& cam) {
    EXPECT_NEAR(glm::length(cam.forward), 1.0, 1e-12);
    EXPECT_NEAR(glm::length(cam.up), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(cam.forward, cam.up), 0.0, 1e-12);
}

}  // namespace

TEST(CameraController, TargetLiesOnTheViewAxisAtTheGivenDistance) {
    const glm::dvec3 eye{1.0, 2.0, 5.0}, at{0.0, 0.5, 0.0};
    airlight::CameraController cc(lookAt(eye, at), glm::length(at - eye));
    expectNear(cc.target(), at);
    EXPECT_NEAR(cc.targetDistance(), glm::length(at - eye), kEps);
}

TEST(CameraController, OrbitKeepsDistanceAndLooksAtTarget) {
    const glm::dvec3 eye{1.0, 2.0, 5.0}, at{0.3, 0.5, -0.2};
    airlight::CameraController cc(lookAt(eye, at), glm::length(at - eye));
    const double d0 = cc.targetDistance();
    for (int i = 0; i < 50; ++i) {
        cc.orbit(0.13 * (i % 7 - 3), 0.07 * (i % 5 - 2));
        EXPECT_NEAR(glm::length(cc.camera().position - at), d0, 1e-9);
        expectNear(glm::normalize(at - cc.camera().position), cc.camera().forward, 1e-9);
        expectOrthonormal(cc.camera());
    }
    expectNear(cc.target(), at);
}

TEST(CameraController, OrbitYawQuarterTurnMovesEyeAroundWorldUp) {
    // Eye on +Z looking at the origin; a quarter turn of yaw (counter-clockwise seen from above)
    // carries the eye to +X.
    airlight::CameraController cc(lookAt({0, 0, 5}, {0, 0, 0}), 5.0);
    cc.orbit(std::numbers::pi / 2.0, 0.0);
    expectNear(cc.camera().position, {5.0, 0.0, 0.0});
    expectNear(cc.camera().up, {0.0, 1.0, 0.0});
}

TEST(CameraController, OrbitPitchRaisesEyeOnCircle) {
    airlight::CameraController cc(lookAt({0, 0, 5}, {0, 0, 0}), 5.0);
    cc.orbit(0.0, 0.3);
    expectNear(cc.camera().position, {0.0, 5.0 * std::sin(0.3), 5.0 * std::cos(0.3)});
}

TEST(CameraController, OrbitPitchStopsShortOfThePole) {
    airlight::CameraController cc(lookAt({0, 0, 5}, {0, 0, 0}), 5.0);
    cc.orbit(0.0, 10.0);
    EXPECT_LT(cc.camera().position.y, 5.0);
    EXPECT_GT(cc.camera().position.y, 4.9);
    EXPECT_GT(cc.camera().up.y, 0.0);
    EXPECT_NEAR(cc.targetDistance(), 5.0, kEps);
    expectOrthonormal(cc.camera());
    cc.orbit(0.0, -20.0);
    EXPECT_LT(cc.camera().position.y, -4.9);
    EXPECT_GT(cc.camera().up.y, 0.0);
}

TEST(CameraController, ZoomScalesDistanceAndKeepsTarget) {
    airlight::CameraController cc(lookAt({0, 0, 5}, {0, 0, 0}), 5.0);
    cc.zoom(2.0);
    EXPECT_NEAR(cc.targetDistance(), 5.0 * 0.85 * 0.85, kEps);
    expectNear(cc.target(), {0, 0, 0});
    cc.zoom(-2.0);
    EXPECT_NEAR(cc.targetDistance(), 5.0, kEps);
    cc.zoom(1000.0);
    EXPECT_GT(cc.targetDistance(), 0.0);
    expectNear(cc.camera().forward, {0, 0, -1});
}

TEST(CameraController, PanMovesEyeAndTargetInTheViewPlane) {
    airlight::CameraController cc(lookAt({0, 0, 5}, {0, 0, 0}), 5.0);
    const double visibleHeight = 2.0 * 5.0 * std::tan(0.9 * 0.5);
    cc.pan(0.5, -0.25);
    expectNear(cc.camera().position, {0.5 * visibleHeight, -0.25 * visibleHeight, 5.0});
    expectNear(cc.target(), {0.5 * visibleHeight, -0.25 * visibleHeight, 0.0});
    expectNear(cc.camera().forward, {0, 0, -1});
}

TEST(CameraController, ResetRestoresSceneCamera) {
    const viz::scene::Camera home = lookAt({1.0, 2.0, 5.0}, {0.0, 0.5, 0.0});
    airlight::CameraController cc(home, 3.0);
    const glm::dvec3 homeTarget = cc.target();
    cc.orbit(0.7, 0.2);
    cc.zoom(3.0);
    cc.pan(0.1, 0.2);
    cc.setMode(airlight::CameraController::Mode::Fly);
    cc.look(0.4, -0.3);
    cc.move({1.0, 0.5, 2.0});
    cc.reset();
    expectNear(cc.camera().position, home.position, 0.0);
    expectNear(cc.camera().forward, home.forward, 1e-15);
    expectNear(cc.camera().up, home.up, 1e-15);
    EXPECT_EQ(cc.camera().yfov, home.yfov);
    expectNear(cc.target(), homeTarget, 1e-15);
    EXPECT_EQ(cc.mode(), airlight::CameraController::Mode::Fly);
}

TEST(CameraController, FlyMovesAlongForward) {
    const viz::scene::Camera home = lookAt({1.0, 2.0, 5.0}, {0.0, 0.5, 0.0});
    airlight::CameraController cc(home, 4.0);
    cc.move({0.0, 0.0, 0.5});
    // move() is in units of the construction distance (4): half a unit is 2 scene units.
    expectNear(cc.camera().position, home.position + home.forward * 2.0);
    expectNear(cc.camera().forward, home.forward);
    EXPECT_NEAR(cc.targetDistance(), 4.0, kEps);
    cc.move({0.0, 0.25, 0.0});
    expectNear(cc.camera().position, home.position + home.forward * 2.0 + glm::dvec3(0.0, 1.0, 0.0));
}

TEST(CameraController, FlyLookTurnsInPlaceAndStaysOrthonormal) {
    airlight::CameraController cc(lookAt({0, 1, 5}, {0, 1, 0}), 5.0);
    cc.look(std::numbers::pi / 2.0, 0.0);
    expectNear(cc.camera().position, {0, 1, 5});
    expectNear(cc.camera().forward, {-1, 0, 0});
    for (int i = 0; i < 40; ++i) {
        cc.look(0.21, 0.37);
        expectOrthonormal(cc.camera());
        EXPECT_GT(cc.camera().up.y, 0.0);
        EXPECT_NEAR(glm::length(cc.target() - cc.camera().position), 5.0, 1e-9);
    }
    expectNear(cc.camera().position, {0, 1, 5});
}

TEST(CameraController, VerticalSceneCameraOrbitsWithoutNaN) {
    // A camera looking straight down with up = -Z, as glTF top views are often authored.
    viz::scene::Camera home;
    home.position = {0, 5, 0};
    home.forward = {0, -1, 0};
    home.up = {0, 0, -1};
    airlight::CameraController cc(home, 5.0);
    cc.orbit(0.5, 0.0);
    cc.orbit(0.0, -0.2);
    expectOrthonormal(cc.camera());
    EXPECT_NEAR(cc.targetDistance(), 5.0, 1e-9);
    expectNear(cc.target(), {0, 0, 0});
    EXPECT_FALSE(std::isnan(cc.camera().position.x));
}

TEST(CameraController, ToggleModeSwitchesBetweenOrbitAndFly) {
    airlight::CameraController cc(lookAt({0, 0, 5}, {0, 0, 0}), 5.0);
    EXPECT_EQ(cc.mode(), airlight::CameraController::Mode::Orbit);
    cc.toggleMode();
    EXPECT_EQ(cc.mode(), airlight::CameraController::Mode::Fly);
    cc.toggleMode();
    EXPECT_EQ(cc.mode(), airlight::CameraController::Mode::Orbit);
}
