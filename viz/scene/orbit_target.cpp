#include "scene/orbit_target.h"

#include <algorithm>
#include <cmath>

namespace viz::scene {

double firstHit(const Scene& scene, glm::dvec3 origin, glm::dvec3 dir) {
    double best = -1.0;
    for (const auto& mesh : scene.meshes) {
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            const glm::dvec3 a(mesh.positions[mesh.indices[i]]);
            const glm::dvec3 e1 = glm::dvec3(mesh.positions[mesh.indices[i + 1]]) - a;
            const glm::dvec3 e2 = glm::dvec3(mesh.positions[mesh.indices[i + 2]]) - a;
            const glm::dvec3 p = glm::cross(dir, e2);
            const double det = glm::dot(e1, p);
            // Scale-free tests: a ray parallel to the triangle (or a sliver) by its own size, a hit behind
            // or on the origin by the distance to the triangle.
            if (!(std::abs(det) > 1e-12 * glm::length(e1) * glm::length(e2))) continue;
            const glm::dvec3 s = origin - a;
            const double u = glm::dot(s, p) / det;
            if (u < 0.0 || u > 1.0) continue;
            const glm::dvec3 q = glm::cross(s, e1);
            const double v = glm::dot(dir, q) / det;
            if (v < 0.0 || u + v > 1.0) continue;
            const double t = glm::dot(e2, q) / det;
            if (t > 1e-9 * glm::length(s) && (best < 0.0 || t < best)) best = t;
        }
    }
    return best;
}

double orbitDistance(const Scene& scene) {
    const glm::dvec3 forward = glm::normalize(scene.camera.forward);
    const double hit = firstHit(scene, scene.camera.position, forward);
    if (hit > 0.0 && hit < scene.camera.zfar) return hit;
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const auto& mesh : scene.meshes)
        for (const glm::vec3& p : mesh.positions) {
            lo = glm::min(lo, glm::dvec3(p));
            hi = glm::max(hi, glm::dvec3(p));
        }
    if (lo.x > hi.x) return 5.0;
    const glm::dvec3 centre = 0.5 * (lo + hi);
    const double extent = 0.5 * glm::length(hi - lo);  // scale-free; a point-like scene gets a unit radius
    const double radius = extent > 0.0 ? extent : 1.0;
    const double along = glm::dot(centre - scene.camera.position, forward);
    return along > 0.1 * radius ? along : radius;
}

glm::dvec3 orbitTarget(const Scene& scene) {
    return scene.camera.position + glm::normalize(scene.camera.forward) * orbitDistance(scene);
}

}  // namespace viz::scene
