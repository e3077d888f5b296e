// polyvol/segment.glsl: unshadowed airlight of one light along [x0, x1] of the pixel-centre ray w (eye at
// the origin, eye-relative world), with the light's whole angular factor. Shared by the volume's
// fragment shader and the per-pixel resolve.
#ifndef POLYVOL_SEGMENT_GLSL
#define POLYVOL_SEGMENT_GLSL

#include "common/host_device.glsl"
#include "common/airlight.glsl"
#include "common/lights.glsl"
#include "polyvol/airlight_lut.glsl"
#include "common/camera_ray.glsl"

uniform float uSigmaS;
uniform float uSigmaT;
uniform float uG;
uniform int uSpotPieces;   // spot lights: equal-angle pieces per penumbra part (see angularSegment)

// Unit-intensity isotropic-source airlight of [x0, x1] (closed form or lookup table).
float unitPointSegment(RayLightGeometry g, float x0, float x1) {
#ifdef AIRLIGHT_LUT
    return lutPointSegment(g.tP, g.h, x0, x1, uSigmaS, uSigmaT, uG);
#else
    return pointSegment(g.tP, g.h, x0, x1, uSigmaS, uSigmaT, uG, 1.0);
#endif
}

// Equal-angle pieces of [x0, x1]: the direction from the light is a function of the angle
// phi = atan((t - tP) / h) alone, so equal angles are equal steps of the angular factor; each piece is the
// exact unit-intensity integral (pointSegment) times the angular factor at its middle angle.
// Under a cookie the pieces follow its texels instead: about one piece per cookie texel the segment
// sweeps (texel angle 2 atan(tan(outer)) / width), at least uSpotPieces, at most kMaxCookiePieces.
const int kMaxCookiePieces = 64;

vec3 angularPieces(GpuLight L, vec3 w, RayLightGeometry g, float h, float x0, float x1) {
    float phi0 = atan(x0 - g.tP, h);
    float phi1 = atan(x1 - g.tP, h);
    int pieces = uSpotPieces;
#ifndef LIGHTS_NO_COOKIE
    if (L.info.x == kLightSpot && L.info.y >= 0) {
        float texelAngle = 2.0 * atan(L.spot.z) / max(L.frameX.w, 1.0);
        pieces = clamp(int(ceil(abs(phi1 - phi0) / texelAngle)), uSpotPieces, max(uSpotPieces, kMaxCookiePieces));
    }
#endif
    vec3 sum = vec3(0.0);
    float xa = x0;
    for (int k = 0; k < pieces; ++k) {
        float xb = k + 1 == pieces ? x1 : g.tP + h * tan(mix(phi0, phi1, float(k + 1) / float(pieces)));
        xb = clamp(xb, xa, x1);
        float phiMid = mix(phi0, phi1, (float(k) + 0.5) / float(pieces));
        vec3 a = lightIntensity(L, (g.tP + h * tan(phiMid)) * w);
        if (any(greaterThan(a, vec3(0.0)))) sum += a * unitPointSegment(g, xa, xb);
        xa = xb;
    }
    return sum;
}

// Roots in (x0, x1) of f(t) = (dot(o + t w, a))^2 - c^2 |o + t w|^2 (the double cone of half-angle
// acos(c) around axis a through the light; o = eye - light), appended to `breaks`.
// Solved in units of the length scale S = max(|o|, x1): with t = S u the coefficients A, B / S, C / S^2
// are all O(1) whatever the scene's units, so the near-degenerate test on A (a ray parallel to the
// cone's surface) and the quadratic stay scale-free (a 1e4-unit scene once made A look negligible next
// to C ~ |o|^2 and every root came from the linear fallback).
void coneRoots(vec3 o, vec3 w, vec3 a, float c, float x0, float x1, inout float breaks[8], inout int n) {
    float S = max(max(length(o), abs(x1)), 1.0e-30);
    vec3 os = o / S;
    float wa = dot(w, a), oa = dot(os, a);
    float A = wa * wa - c * c;
    float B = 2.0 * (oa * wa - c * c * dot(os, w));
    float C = oa * oa - c * c * dot(os, os);
    float r[2];
    int m = 0;
    if (abs(A) < 1e-7 * (abs(B) + abs(C) + 1e-30)) {
        if (B != 0.0) r[m++] = -C / B;
    } else {
        float disc = B * B - 4.0 * A * C;
        if (disc >= 0.0) {
            // Stable pair: q = -(B + sign(B) sqrt(disc)) / 2, roots q / A and C / q.
            float q = -0.5 * (B + (B >= 0.0 ? 1.0 : -1.0) * sqrt(disc));
            r[m++] = q / A;
            if (q != 0.0) r[m++] = C / q;
        }
    }
    for (int i = 0; i < m; ++i) {
        float t = r[i] * S;
        if (t > x0 && t < x1 && n < 8) breaks[n++] = t;
    }
}

// A spot light's segment. A_spot and the cookie depend on the direction from the light, which turns
// along the segment, so they do not factor out of the integral. The segment is cut where it crosses the
// outer and inner cones and the plane through the light normal to the axis; each part is classified at
// its middle: outside the outer cone it adds nothing, inside the inner cone (no cookie) A_spot = 1 and the
// part is exact, in the penumbra (or under a cookie) it takes uSpotPieces equal-angle pieces.
vec3 angularSegment(GpuLight L, vec3 w, RayLightGeometry g, float x0, float x1) {
    float h = max(g.h, 1.0e-7 * max(abs(g.tP), 1.0e-20));
    vec3 o = -L.position.xyz;
    vec3 a = L.direction.xyz;
    float cosOuter = L.spot.w;
    // KHR: A = 1 where cd * scale + offset >= 1, i.e. cd >= (1 - offset) / scale = cos(inner).
    float cosInner = min((1.0 - L.spot.y) / L.spot.x, 1.0);
    float breaks[8];
    int n = 0;
    breaks[n++] = x0;
    coneRoots(o, w, a, cosOuter, x0, x1, breaks, n);
    coneRoots(o, w, a, cosInner, x0, x1, breaks, n);
    float wa = dot(w, a);
    if (wa != 0.0) {
        float tPlane = -dot(o, a) / wa;
        if (tPlane > x0 && tPlane < x1 && n < 8) breaks[n++] = tPlane;
    }
    // Insertion sort (at most 6 interior points), then x1.
    for (int i = 1; i < n; ++i) {
        float v = breaks[i];
        int j = i - 1;
        while (j >= 0 && breaks[j] > v) {
            breaks[j + 1] = breaks[j];
            --j;
        }
        breaks[j + 1] = v;
    }
    bool cookie = L.info.y >= 0;
    vec3 sum = vec3(0.0);
    for (int i = 0; i < n; ++i) {
        float xa = breaks[i];
        float xb = i + 1 < n ? breaks[i + 1] : x1;
        if (!(xb > xa)) continue;
        vec3 dirMid = normalize(0.5 * (xa + xb) * w - L.position.xyz);
        float cd = dot(dirMid, a);
        if (cd <= cosOuter) continue;                       // outside the outer cone: A_spot = 0
        if (cd >= cosInner && !cookie) {
            sum += L.radiant.rgb * unitPointSegment(g, xa, xb);  // inside the inner cone: A_spot = 1
        } else {
            sum += angularPieces(L, w, g, h, xa, xb);
        }
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
    if (L.info.x == kLightVpl) {
        // Cosine lobe around the emitter normal: zero behind the emitter's plane, which cuts the segment;
        // equal-angle pieces on the front part.
        float h = max(g.h, 1.0e-7 * max(abs(g.tP), 1.0e-20));
        vec3 n = L.direction.xyz;
        float wn = dot(w, n), on = dot(-L.position.xyz, n);  // side of the eye: sign of on
        float a = x0, b = x1;
        if (wn != 0.0) {
            float tPlane = -on / wn;
            if (wn > 0.0) a = max(a, tPlane); else b = min(b, tPlane);
        } else if (on <= 0.0) {
            return vec3(0.0);
        }
        return b > a ? angularPieces(L, w, g, h, a, b) : vec3(0.0);
    }
    return unitPointSegment(g, x0, x1) * L.radiant.rgb;
}

#endif  // POLYVOL_SEGMENT_GLSL
