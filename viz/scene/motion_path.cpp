// Evaluating a motion path at one frame (the parsing is in motion_path_parse.cpp).
#include "scene/motion_path.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/error.h"
#include "scene/camera.h"
#include "scene/light_orbit.h"
#include "scene/orbit_target.h"

namespace viz::scene {

namespace {

constexpr glm::dvec3 kWorldUp{0.0, 1.0, 0.0};
constexpr double kTwoPi = 2.0 * std::numbers::pi;

bool isLightMotion(MotionKind k) { return k == MotionKind::LightOrbit || k == MotionKind::LightSweep; }

// The first light, checked movable.
Light& movableLight(Pose& pose, const std::string& pathText) {
    if (pose.lights.empty()) throw InputError("path '" + pathText + "' moves the first light, but the scene has none");
    Light& light = pose.lights[0];
    if (light.type == LightType::Area)
        throw InputError("path '" + pathText + "' moves the first light, but '" + light.name +
                         "' is an area light (its emitter is scene geometry and cannot move)");
    return light;
}

void orbitCamera(Camera& camera, glm::dvec3 target, double angle) {
    if (angle == 0.0) return;
    camera.position = target + rotateAbout(camera.position - target, kWorldUp, angle);
    camera.forward = glm::normalize(rotateAbout(camera.forward, kWorldUp, angle));
    camera.up = glm::normalize(rotateAbout(camera.up, kWorldUp, angle));
}

// The vertical axis, unless the light's offset from its aim (a directional light's direction) is within a
// degree of it; then the camera's right axis, which is horizontal for an unrolled camera.
glm::dvec3 sweepAxis(const Light& light, glm::dvec3 aim, const Camera& camera) {
    const glm::dvec3 v = light.type == LightType::Directional ? light.direction : light.position - aim;
    const double length = glm::length(v);
    if (length > 0.0 && std::abs(glm::dot(v / length, kWorldUp)) < std::cos(std::numbers::pi / 180.0)) return kWorldUp;
    return cameraRight(camera);
}

void sweepLight(Light& light, glm::dvec3 centre, const Camera& camera, double angle) {
    if (angle == 0.0) return;
    const glm::dvec3 aim = lightAim(light, centre);
    const glm::dvec3 axis = sweepAxis(light, aim, camera);
    if (light.type == LightType::Directional) {
        light.direction = glm::normalize(rotateAbout(light.direction, axis, angle));
        return;
    }
    light.position = aim + rotateAbout(light.position - aim, axis, angle);
    if (light.type == LightType::Spot) light.direction = glm::normalize(rotateAbout(light.direction, axis, angle));
}

Pose declarativePose(const MotionPath& path, const Scene& scene, int index, int count) {
    Pose pose{scene.camera, scene.lights};
    // Every motion turns about the scene's orbit target as the scene places it (not as earlier motions
    // moved the camera), so the order only matters where motions of the camera combine.
    const double distance = orbitDistance(scene);
    const glm::dvec3 target = orbitTarget(scene);
    const double phase = double(index) / double(count);  // 0 .. (N-1)/N
    const double wave = std::sin(kTwoPi * phase);
    const double inOut = 0.5 * (1.0 - std::cos(kTwoPi * phase));
    for (const Motion& m : path.motions) {
        switch (m.kind) {
            case MotionKind::CameraOrbit: orbitCamera(pose.camera, target, m.amount * phase); break;
            case MotionKind::CameraDolly: {
                const double offset = (m.percent ? m.amount * distance : m.amount) * inOut;
                if (offset != 0.0) pose.camera.position += glm::normalize(pose.camera.forward) * offset;
                break;
            }
            case MotionKind::LightOrbit: {
                Light& light = movableLight(pose, path.text);
                light = orbitLight(light, target, m.amount / kTwoPi * phase);
                break;
            }
            case MotionKind::LightSweep:
                sweepLight(movableLight(pose, path.text), target, scene.camera, m.amount * wave);
                break;
        }
    }
    return pose;
}

glm::dvec3 lerp(glm::dvec3 a, glm::dvec3 b, double s) { return s == 0.0 ? a : s == 1.0 ? b : a + (b - a) * s; }

Pose keyframePose(const MotionPath& path, const Scene& scene, int index, int count) {
    Pose pose{scene.camera, scene.lights};
    const std::vector<Keyframe>& keys = path.keyframes;
    const double first = keys.front().time, last = keys.back().time;
    const double u = count > 1 ? first + (last - first) * double(index) / double(count - 1) : first;
    // The segment [keys[k], keys[k + 1]] holding u (the last one for u at the end).
    std::size_t k = 0;
    while (k + 2 < keys.size() && u >= keys[k + 1].time) ++k;
    const Keyframe& a = keys[k];
    const Keyframe& b = keys.size() > 1 ? keys[k + 1] : a;
    const double s = b.time > a.time ? std::clamp((u - a.time) / (b.time - a.time), 0.0, 1.0) : 0.0;
    if (a.cameraPosition) {
        Camera& c = pose.camera;
        c.position = lerp(*a.cameraPosition, *b.cameraPosition, s);
        const glm::dvec3 view = lerp(*a.cameraTarget, *b.cameraTarget, s) - c.position;
        const glm::dvec3 upHint = a.cameraUp ? lerp(*a.cameraUp, *b.cameraUp, s) : scene.camera.up;
        const double viewLength = glm::length(view);
        if (!(viewLength > 1e-12))
            throw InputError("path '" + path.text + "': at frame " + std::to_string(index) +
                             " the camera's target is at its position");
        c.forward = view / viewLength;
        const glm::dvec3 up = upHint - c.forward * glm::dot(upHint, c.forward);
        if (!(glm::length(up) > 1e-9))
            throw InputError("path '" + path.text + "': at frame " + std::to_string(index) +
                             " the camera looks along its up direction");
        c.up = glm::normalize(up);
    }
    if (a.lightPosition || a.lightDirection) {
        Light& light = movableLight(pose, path.text);
        if (a.lightPosition) light.position = lerp(*a.lightPosition, *b.lightPosition, s);
        if (a.lightDirection) {
            const glm::dvec3 d = lerp(*a.lightDirection, *b.lightDirection, s);
            if (!(glm::length(d) > 1e-12))
                throw InputError("path '" + path.text + "': at frame " + std::to_string(index) +
                                 " the light's direction vanishes (opposite directions in neighbouring keyframes)");
            light.direction = glm::normalize(d);
        }
    }
    return pose;
}

std::string degrees(double radians) {
    char text[32];
    std::snprintf(text, sizeof text, "%g deg", radians * 180.0 / std::numbers::pi);
    return text;
}

}  // namespace

bool MotionPath::movesCamera() const {
    for (const Motion& m : motions)
        if (!isLightMotion(m.kind)) return true;
    return !keyframes.empty() && keyframes.front().cameraPosition.has_value();
}

bool MotionPath::movesLight() const {
    for (const Motion& m : motions)
        if (isLightMotion(m.kind)) return true;
    return !keyframes.empty() && (keyframes.front().lightPosition || keyframes.front().lightDirection);
}

Pose poseAt(const MotionPath& path, const Scene& scene, int index, int count) {
    VIZ_CHECK(count >= 1 && index >= 0 && index < count, "poseAt: frame index out of range");
    VIZ_CHECK(path.motions.empty() != path.keyframes.empty(), "poseAt: a path has motions or keyframes");
    return path.keyframes.empty() ? declarativePose(path, scene, index, count)
                                  : keyframePose(path, scene, index, count);
}

void applyPose(const Pose& pose, Scene& scene) {
    scene.camera = pose.camera;
    scene.lights = pose.lights;
}

std::string describeMotionPath(const MotionPath& path) {
    if (!path.keyframes.empty())
        return "keyframes from " + path.text + " (" + std::to_string(path.keyframes.size()) + " keys)";
    std::string out;
    for (const Motion& m : path.motions) {
        if (!out.empty()) out += ", ";
        switch (m.kind) {
            case MotionKind::CameraOrbit: out += "camera orbit " + degrees(m.amount); break;
            case MotionKind::LightOrbit: out += "light orbit " + degrees(m.amount); break;
            case MotionKind::LightSweep: out += "light sweep +-" + degrees(std::abs(m.amount)); break;
            case MotionKind::CameraDolly: {
                char text[48];
                if (m.percent) std::snprintf(text, sizeof text, "%g%% of the target distance", m.amount * 100.0);
                else std::snprintf(text, sizeof text, "%g scene units", m.amount);
                out += std::string("camera dolly ") + text;
                break;
            }
        }
    }
    return out;
}

}  // namespace viz::scene
