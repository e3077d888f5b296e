#include "light_gizmo.h"

#include <cmath>

#include "scene/camera.h"

namespace airlight {

using viz::scene::Light;
using viz::scene::LightType;

namespace {

bool hasPositionHandle(const Light& light) { return light.type == LightType::Point || light.type == LightType::Spot; }
bool hasDirectionHandle(const Light& light) {
    return light.type == LightType::Spot || light.type == LightType::Directional;
}
// +1: the arm points the way the light travels (spot); -1: it points back to where the light comes from
// (directional, whose handle is the "sun").
double armSign(const Light& light) { return light.type == LightType::Directional ? -1.0 : 1.0; }

}  // namespace

LightGizmo::LightGizmo(const viz::scene::Camera& camera, glm::ivec2 frame, double arm, glm::dvec3 anchor)
    : mCamera(camera), mFrame(glm::max(frame, glm::ivec2(1))), mArm(arm > 0.0 ? arm : 1.0), mAnchor(anchor) {}

bool LightGizmo::hasHandles(const Light& light) { return hasPositionHandle(light) || hasDirectionHandle(light); }

glm::dvec3 LightGizmo::rayThrough(glm::dvec2 pixel) const {
    // scene::pixelRay(x, y) is this ray at (x + 0.5, y + 0.5).
    return viz::scene::pixelRay(mCamera, mFrame.x, mFrame.y, pixel.x - 0.5, pixel.y - 0.5);
}

std::optional<glm::dvec2> LightGizmo::project(glm::dvec3 world) const {
    const glm::dvec3 v = world - mCamera.position;
    const double z = glm::dot(v, mCamera.forward);
    if (!(z > 1e-9 * glm::length(v))) return std::nullopt;  // behind the eye, on its plane, or the eye itself
    const double tanHalf = std::tan(mCamera.yfov * 0.5);
    const double aspect = viz::scene::aspectOf(mCamera, mFrame.x, mFrame.y);
    const double ndcX = glm::dot(v, viz::scene::cameraRight(mCamera)) / (z * tanHalf * aspect);
    const double ndcY = glm::dot(v, mCamera.up) / (z * tanHalf);
    return glm::dvec2(0.5 * (ndcX + 1.0) * mFrame.x, 0.5 * (1.0 - ndcY) * mFrame.y);
}

glm::dvec3 LightGizmo::armRoot(const Light& light) const {
    return light.type == LightType::Directional ? mAnchor : light.position;
}

glm::dvec3 LightGizmo::armTip(const Light& light) const {
    return armRoot(light) + armSign(light) * mArm * glm::normalize(light.direction);
}

GizmoHandles LightGizmo::handles(const Light& light) const {
    GizmoHandles h;
    if (hasPositionHandle(light)) h.position = project(light.position);
    if (hasDirectionHandle(light)) {
        h.tip = project(armTip(light));
        h.root = project(armRoot(light));
    }
    return h;
}

bool LightGizmo::dragPosition(Light& light, glm::dvec2 pixel) const {
    if (!hasPositionHandle(light)) return false;
    const double depth = glm::dot(light.position - mCamera.position, mCamera.forward);
    if (!(depth > 0.0)) return false;
    const glm::dvec3 ray = rayThrough(pixel);
    const double along = glm::dot(ray, mCamera.forward);  // > 0 for every ray of the frustum and near it
    if (!(along > 1e-6)) return false;
    light.position = mCamera.position + ray * (depth / along);
    return true;
}

bool LightGizmo::dragDirection(Light& light, glm::dvec2 pixel) const {
    if (!hasDirectionHandle(light)) return false;
    const glm::dvec3 centre = armRoot(light), eye = mCamera.position, ray = rayThrough(pixel);
    const glm::dvec3 oldTip = armTip(light);
    // The ray against the sphere |x - centre| = arm: t^2 + 2 b t + c = 0 with b = ray.(eye - centre).
    const glm::dvec3 oc = eye - centre;
    const double b = glm::dot(ray, oc), c = glm::dot(oc, oc) - mArm * mArm;
    const double disc = b * b - c;
    glm::dvec3 tip;
    if (disc >= 0.0) {
        // Of the two crossings in front of the eye, the one nearer the current tip: the handle stays on
        // the side of the sphere it was on.
        const double root = std::sqrt(disc);
        const double t0 = -b - root, t1 = -b + root;
        const glm::dvec3 p0 = eye + ray * t0, p1 = eye + ray * t1;
        if (t1 < 0.0) return false;  // the whole sphere is behind the eye
        tip = t0 < 0.0 || glm::length(p1 - oldTip) < glm::length(p0 - oldTip) ? p1 : p0;
    } else {
        // Missed: the point of the sphere's outline (seen from the eye) towards the cursor, i.e. the
        // tangent from the eye in the plane of the eye, the centre and the ray. The eye is outside the
        // sphere here (a ray from inside always meets it): the tangent makes the angle asin(arm / D)
        // with the line to the centre and is sqrt(D^2 - arm^2) long.
        const double distance = glm::length(centre - eye);
        const glm::dvec3 w = (centre - eye) / distance;
        const glm::dvec3 across = ray - w * glm::dot(ray, w);
        const double acrossLength = glm::length(across);
        if (!(acrossLength > 0.0) || !(distance > mArm)) return false;
        const double sinA = mArm / distance, cosA = std::sqrt(std::max(0.0, 1.0 - sinA * sinA));
        const glm::dvec3 tangent = cosA * w + sinA * (across / acrossLength);
        tip = eye + tangent * std::sqrt(std::max(0.0, distance * distance - mArm * mArm));
    }
    const glm::dvec3 arm = tip - centre;
    const double length = glm::length(arm);
    if (!(length > 1e-12 * mArm)) return false;
    light.direction = armSign(light) * arm / length;
    return true;
}

}  // namespace airlight
