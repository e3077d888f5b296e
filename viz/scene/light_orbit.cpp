#include "scene/light_orbit.h"

#include <cmath>
#include <numbers>

#include "core/error.h"

namespace viz::scene {

namespace {

// The axis of the orbit cone: `v` tilted by kOrbitTilt towards the horizontal (or, for a vertical v,
// towards +x), so that v lies on the cone's surface.
glm::dvec3 orbitAxis(glm::dvec3 v) {
    const glm::dvec3 n = glm::normalize(v);
    glm::dvec3 side = glm::cross(n, glm::dvec3(0.0, 1.0, 0.0));
    if (glm::length(side) < 1e-6) side = glm::cross(n, glm::dvec3(1.0, 0.0, 0.0));
    const glm::dvec3 perpendicular = glm::normalize(glm::cross(side, n));
    return glm::normalize(std::cos(kOrbitTilt) * n + std::sin(kOrbitTilt) * perpendicular);
}

}  // namespace

glm::dvec3 rotateAbout(glm::dvec3 v, glm::dvec3 axis, double angle) {
    if (angle == 0.0) return v;
    // Rodrigues: v cos + (a x v) sin + a (a . v)(1 - cos), a a unit vector.
    const double c = std::cos(angle), s = std::sin(angle);
    return v * c + glm::cross(axis, v) * s + axis * glm::dot(axis, v) * (1.0 - c);
}

glm::dvec3 lightAim(const Light& light, glm::dvec3 centre) {
    if (light.type == LightType::Spot)
        return light.position + glm::normalize(light.direction) * glm::length(centre - light.position);
    return centre;
}

Light orbitLight(const Light& light, glm::dvec3 centre, double turn) {
    if (light.type == LightType::Area)
        throw InputError("light orbit: the first light '" + light.name + "' is an area light, which cannot be moved");
    Light out = light;
    if (turn == std::floor(turn)) return out;  // whole turns: exactly where it started
    const double angle = 2.0 * std::numbers::pi * turn;
    if (light.type == LightType::Directional) {
        out.direction = glm::normalize(rotateAbout(light.direction, orbitAxis(light.direction), angle));
        return out;
    }
    const glm::dvec3 aim = lightAim(light, centre);
    const glm::dvec3 offset = light.position - aim;
    if (glm::length(offset) < 1e-9) return out;
    out.position = aim + rotateAbout(offset, orbitAxis(offset), angle);
    if (light.type == LightType::Spot) out.direction = glm::normalize(aim - out.position);
    return out;
}

}  // namespace viz::scene
