#include "scene/default_lighting.h"

#include <algorithm>
#include <cmath>

namespace viz::scene {

Light defaultSpotLight(const Scene& scene) {
    const Bounds b = sceneBounds(scene);
    const glm::dvec3 centre = b.centre();
    const double extent = 0.5 * b.diagonal();  // scale-free; a point-like scene gets a unit radius
    const double radius = extent > 0.0 && std::isfinite(extent) ? extent : 1.0;
    // The camera's right, flattened onto the ground plane (glTF is +Y up).
    glm::dvec3 right = glm::cross(scene.camera.forward, glm::dvec3(0, 1, 0));
    right.y = 0.0;
    const double len = glm::length(right);
    right = len > 1e-9 ? right / len : glm::dvec3(1, 0, 0);

    Light l;
    l.name = "default spot";
    l.type = LightType::Spot;
    l.position = centre + radius * (2.5 * glm::dvec3(0, 1, 0) + right);
    const glm::dvec3 toCentre = centre - l.position;
    const double distance = glm::length(toCentre);
    l.direction = toCentre / distance;
    l.outerConeAngle = std::clamp(std::atan(1.4 * radius / distance), 0.2, 1.2);
    l.innerConeAngle = 0.75 * l.outerConeAngle;
    l.colour = glm::dvec3(1.0, 0.95, 0.85);
    l.intensity = 10.0 * distance * distance;
    return l;
}

Medium scaleAwareMedium(const Scene& scene) {
    const double diagonal = sceneBounds(scene).diagonal();
    Medium m;
    m.sigma_s = diagonal > 0.0 ? 0.5 / diagonal : 0.05;
    return m;
}

}  // namespace viz::scene
