#include "techniques/reference/ray_tracer.h"

#include <cmath>
#include <string>
#include <utility>

#include <embree3/rtcore.h>

#include "core/error.h"

namespace viz::reference {

namespace {

void embreeError(void*, RTCError code, const char* str) {
    // Embree reports misuse (bad buffers, out of memory) here; these are programmer errors.
    VIZ_CHECK(code == RTC_ERROR_NONE, std::string("embree: ") + (str ? str : "unknown error"));
}

RTCRay makeRay(const glm::dvec3& origin, const glm::dvec3& dir, double tNear, double tFar) {
    RTCRay ray{};
    ray.org_x = float(origin.x);
    ray.org_y = float(origin.y);
    ray.org_z = float(origin.z);
    ray.dir_x = float(dir.x);
    ray.dir_y = float(dir.y);
    ray.dir_z = float(dir.z);
    ray.tnear = float(tNear);
    ray.tfar = std::isinf(tFar) ? std::numeric_limits<float>::infinity() : float(tFar);
    ray.mask = 0xFFFFFFFFu;
    ray.time = 0.0f;
    ray.flags = 0;
    return ray;
}

}  // namespace

RayTracer::RayTracer(const scene::Scene& scene) {
    // Embree's default configuration: "threads=1" would cap the whole process's oneTBB at one thread while
    // the device lives, and with it the reference's row loop (tests/cpu/reference/parallel_rows_test.cpp).
    mDevice = rtcNewDevice(nullptr);
    VIZ_CHECK(mDevice != nullptr, "rtcNewDevice failed");
    rtcSetDeviceErrorFunction(mDevice, embreeError, nullptr);
    mScene = rtcNewScene(mDevice);
    // High build quality: the reference traces many rays per build.
    rtcSetSceneBuildQuality(mScene, RTC_BUILD_QUALITY_HIGH);
    rtcSetSceneFlags(mScene, RTC_SCENE_FLAG_ROBUST);

    // World-space extent, used to scale the offset of rays that leave a surface.
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        const scene::Mesh& mesh = scene.meshes[m];
        const std::size_t triangles = mesh.indices.size() / 3;
        // Geometry ids follow mesh indices, so an empty mesh still takes its slot.
        RTCGeometry geom = rtcNewGeometry(mDevice, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
            geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
            std::max<std::size_t>(mesh.positions.size(), 1)));
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
            vertices[3 * i + 0] = mesh.positions[i].x;
            vertices[3 * i + 1] = mesh.positions[i].y;
            vertices[3 * i + 2] = mesh.positions[i].z;
            lo = glm::min(lo, glm::dvec3(mesh.positions[i]));
            hi = glm::max(hi, glm::dvec3(mesh.positions[i]));
        }
        if (mesh.positions.empty()) {
            vertices[0] = vertices[1] = vertices[2] = 0.0f;
        }
        auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
            geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), triangles));
        for (std::size_t i = 0; i < 3 * triangles; ++i) {
            VIZ_CHECK(mesh.indices[i] < mesh.positions.size(), "mesh index out of range");
            indices[i] = mesh.indices[i];
        }
        rtcCommitGeometry(geom);
        rtcAttachGeometryByID(mScene, geom, unsigned(m));
        rtcReleaseGeometry(geom);
        mTriangleCount += triangles;
    }
    rtcCommitScene(mScene);
    mLo = lo;
    mHi = hi;
    if (mTriangleCount > 0) {
        // Float positions carry ~1e-7 relative error; offset rays well above that.
        const double extent = glm::length(hi - lo) + glm::length(glm::max(glm::abs(hi), glm::abs(lo)));
        mRayEpsilon = std::max(1e-6, 1e-5 * extent);
    }
}

RayTracer::~RayTracer() { release(); }

glm::dvec2 RayTracer::insideBounds(const glm::dvec3& origin, const glm::dvec3& dir, double tMax) const {
    if (mTriangleCount == 0) return {1.0, 0.0};
    // Slabs, widened by the ray offset so that a triangle in a face of the box counts as inside.
    glm::dvec2 r(0.0, tMax);
    for (int a = 0; a < 3; ++a) {
        const double lo = mLo[a] - mRayEpsilon, hi = mHi[a] + mRayEpsilon;
        if (dir[a] == 0.0) {
            if (origin[a] < lo || origin[a] > hi) return {1.0, 0.0};
            continue;
        }
        double t0 = (lo - origin[a]) / dir[a], t1 = (hi - origin[a]) / dir[a];
        if (t0 > t1) std::swap(t0, t1);
        r.x = std::max(r.x, t0);
        r.y = std::min(r.y, t1);
    }
    return r;
}

RayTracer::RayTracer(RayTracer&& other) noexcept
    : mDevice(std::exchange(other.mDevice, nullptr)),
      mScene(std::exchange(other.mScene, nullptr)),
      mTriangleCount(other.mTriangleCount),
      mRayEpsilon(other.mRayEpsilon),
      mLo(other.mLo),
      mHi(other.mHi) {}

RayTracer& RayTracer::operator=(RayTracer&& other) noexcept {
    if (this != &other) {
        release();
        mDevice = std::exchange(other.mDevice, nullptr);
        mScene = std::exchange(other.mScene, nullptr);
        mTriangleCount = other.mTriangleCount;
        mRayEpsilon = other.mRayEpsilon;
        mLo = other.mLo;
        mHi = other.mHi;
    }
    return *this;
}

void RayTracer::release() {
    if (mScene) rtcReleaseScene(mScene);
    if (mDevice) rtcReleaseDevice(mDevice);
    mScene = nullptr;
    mDevice = nullptr;
}

Hit RayTracer::intersect(const glm::dvec3& origin, const glm::dvec3& dir, double tMax) const {
    Hit hit;
    if (mTriangleCount == 0) return hit;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh{};
    rh.ray = makeRay(origin, dir, 0.0, tMax);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(mScene, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
    hit.found = true;
    hit.t = rh.ray.tfar;
    hit.mesh = int(rh.hit.geomID);
    hit.triangle = int(rh.hit.primID);
    hit.u = rh.hit.u;
    hit.v = rh.hit.v;
    return hit;
}

bool RayTracer::occludedSegment(const glm::dvec3& a, const glm::dvec3& b) const {
    if (mTriangleCount == 0) return false;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    // Unnormalised direction b - a: t in [eps, 1 - eps] covers the segment minus both ends.
    RTCRay ray = makeRay(a, b - a, kSegmentEpsilon, 1.0 - kSegmentEpsilon);
    rtcOccluded1(mScene, &context, &ray);
    return ray.tfar < 0.0f;
}

bool RayTracer::occludedRay(const glm::dvec3& a, const glm::dvec3& dir) const {
    if (mTriangleCount == 0) return false;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray = makeRay(a, dir, mRayEpsilon, std::numeric_limits<double>::infinity());
    rtcOccluded1(mScene, &context, &ray);
    return ray.tfar < 0.0f;
}

}  // namespace viz::reference
