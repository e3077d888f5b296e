#include "camera_controller.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"

namespace airlight {

namespace {

const glm::dvec3 kWorldUp{0.0, 1.0, 0.0};
// Largest |pitch| the orbit and look keep: 89 degrees, so cross(forward, up) stays well defined.
constexpr double kMaxPitch = 1.5533430342749532;

glm::dvec3 rotateAbout(glm::dvec3 v, glm::dvec3 axis, double angle) {
    return glm::dvec3(glm::rotate(glm::dmat4(1.0), angle, axis) * glm::dvec4(v, 0.0));
}

// Elevation of a unit direction above the horizontal plane, radians.
double pitchOf(glm::dvec3 dir) { return std::asin(std::clamp(dir.y, -1.0, 1.0)); }

// Unit vector to the right of `forward` in the horizontal plane; `fallback` when forward is (nearly)
// vertical, as with a scene camera looking straight down.
glm::dvec3 horizontalRight(glm::dvec3 forward, glm::dvec3 fallback) {
    const glm::dvec3 r = glm::cross(forward, kWorldUp);
    const double len = glm::length(r);
    return len > 1e-9 ? r / len : fallback;
}

struct Frame {
    glm::dvec3 forward;
    glm::dvec3 right;  // hint for a vertical forward
};

// Rotates `dir` by yaw about world up, then by pitch about its right axis. The elevation is kept
// within +-kMaxPitch; a direction already beyond it (a vertical scene camera) may only turn back.
Frame turn(glm::dvec3 dir, glm::dvec3 right, double yaw, double pitch) {
    glm::dvec3 d = rotateAbout(dir, kWorldUp, yaw);
    right = rotateAbout(right, kWorldUp, yaw);
    const double current = pitchOf(d);
    // The allowed band widens to include the current elevation, so a direction beyond the limit
    // can turn back but not further out.
    const double wanted = std::clamp(current + pitch, std::min(current, -kMaxPitch), std::max(current, kMaxPitch));
    right = horizontalRight(d, right);
    d = rotateAbout(d, right, wanted - current);
    return {glm::normalize(d), right};
}

}  // namespace

CameraController::CameraController(const viz::scene::Camera& home, double targetDistance)
    : mHome(home), mSpeed(targetDistance), mCamera(home) {
    VIZ_CHECK(targetDistance > 0.0, "orbit target distance must be positive");
    mHome.forward = glm::normalize(mHome.forward);
    mHome.up = glm::normalize(mHome.up);
    mHomeTarget = mHome.position + mHome.forward * targetDistance;
    reset();
}

void CameraController::reset() {
    mCamera = mHome;
    mTarget = mHomeTarget;
}

void CameraController::place(const viz::scene::Camera& camera, glm::dvec3 target) {
    mCamera = camera;
    mCamera.forward = glm::normalize(mCamera.forward);
    mCamera.up = glm::normalize(mCamera.up);
    // An orbit target on the eye would make orbiting undefined: keep it in front at the usual distance.
    mTarget = glm::length(target - camera.position) > 1e-9 * mSpeed ? target : camera.position + mCamera.forward * mSpeed;
}

void CameraController::setOrientation(glm::dvec3 forward, glm::dvec3 rightHint) {
    mCamera.forward = glm::normalize(forward);
    const glm::dvec3 right = horizontalRight(mCamera.forward, rightHint);
    // Gram-Schmidt through the cross product: up is unit and orthogonal to forward by construction.
    mCamera.up = glm::normalize(glm::cross(right, mCamera.forward));
}

void CameraController::orbit(double yaw, double pitch) {
    const double distance = targetDistance();
    // The eye sits at target - forward * distance; turning forward turns the eye about the target.
    // Negative pitch on forward moves the eye up.
    const Frame f = turn(mCamera.forward, cameraRight(), yaw, -pitch);
    setOrientation(f.forward, f.right);
    mCamera.position = mTarget - mCamera.forward * distance;
}

void CameraController::zoom(double steps) {
    const double distance = targetDistance() * std::pow(0.85, steps);
    // Never pass through the target or sit on it (the near plane would clip everything).
    // Scale-free: the floor is the near plane's, whatever the scene's size.
    const double clamped = std::max(distance, mCamera.znear * 2.0);
    mCamera.position = mTarget - mCamera.forward * clamped;
}

void CameraController::pan(double dx, double dy) {
    const double visibleHeight = 2.0 * targetDistance() * std::tan(mCamera.yfov * 0.5);
    const glm::dvec3 offset = (cameraRight() * dx + mCamera.up * dy) * visibleHeight;
    mCamera.position += offset;
    mTarget += offset;
}

void CameraController::look(double yaw, double pitch) {
    const double distance = targetDistance();
    const Frame f = turn(mCamera.forward, cameraRight(), yaw, pitch);
    setOrientation(f.forward, f.right);
    mTarget = mCamera.position + mCamera.forward * distance;
}

void CameraController::move(glm::dvec3 amount) {
    const glm::dvec3 offset = (cameraRight() * amount.x + kWorldUp * amount.y + mCamera.forward * amount.z) * mSpeed;
    mCamera.position += offset;
    mTarget += offset;
}

}  // namespace airlight
