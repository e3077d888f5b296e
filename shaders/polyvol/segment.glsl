// polyvol/segment.glsl: unshadowed airlight of one light along [x0, x1] of the pixel-centre ray w (eye at
// the origin, eye-relative world), with the light's whole angular factor. Shared by the volume's
// fragment shader and the per-pixel resolve.
#ifndef POLYVOL_SEGMENT_GLSL
#define POLYVOL_SEGMENT_GLSL

#include "common/host_device.glsl"
#include "common/airlight.glsl"
#include "common/lights.glsl"
#include "common/sort.glsl"
#include "polyvol/airlight_lut.glsl"
#include "common/camera_ray.glsl"

#include "common/medium.glsl"  // uSigmaS, uSigmaT, uG
uniform int uSpotPieces;   // spot lights: equal-angle pieces per penumbra part (see angularSegment)

// Unit-intensity airlight of [x0, x1] with the angular factor `lobe` (the segment integral), or of an
// isotropic source (the lookup table, which has no lobe: callers pass AIRLIGHT_NO_LOBE there).
float unitPointSegment(RayLightGeometry g, float x0, float x1, vec4 lobe) {
#ifdef AIRLIGHT_LUT
    return lutPointSegment(g.tP, g.h, x0, x1, uSigmaS, uSigmaT, uG);
#else
    return pointSegmentWithLobe(g.tP, g.h, x0, x1, uSigmaS, uSigmaT, uG, 1.0, lobe);
#endif
}

// Equal-angle pieces of [x0, x1]: the direction from the light is a function of the angle
// phi = atan((t - tP) / h) alone, so equal angles are equal steps of the angular factor; each piece is the
// exact unit-intensity integral (pointSegment) times the angular factor at its middle angle.
// Under a cookie the pieces follow its texels instead: about one piece per cookie texel the segment
// sweeps (texel angle 2 atan(tan(outer)) / width), at least uSpotPieces, at most kMaxCookiePieces.
const int kMaxCookiePieces = 64;

// The direction from the light to the ray's point at angle phi: (m / h) cos(phi) + w sin(phi), m = P - light
// (see angularSegment), with no difference of |eye - light|-sized vectors (a ray passing 1e-4 from a light
// 5 away would lose ~0.5 % of the direction to rounding, and the spot factor's penumbra slope of ~15 per
// unit cosine turned that into a few % per piece next to the apex).
vec3 directionFromLight(vec3 m, float h, vec3 w, float phi) {
    return normalize((m / h) * cos(phi) + w * sin(phi));
}

// lightIntensity toward a direction from the light (the light moved to the origin: lightIntensity only
// forms p - position from its point).
vec3 lightIntensityToward(GpuLight L, vec3 dirFromLight) {
    L.position.xyz = vec3(0.0);
    return lightIntensity(L, dirFromLight);
}

// whole: the part lies inside a spot's inner cone with no cookie, where A_spot = 1: one exact piece at the
// light's full intensity. A spot's penumbra without a cookie is one exact piece too with the segment
// integral: A_spot there is the square of a lobe in the integrand's own variable (spotPenumbraLobeOf),
// integrated on the segment's panels; the pieces remain for the lookup table (no lobe) and cookies.
// (One loop for all, so that the segment integral is inlined once: llvmpipe runs every inlined copy for
// the whole invocation group, whichever lanes need it.)
vec3 angularPieces(GpuLight L, vec3 w, RayLightGeometry g, float h, float x0, float x1, bool whole) {
    vec3 m = cross(cross(L.position.xyz, w), w);  // P - light, see angularSegment
    float phi0 = atan(x0 - g.tP, h);
    float phi1 = atan(x1 - g.tP, h);
    vec4 lobe = AIRLIGHT_NO_LOBE;
#ifndef AIRLIGHT_LUT
    if (!whole && L.info.x == kLightSpot && L.info.y < 0) {
        lobe = spotPenumbraLobeOf(L.position.xyz, w, L.direction.xyz, L.spot.x, L.spot.y);
        whole = true;
    }
#endif
    int pieces = whole ? 1 : uSpotPieces;
#ifndef LIGHTS_NO_COOKIE
    if (!whole && L.info.x == kLightSpot && L.info.y >= 0) {
        pieces = clamp(int(ceil(abs(phi1 - phi0) / cookieTexelAngle(L))), uSpotPieces, max(uSpotPieces, kMaxCookiePieces));
    }
#endif
    vec3 sum = vec3(0.0);
    float xa = x0;
    for (int k = 0; k < pieces; ++k) {
        float xb = k + 1 == pieces ? x1 : g.tP + h * tan(mix(phi0, phi1, float(k + 1) / float(pieces)));
        xb = clamp(xb, xa, x1);
        float phiMid = mix(phi0, phi1, (float(k) + 0.5) / float(pieces));
        vec3 a = whole ? L.radiant.rgb : lightIntensityToward(L, directionFromLight(m, h, w, phiMid));
        if (any(greaterThan(a, vec3(0.0)))) sum += a * unitPointSegment(g, xa, xb, lobe);
        xa = xb;
    }
    return sum;
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

// A spot light's segment. A_spot and the cookie depend on the direction from the light, which turns
// along the segment, so they do not factor out of the integral. The segment is cut where it crosses the
// outer and inner cones and the plane through the light normal to the axis; each part is classified at
// its middle: outside the outer cone it adds nothing, inside the inner cone (no cookie) A_spot = 1 and the
// part is exact, in the penumbra exact too with the segment integral (A_spot's lobe), and under a cookie
// (or with the lookup table) it takes uSpotPieces or more equal-angle pieces (angularPieces).
vec3 angularSegment(GpuLight L, vec3 w, RayLightGeometry g, float x0, float x1) {
    float h = max(g.h, 1.0e-7 * max(abs(g.tP), 1.0e-20));
    // m = P - light = (D x w) x w (D = light - eye): every position along the ray is m + s w relative to
    // the light, s = t - tP, so no direction near the light is a difference of two |eye - light|-sized
    // vectors. Formed from cross products (|m| = |D x w| = g.h, and m . w = 0 up to rounding) rather than as
    // tP w - D, whose component along w would be tP's rounding (~1e-7 |D|, 0.5 % of h at h = 1e-4, |D| = 5).
    vec3 m = cross(cross(L.position.xyz, w), w);
    vec3 a = L.direction.xyz;
    float cosOuter = L.spot.w;
    float cosInner = spotCosInner(L);
    float breaks[8];
    int n = 0;
    breaks[n++] = x0;
    coneRoots(m, h, w, g.tP, a, cosOuter, x0, x1, breaks, n);
    coneRoots(m, h, w, g.tP, a, cosInner, x0, x1, breaks, n);
    float wa = dot(w, a);
    if (wa != 0.0) {
        float tPlane = g.tP - dot(m, a) / wa;
        if (tPlane > x0 && tPlane < x1 && n < 8) breaks[n++] = tPlane;
    }
    // Insertion sort (at most 6 interior points), then x1.
    SORT_ASCENDING(breaks, n);
    bool cookie = L.info.y >= 0;
    vec3 sum = vec3(0.0);
    for (int i = 0; i < n; ++i) {
        float xa = breaks[i];
        float xb = i + 1 < n ? breaks[i + 1] : x1;
        if (!(xb > xa)) continue;
        vec3 dirMid = directionFromLight(m, h, w, atan(0.5 * (xa + xb) - g.tP, h));
        float cd = dot(dirMid, a);
        if (cd <= cosOuter) continue;  // outside the outer cone: A_spot = 0
        sum += angularPieces(L, w, g, h, xa, xb, cd >= cosInner && !cookie);  // inside the inner cone: whole
    }
    return sum;
}

vec3 segmentAirlight(GpuLight L, vec3 w, float x0, float x1) {
    if (!(x1 > x0)) return vec3(0.0);
    if (L.info.x == kLightDirectional) {
        float cosTheta = dot(-L.direction.xyz, w);
        return directionalSegment(cosTheta, x0, x1, uSigmaS, uSigmaT, uG, 1.0) * L.radiant.rgb;
    }
    RayLightGeometry g = rayLightGeometry(L.position.xyz, w);
#ifndef LIGHTS_NO_SPOT
    if (L.info.x == kLightSpot) return angularSegment(L, w, g, x0, x1);
#endif
    // Point lights and area-light VPLs. Without either in the scene the plan leaves out their cube maps
    // (SHADOW_NO_CUBE) and this code is not compiled: llvmpipe would run it for every fragment.
#ifndef SHADOW_NO_CUBE
#ifdef AIRLIGHT_LUT
    if (L.info.x == kLightVpl) {
        // Cosine lobe around the emitter normal: zero behind the emitter's plane, which cuts the segment;
        // the table has no lobe, so equal-angle pieces on the front part.
        float h = max(g.h, 1.0e-7 * max(abs(g.tP), 1.0e-20));
        vec2 front = frontOfEmitter(L.position.xyz, w, L.direction.xyz, x0, x1);
        return front.y > front.x ? angularPieces(L, w, g, h, front.x, front.y, false) : vec3(0.0);
    }
    return unitPointSegment(g, x0, x1, AIRLIGHT_NO_LOBE) * L.radiant.rgb;
#else
    // One segment integral for both: a point light's angular factor is 1, a VPL's its cosine lobe around
    // the emitter normal, integrated exactly (not uSpotPieces pieces).
    vec4 lobe = L.info.x == kLightVpl ? cosineLobeOf(L.position.xyz, w, L.direction.xyz) : AIRLIGHT_NO_LOBE;
    return pointSegmentWithLobe(g.tP, g.h, x0, x1, uSigmaS, uSigmaT, uG, 1.0, lobe) * L.radiant.rgb;
#endif
#else
    return vec3(0.0);
#endif
}

// ---- The ball around the light (README, "Rays next to the light") ----------------------------------
// Within R of a spot, point or VPL light (R, set per light by the technique: at most half the nearest
// distance its shadow map stores and 16 pixel footprints; 0 for directional lights and the crack
// detector) nothing occludes, so the lit
// part of the ball is exactly where the light's angular factor is non-zero, which segmentAirlight already
// integrates. The mesh's crossings there (the spot's cone walls meeting at the apex, sub-pixel near a ray
// passing the light) are placed by the rasteriser to about 1/256 pixel, much coarser than the distance h
// at which the 1/r^2 glow varies, and whole pairs of them can be missed. So every crossing term leaves
// out the ray's chord through the ball, and the chord is added once per pixel (resolve.comp): crossings
// inside the ball all add the same, whatever their exact place.

// The ray's chord [tP - c, tP + c] through the ball of radius R around the light, c = sqrt(R^2 - h^2);
// false when the ray misses the ball (or R = 0).
bool nearChord(GpuLight L, vec3 w, float R, out vec2 chord) {
    chord = vec2(0.0);
    if (!(R > 0.0) || L.info.x == kLightDirectional) return false;
    RayLightGeometry g = rayLightGeometry(L.position.xyz, w);
    if (!(g.h < R)) return false;
    float c = sqrt((R - g.h) * (R + g.h));
    chord = vec2(g.tP - c, g.tP + c);
    return true;
}

// segmentAirlight of [x0, x1] without its part inside the ball of radius R: [x0, x1] itself, or its parts
// before and after the chord. One call site in a loop (not two calls): segmentAirlight is large and the
// fragment shader with two inlined copies ran 25 % slower on llvmpipe, rays far from the light included.
vec3 segmentAirlightOutsideBall(GpuLight L, vec3 w, float x0, float x1, float R) {
    vec2 chord;
    bool ball = nearChord(L, w, R, chord);
    vec3 sum = vec3(0.0);
    int parts = ball ? 2 : 1;
    for (int k = 0; k < parts; ++k) {
        float a = k == 0 ? x0 : max(x0, chord.y);
        float b = k == 0 && ball ? min(x1, chord.x) : x1;
        sum += segmentAirlight(L, w, a, b);
    }
    return sum;
}

// segmentAirlight of the part of [0, d] inside the ball of radius R.
vec3 ballAirlight(GpuLight L, vec3 w, float d, float R) {
    vec2 chord;
    if (!nearChord(L, w, R, chord)) return vec3(0.0);
    return segmentAirlight(L, w, max(chord.x, 0.0), min(chord.y, d));
}

#endif  // POLYVOL_SEGMENT_GLSL
