// common/spot_cone.glsl: a spot light's cones along an eye ray. The ray is cut where it crosses the outer
// and inner cones and the plane through the light normal to the axis, so that on each part A_spot is 0,
// 1, or the square of a smooth lobe (the penumbra; docs/numerics.md#spot-penumbra). Used by polyvol's
// segment integral and minmax's lit runs.
#ifndef COMMON_SPOT_CONE_GLSL
#define COMMON_SPOT_CONE_GLSL

#include "common/host_device.glsl"
#include "common/airlight.glsl"
#include "common/lights.glsl"
#include "common/sort.glsl"

// The direction from the light to the ray's point at angle phi: (m / h) cos(phi) + w sin(phi), m = P - light
// (see spotConeCuts), with no difference of |eye - light|-sized vectors (a ray passing 1e-4 from a light
// 5 away would lose ~0.5 % of the direction to rounding, and the spot factor's penumbra slope of ~15 per
// unit cosine turned that into a few % per piece next to the apex).
vec3 directionFromLight(vec3 m, float h, vec3 w, float phi) {
    return normalize((m / h) * cos(phi) + w * sin(phi));
}

// Roots in (x0, x1) of the double cone of half-angle acos(c) around the unit axis a through the light,
// appended to `breaks`. Written relative to the foot point P of the light on the ray: a point of the ray is
// t = tP + s, its offset from the light is m + s w with m = P - light (|m| = h, m . w = 0), and the cone is
//   f(s) = (m.a + s w.a)^2 - c^2 (h^2 + s^2) = A s^2 + B s + C,
//   A = (w.a)^2 - c^2,  B = 2 (m.a)(w.a),  C = (m.a)^2 - c^2 h^2,  B^2 - 4 A C = 4 c^2 ((m.a)^2 + A h^2).
// Every coefficient is of the size of h^2, h s or s^2 near the light, and the discriminant is formed
// without the difference B^2 - 4 A C: with t-coefficients of the size of |eye - light|^2 that difference
// cancelled for a ray passing within ~1e-3 |eye - light| of the apex (float keeps ~7 digits, the two roots
// are h apart), the cuts landed ~sqrt(eps) |eye - light| from where they belong and the pieces next to
// the light were classified inside or outside the cone wrongly (README, "Rays next to the light").
// The degenerate test on A (a ray parallel to the cone's surface) is taken in units of the largest |s|
// of the segment, so it stays scale-free.
void coneRoots(vec3 m, float h, vec3 w, float tP, vec3 a, float c, float x0, float x1, inout float breaks[8],
               inout int n) {
    float wa = dot(w, a), ma = dot(m, a);
    float S = max(max(h, abs(x0 - tP)), min(abs(x1 - tP), 1.0e30));
    float A = wa * wa - c * c;
    float B = 2.0 * ma * wa;
    float C = ma * ma - c * c * h * h;
    float r[2];
    int k = 0;
    if (abs(A) * S < 1e-7 * (abs(B) + abs(C) / S + 1e-30)) {
        if (B != 0.0) r[k++] = -C / B;
    } else {
        float disc = 4.0 * c * c * (ma * ma + A * h * h);
        if (disc >= 0.0) {
            // Stable pair: q = -(B + sign(B) sqrt(disc)) / 2, roots q / A and C / q.
            float q = -0.5 * (B + (B >= 0.0 ? 1.0 : -1.0) * sqrt(disc));
            r[k++] = q / A;
            if (q != 0.0) r[k++] = C / q;
        }
    }
    for (int i = 0; i < k; ++i) {
        float t = tP + r[i];
        if (t > x0 && t < x1 && n < 8) breaks[n++] = t;
    }
}

// The cuts of [x0, x1]: breaks[0] = x0, then the crossings in order (at most 5); part i is [breaks[i],
// breaks[i + 1]] and the last ends at x1. m = P - light and h (floored at 1e-7 |tP|) for the directions.
struct SpotCuts {
    float breaks[8];
    int n;
    vec3 m;
    float h;
};

SpotCuts spotConeCuts(GpuLight L, vec3 w, RayLightGeometry g, float x0, float x1) {
    SpotCuts c;
    c.h = max(g.h, 1.0e-7 * max(abs(g.tP), 1.0e-20));
    // m = P - light = (D x w) x w (D = light - eye): every position along the ray is m + s w relative to
    // the light, s = t - tP, so no direction near the light is a difference of two |eye - light|-sized
    // vectors. Formed from cross products (|m| = |D x w| = g.h, and m . w = 0 up to rounding) rather than as
    // tP w - D, whose component along w would be tP's rounding (~1e-7 |D|, 0.5 % of h at h = 1e-4, |D| = 5).
    c.m = cross(cross(L.position.xyz, w), w);
    vec3 a = L.direction.xyz;
    c.n = 0;
    c.breaks[c.n++] = x0;
    coneRoots(c.m, c.h, w, g.tP, a, L.spot.w, x0, x1, c.breaks, c.n);
    coneRoots(c.m, c.h, w, g.tP, a, spotCosInner(L), x0, x1, c.breaks, c.n);
    float wa = dot(w, a);
    if (wa != 0.0) {
        float tPlane = g.tP - dot(c.m, a) / wa;
        if (tPlane > x0 && tPlane < x1 && c.n < 8) c.breaks[c.n++] = tPlane;
    }
    // Insertion sort (at most 5 interior points).
    SORT_ASCENDING(c.breaks, c.n);
    return c;
}

// Where a part [xa, xb] of the cuts lies, classified at its middle: outside the outer cone (A_spot = 0),
// in the penumbra, or inside the inner cone (A_spot = 1).
const int kSpotDark = 0;
const int kSpotPenumbra = 1;
const int kSpotInside = 2;

int spotZone(GpuLight L, SpotCuts c, vec3 w, float tP, float xa, float xb) {
    float cd = dot(directionFromLight(c.m, c.h, w, atan(0.5 * (xa + xb) - tP, c.h)), L.direction.xyz);
    return cd <= L.spot.w ? kSpotDark : (cd >= spotCosInner(L) ? kSpotInside : kSpotPenumbra);
}

#endif  // COMMON_SPOT_CONE_GLSL
