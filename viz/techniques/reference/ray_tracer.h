// Exact triangle visibility for the reference: one Embree 3 scene holding every triangle of every mesh
// (world space). Embree works in float; the reference keeps everything else in double.
#pragma once

#include <cstdint>
#include <limits>

#include <glm/glm.hpp>

#include "scene/scene.h"

// Embree's handles are opaque pointers; forward-declared so that users need not include rtcore.h.
typedef struct RTCDeviceTy* RTCDevice;
typedef struct RTCSceneTy* RTCScene;

namespace viz::reference {

struct Hit {
    bool found = false;
    double t = 0.0;      // distance along the unit ray direction
    int mesh = -1;       // index into Scene::meshes
    int triangle = -1;   // triangle index inside that mesh
    double u = 0.0;      // barycentrics of vertices 1 and 2 (vertex 0 has 1 - u - v)
    double v = 0.0;
};

// Owns an Embree device and a committed scene. Move-only; thread-safe queries after construction.
class RayTracer {
public:
    explicit RayTracer(const scene::Scene& scene);
    ~RayTracer();
    RayTracer(const RayTracer&) = delete;
    RayTracer& operator=(const RayTracer&) = delete;
    RayTracer(RayTracer&& other) noexcept;
    RayTracer& operator=(RayTracer&& other) noexcept;

    // First hit of origin + t * dir (dir unit) with t in (0, tMax].
    Hit intersect(const glm::dvec3& origin, const glm::dvec3& dir, double tMax) const;

    // True when the open segment from a to b is blocked, ignoring a fraction kSegmentEpsilon of the
    // segment at each end (so the surfaces a and b lie on do not block themselves).
    bool occludedSegment(const glm::dvec3& a, const glm::dvec3& b) const;
    // True when the ray from a towards unit direction dir is blocked anywhere beyond a small offset.
    bool occludedRay(const glm::dvec3& a, const glm::dvec3& dir) const;

    // Relative end trim of occlusion segments, and absolute start offset (scene units) of rays.
    static constexpr double kSegmentEpsilon = 1e-5;
    double rayEpsilon() const { return mRayEpsilon; }
    bool empty() const { return mTriangleCount == 0; }
    // The part [x, y] of origin + t dir, t in [0, tMax], inside the box around every triangle (where every
    // occluder lies); x >= y when the ray misses it. The box's diagonal (0 without triangles).
    glm::dvec2 insideBounds(const glm::dvec3& origin, const glm::dvec3& dir, double tMax) const;
    double boundsDiagonal() const { return mTriangleCount > 0 ? glm::length(mHi - mLo) : 0.0; }

private:
    void release();

    RTCDevice mDevice = nullptr;
    RTCScene mScene = nullptr;
    std::size_t mTriangleCount = 0;
    double mRayEpsilon = 1e-5;
    glm::dvec3 mLo{0.0}, mHi{0.0};
};

}  // namespace viz::reference
