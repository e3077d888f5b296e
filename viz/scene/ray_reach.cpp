#include "scene/ray_reach.h"

#include <algorithm>

#include "scene/bounds.h"

namespace viz::scene {

double farSpan(const Scene& scene) { return kFarSpanRadii * 0.5 * sceneBounds(scene).diagonal(); }

double longestLitSpan(const Scene& scene) {
    const double sigmaT = scene.medium.sigma_t();
    return sigmaT > 0.0 ? std::min(scene.camera.zfar, kReachMeanFreePaths / sigmaT) : scene.camera.zfar;
}

double depthOfInterest(const Scene& scene) {
    const double zfar = scene.camera.zfar;
    const Bounds b = sceneBounds(scene);
    if (b.empty || zfar <= kFarSpanRadii * 0.5 * b.diagonal()) return zfar;
    double far = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 p((corner & 1) ? b.hi.x : b.lo.x, (corner & 2) ? b.hi.y : b.lo.y, (corner & 4) ? b.hi.z : b.lo.z);
        far = std::max(far, glm::length(p - scene.camera.position));
    }
    for (const Light& light : scene.lights)
        if (light.type != LightType::Directional) far = std::max(far, glm::length(light.position - scene.camera.position));
    // A little past the farthest point, so that a surface there stays inside.
    return std::min(zfar, far * 1.01);
}

}  // namespace viz::scene
