// Interactive camera: orbit about a target or fly, starting from (and resettable to) the scene camera.
// Plain math on viz::scene::Camera, no window or GL, so it is tested on the CPU.
// World space is the scene's (glTF: +Y up); yaw turns about world up, pitch about the camera's right
// axis, and the camera never rolls except when reset to a rolled scene camera.
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace airlight {

class CameraController {
public:
    enum class Mode { Orbit, Fly };

    // home: the scene camera. targetDistance: how far in front of it the orbit target lies
    // (scene units, > 0); it also sets the speed of panning and flying.
    CameraController(const viz::scene::Camera& home, double targetDistance);

    const viz::scene::Camera& camera() const { return mCamera; }
    glm::dvec3 target() const { return mTarget; }
    double targetDistance() const { return glm::length(mTarget - mCamera.position); }
    Mode mode() const { return mMode; }
    void setMode(Mode mode) { mMode = mode; }
    void toggleMode() { mMode = mMode == Mode::Orbit ? Mode::Fly : Mode::Orbit; }

    // Back to the scene camera and its target; keeps the mode.
    void reset();
    // Places the camera (a restored session); the target keeps its distance rule only through `target`.
    void place(const viz::scene::Camera& camera, glm::dvec3 target);

    // ---- orbit ----
    // Turns the eye about the target: yaw about world up, pitch about the camera's right axis
    // (radians, positive pitch moves the eye up). The distance to the target does not change; pitch
    // stops short of the poles so that forward never becomes parallel to world up.
    void orbit(double yaw, double pitch);
    // Moves the eye towards the target by the factor 0.85^steps (steps > 0 zooms in); the target stays.
    void zoom(double steps);
    // Moves eye and target together in the view plane. dx, dy are fractions of the view height
    // (a drag across the whole view height pans by the visible height at the target's distance);
    // +dx moves the camera right, +dy up.
    void pan(double dx, double dy);

    // ---- fly ----
    // Turns the view direction from the eye (radians): yaw about world up, pitch about right.
    void look(double yaw, double pitch);
    // Moves the eye (and the target with it) in the camera frame: x right, y world up, z forward;
    // `amount` is in units of targetDistance at construction (so speed scales with the scene).
    void move(glm::dvec3 amount);

private:
    // Sets forward and rebuilds up from the horizontal right axis (rightHint when forward is vertical).
    void setOrientation(glm::dvec3 forward, glm::dvec3 rightHint);
    glm::dvec3 cameraRight() const { return glm::normalize(glm::cross(mCamera.forward, mCamera.up)); }

    viz::scene::Camera mHome;
    glm::dvec3 mHomeTarget{0.0};
    double mSpeed = 1.0;  // scene units per unit of move()
    viz::scene::Camera mCamera;
    glm::dvec3 mTarget{0.0};
    Mode mMode = Mode::Orbit;
};

}  // namespace airlight
