#include "scene/bounds.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <mutex>

namespace viz::scene {
namespace {

Bounds walkBounds(const Scene& scene) {
    Bounds b;
    for (const Mesh& mesh : scene.meshes) {
        for (const glm::vec3& p : mesh.positions) {
            const glm::dvec3 q(p);
            if (b.empty) {
                b.lo = b.hi = q;
                b.empty = false;
            } else {
                b.lo = glm::min(b.lo, q);
                b.hi = glm::max(b.hi, q);
            }
        }
    }
    return b;
}

// The last few stamped scenes' bounds: the window holds one scene and its comparison grid and CPU worker
// copies of it; bench and report a handful.
struct KeptBounds {
    std::mutex mutex;
    std::array<std::uint64_t, 8> keys{};
    std::array<Bounds, 8> bounds{};
    std::size_t next = 0;
};

KeptBounds& kept() {
    static KeptBounds k;
    return k;
}

}  // namespace

Bounds sceneBounds(const Scene& scene) {
    if (scene.geometryKey == 0) return walkBounds(scene);
    KeptBounds& k = kept();
    {
        const std::lock_guard<std::mutex> lock(k.mutex);
        for (std::size_t i = 0; i < k.keys.size(); ++i)
            if (k.keys[i] == scene.geometryKey) return k.bounds[i];
    }
    const Bounds b = walkBounds(scene);
    const std::lock_guard<std::mutex> lock(k.mutex);
    k.keys[k.next] = scene.geometryKey;
    k.bounds[k.next] = b;
    k.next = (k.next + 1) % k.keys.size();
    return b;
}

}  // namespace viz::scene
