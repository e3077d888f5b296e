// Where the sampling planes go (Mitchell 2004, "Positioning the Sampling Planes"): the view-space
// axis-aligned bounding box of a light's frustum, cut to the depth range [0, zfar] in front of the eye.
// Plane i of N sits at the midpoint of slab i, s_i = far - (i + 1/2) delta_s, delta_s = (far - near) / N,
// but never nearer than just beyond the camera's znear, where it would be clipped: when the eye is inside
// the box, the nearest slab still covers [0, delta_s] of the ray (a thick medium can put half of L_air
// before znear), sampled at drawNear.
// View space here = eye-relative world projected on the camera basis: x along right, y along up, s (depth)
// along forward. The light frustum is the clip volume of its shadow matrix (eye-relative world -> clip).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

namespace viz {

struct CameraBasis {
    glm::dvec3 forward, right, up;  // unit, world axes
};

struct PlaneRange {
    bool empty = true;
    glm::dvec2 minXY{0.0}, maxXY{0.0};  // box extent across the view (x: right, y: up)
    double near = 0.0, far = 0.0;       // view depth range covered by the slabs
    double spacing = 0.0;               // delta_s = (far - near) / N
    double drawNear = 0.0;              // planes nearer than this are drawn at it (znear, with a margin)
    int planes = 0;                     // slabs from far to near: the N asked for, or the world grid's count
    double nearestWeight = 1.0;         // the nearest slab's part in front of the eye, in units of spacing
};

// lightMatrix: eye-relative world -> the light's clip space; its inverse maps the 8 NDC cube corners to
// the frustum's corners (a perspective frustum is the convex hull of its corners, so the box of the corners
// bounds it).
inline PlaneRange planeRange(const glm::dmat4& lightMatrix, const CameraBasis& basis, double znear, double zfar,
                             int planes) {
    const glm::dmat4 inv = glm::inverse(lightMatrix);
    PlaneRange r;
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec4 ndc((corner & 1) ? 1.0 : -1.0, (corner & 2) ? 1.0 : -1.0, (corner & 4) ? 1.0 : -1.0, 1.0);
        glm::dvec4 p = inv * ndc;
        p /= p.w;
        const glm::dvec3 v(glm::dot(glm::dvec3(p), basis.right), glm::dot(glm::dvec3(p), basis.up),
                           glm::dot(glm::dvec3(p), basis.forward));
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
    // The slabs cover the rays from the eye on; beyond zfar every ray has ended (t >= s). Planes nearer
    // than znear would be clipped by the camera, so they are drawn just beyond it.
    r.near = std::max(lo.z, 0.0);
    r.drawNear = znear * 1.001;
    r.far = std::min(hi.z, zfar);
    if (!(r.far > r.near) || planes < 1) return r;
    r.empty = false;
    r.minXY = glm::dvec2(lo.x, lo.y);
    r.maxXY = glm::dvec2(hi.x, hi.y);
    r.spacing = (r.far - r.near) / double(planes);
    r.planes = planes;
    return r;
}

// plane_grid=world: the same range on slabs fixed in the world, so that planes do not sweep through the
// scene when the light or the camera moves (they stay put while the camera only turns about its forward
// axis or moves along it, and while the light moves at all). The spacing is the fitted (far - near) / N
// rounded up to a power of 2^(1/4) (it changes only when the box's depth grows or shrinks by a quarter
// octave: the count stays between 0.84 N and N + 2); the slab boundaries are its multiples in world
// depth dot(p_world, forward) = dot(p, forward) + eyeDepth, eyeDepth = dot(eye, forward). The slabs cover
// the fitted range outward to whole slabs. When the eye lies inside the nearest slab, only its part in
// front of the eye is on the rays: nearestWeight < 1 (its plane is still drawn at the slab's midpoint, or
// just beyond znear when that is behind the eye, both inside that part).
inline PlaneRange worldGridRange(const PlaneRange& fitted, double eyeDepth) {
    PlaneRange r = fitted;
    if (r.empty || !(r.spacing > 0.0)) return r;
    const double spacing = std::exp2(std::ceil(std::log2(r.spacing) * 4.0) / 4.0);
    const double first = std::floor((fitted.near + eyeDepth) / spacing);
    const double last = std::ceil((fitted.far + eyeDepth) / spacing);
    r.spacing = spacing;
    r.near = first * spacing - eyeDepth;
    r.far = last * spacing - eyeDepth;
    r.planes = std::max(1, int(std::lround(last - first)));
    r.nearestWeight = r.near < 0.0 ? std::clamp((r.near + spacing) / spacing, 0.0, 1.0) : 1.0;
    return r;
}

// Plane count scaled down with the eye's distance from the light volume (Mitchell 2004, "Efficiency"):
// N' = clamp(round(N * referenceDistance / distance), minPlanes, N); referenceDistance <= 0 keeps N. The
// per-plane weight compensates by itself: the physical weight uses the spacing (far - near) / N', and the
// artistic scale 9 / (N' / 100) uses N'.
inline int scaledPlaneCount(int planes, double distance, double referenceDistance, int minPlanes) {
    if (referenceDistance <= 0.0 || distance <= referenceDistance) return planes;
    const int scaled = int(std::lround(double(planes) * referenceDistance / distance));
    return std::clamp(scaled, std::min(minPlanes, planes), planes);
}

// The frustum's six planes in eye-relative world space as (n, c) with dot(n, p) + c >= 0 inside: the
// rows of the clip matrix combined as w + x, w - x, w + y, w - y, w + z, w - z (the same sums the vertex
// shader writes to gl_ClipDistance).
inline std::array<glm::dvec4, 6> frustumPlanes(const glm::dmat4& m) {
    const glm::dmat4 t = glm::transpose(m);  // t[i] = row i of m
    return {t[3] + t[0], t[3] - t[0], t[3] + t[1], t[3] - t[1], t[3] + t[2], t[3] - t[2]};
}

// Sutherland-Hodgman: the part of a convex polygon with dot(plane, (p, 1)) >= 0.
inline std::vector<glm::dvec3> clipPolygon(const std::vector<glm::dvec3>& poly, const glm::dvec4& plane) {
    std::vector<glm::dvec3> out;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const glm::dvec3& a = poly[i];
        const glm::dvec3& b = poly[(i + 1) % poly.size()];
        const double da = glm::dot(glm::dvec3(plane), a) + plane.w;
        const double db = glm::dot(glm::dvec3(plane), b) + plane.w;
        if (da >= 0.0) out.push_back(a);
        if ((da >= 0.0) != (db >= 0.0)) out.push_back(a + (b - a) * (da / (da - db)));
    }
    return out;
}

// The sampling planes as the debugger shows them from outside: plane i's quad (eye-relative world,
// corners in the vertex shader's order) clipped to the frustum when `clip` is set. Empty when clipped away.
// `wholeSlab` (integration=equiangular): widened as plane.vert widens them, to every point p of the plane
// whose ray meets the frustum somewhere in the slab (the points f p, f in [s_lo / s, s_hi / s]): the box
// scaled by s / s_lo and s / s_hi, and each frustum plane (n, c) tested at f_lo p where c >= 0 (it keeps
// the eye) and at f_hi p otherwise; cut to the view (tangents of its half-angles `viewTan`, 1 % wider).
inline std::vector<std::vector<glm::dvec3>> planePolygons(const PlaneRange& r, const CameraBasis& basis,
                                                          const glm::dmat4& lightMatrix, int planes, bool clip,
                                                          bool wholeSlab = false, glm::dvec2 viewTan = glm::dvec2(1e30)) {
    std::vector<std::vector<glm::dvec3>> out;
    if (r.empty) return out;
    const auto frustum = frustumPlanes(lightMatrix);
    for (int i = 0; i < planes; ++i) {
        const double mid = r.far - (double(i) + 0.5) * r.spacing;
        const double s = std::max(mid, r.drawNear);
        const double lo = std::max(mid - 0.5 * r.spacing, 0.0), hi = mid + 0.5 * r.spacing;
        glm::dvec2 boxMin = r.minXY, boxMax = r.maxXY;
        if (wholeSlab) {
            const double scaleLo = s / std::max(lo, 1e-3 * s), scaleHi = s / hi;
            const glm::dvec2 view = 1.01 * s * viewTan;
            boxMin = glm::clamp(glm::min(r.minXY * scaleLo, r.minXY * scaleHi), -view, view);
            boxMax = glm::clamp(glm::max(r.maxXY * scaleLo, r.maxXY * scaleHi), -view, view);
        }
        std::vector<glm::dvec3> poly;
        for (const glm::dvec2 c : {glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(1, 1), glm::dvec2(0, 1)}) {
            const glm::dvec2 xy = boxMin + (boxMax - boxMin) * c;
            poly.push_back(xy.x * basis.right + xy.y * basis.up + s * basis.forward);
        }
        if (clip)
            for (const glm::dvec4& plane : frustum) {
                const double f = !wholeSlab ? 1.0 : plane.w >= 0.0 ? lo / s : hi / s;
                poly = clipPolygon(poly, glm::dvec4(glm::dvec3(plane) * f, plane.w));
            }
        out.push_back(poly);
    }
    return out;
}

}  // namespace viz
