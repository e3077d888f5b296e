#include "render/light_culling.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "scene/camera.h"

namespace viz::render {

namespace {

struct Plane {
    glm::dvec3 n;  // inward unit normal
    double c;      // inside: dot(n, p) + c >= 0
};

// The view volume: apex at the eye, near plane at znear, far plane at zfar, sides through the eye.
std::array<Plane, 6> viewPlanes(const scene::Camera& cam, double aspect) {
    const glm::dvec3 f = glm::normalize(cam.forward), u = glm::normalize(cam.up);
    const glm::dvec3 r = glm::normalize(glm::cross(f, u));
    const double ty = std::tan(cam.yfov * 0.5), tx = ty * aspect;
    // Side normals point inwards: for the right side, the plane holds the eye and the edge direction
    // f + tx r; its inward normal is (tx f - r) normalised.
    const auto side = [&](glm::dvec3 n) {
        n = glm::normalize(n);
        return Plane{n, -glm::dot(n, cam.position)};
    };
    return {side(tx * f - r), side(tx * f + r), side(ty * f - u), side(ty * f + u),
            Plane{f, -glm::dot(f, cam.position) - cam.znear}, Plane{-f, glm::dot(f, cam.position) + cam.zfar}};
}

std::array<glm::dvec3, 8> viewCorners(const scene::Camera& cam, double aspect) {
    const glm::dvec3 f = glm::normalize(cam.forward), u = glm::normalize(cam.up);
    const glm::dvec3 r = glm::normalize(glm::cross(f, u));
    const double ty = std::tan(cam.yfov * 0.5), tx = ty * aspect;
    std::array<glm::dvec3, 8> corners;
    int k = 0;
    for (double depth : {cam.znear, cam.zfar})
        for (double sx : {-1.0, 1.0})
            for (double sy : {-1.0, 1.0}) corners[k++] = cam.position + depth * (f + sx * tx * r + sy * ty * u);
    return corners;
}

}  // namespace

bool lightReachesView(const scene::Light& light, const scene::Camera& camera) {
    const double aspect = std::max(camera.aspectRatio, kCullingAspect);
    switch (light.type) {
        case scene::LightType::Point:
        case scene::LightType::Directional:
            return true;
        case scene::LightType::Spot: {
            const glm::dvec3 axis = glm::normalize(light.direction);
            const double outer = std::min(light.outerConeAngle, 3.14159265358979323846 / 2.0);
            for (const Plane& p : viewPlanes(camera, aspect))
                if (glm::dot(p.n, light.position) + p.c < 0.0 && glm::dot(p.n, axis) <= -std::sin(outer)) return false;
            return true;
        }
        case scene::LightType::Area: {
            const glm::dvec3 n = glm::normalize(light.direction);
            for (const glm::dvec3& c : viewCorners(camera, aspect))
                if (glm::dot(n, c - light.position) > 0.0) return true;
            return false;
        }
    }
    return true;
}

std::vector<std::string> culledLightNames(const scene::Scene& scene) {
    std::vector<std::string> names;
    for (std::size_t i = 0; i < scene.lights.size(); ++i)
        if (!lightReachesView(scene.lights[i], scene.camera))
            names.push_back(scene.lights[i].name.empty() ? "light " + std::to_string(i) : scene.lights[i].name);
    return names;
}

void planCulledLights(const scene::Scene& scene, Plan& plan) {
    for (const std::string& name : culledLightNames(scene))
        plan.features.push_back({"LIGHT " + name, false,
                                 "its lit volume misses the view volume: no shadow map, no airlight, no lighting"});
}

}  // namespace viz::render
