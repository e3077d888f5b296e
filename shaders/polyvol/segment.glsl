// polyvol/segment.glsl: unshadowed airlight of one light along [x0, x1] of the pixel-centre ray w (eye at
// the origin, eye-relative world), with the light's whole angular factor. Shared by the volume's
// fragment shader and the per-pixel resolve.
#ifndef POLYVOL_SEGMENT_GLSL
#define POLYVOL_SEGMENT_GLSL

#include "common/host_device.glsl"
#include "common/airlight.glsl"
#include "common/lights.glsl"
#include "common/vpl_cell.glsl"
#include "common/spot_cone.glsl"
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
// Neighbouring pieces whose angular factors agree (a cookie's texels of one colour, its dark lead, the
// inner cone) form a run, integrated as one segment: the same sum, one segment integral where there were
// as many as pieces (README, "Runs of one colour").
const int kMaxCookiePieces = 64;
const int kMaxPieces = 256;          // spot_pieces' largest value
const float kRunTolerance = 1.0e-5;  // relative difference of two angular factors taken as one run

// lightIntensityToward a direction from the light (the light moved to the origin: lightIntensity only
// forms p - position from its point).
vec3 lightIntensityToward(GpuLight L, vec3 dirFromLight) {
    L.position.xyz = vec3(0.0);
    return lightIntensity(L, dirFromLight);
}

// The factor piece k takes at its middle angle: the light's whole intensity when the part is whole; a
// spot's colour times its cookie when the segment integral carries A_spot (its lobe, 1 inside the inner
// cone); else the whole angular factor (lightIntensityToward).
vec3 pieceIntensity(GpuLight L, vec3 m, float h, vec3 w, float phi0, float phi1, int k, int pieces, bool whole) {
    if (whole) return L.radiant.rgb;
    float phiMid = mix(phi0, phi1, (float(k) + 0.5) / float(pieces));
    vec3 dirFromLight = directionFromLight(m, h, w, phiMid);
#if !defined(AIRLIGHT_LUT) && !defined(LIGHTS_NO_COOKIE)
    if (L.info.x == kLightSpot) return L.radiant.rgb * spotCookie(L, dirFromLight);
#endif
    // A VPL's cell (lights.glsl, vplCellFactor) at the middle's point, r = h / cos from the light.
    if (vplHasCell(L)) {
        float r = h / max(cos(phiMid), 1.0e-30);
        return L.radiant.rgb * vplCellFactor(L, L.position.xyz + r * dirFromLight, r * r);
    }
    return lightIntensityToward(L, dirFromLight);
}

// The ray parameter of the edge before piece k (k = pieces: x1), kept inside [x0, x1] against rounding
// near +-pi/2.
float pieceEdge(RayLightGeometry g, float h, float x0, float x1, float phi0, float phi1, int k, int pieces) {
    if (k <= 0) return x0;
    if (k >= pieces) return x1;
    return clamp(g.tP + h * tan(mix(phi0, phi1, float(k) / float(pieces))), x0, x1);
}

// whole: the part lies inside a spot's inner cone with no cookie, where A_spot = 1: one exact piece at the
// light's full intensity. In a spot's penumbra (`penumbra`) the segment integral takes A_spot exactly: it
// is the square of a lobe in the integrand's own variable (spotPenumbraLobeOf), integrated on the
// segment's panels; without a cookie that is one piece, under a cookie the pieces carry the cookie alone.
// The lookup table has no lobe: with it the pieces carry A_spot * cookie at their middles.
// Two loops: the first finds where a run of pieces with one angular factor begins (a bit per piece), the
// second integrates each run that has light, so a SIMD group runs as many segment integrals as its
// lanes' largest number of runs, not of pieces. (One call of the segment integral, so that it is
// inlined once: llvmpipe runs every inlined copy for the whole invocation group, whichever lanes need it.)
vec3 angularPieces(GpuLight L, vec3 w, RayLightGeometry g, float h, float x0, float x1, bool whole, bool penumbra) {
    vec3 m = cross(cross(L.position.xyz, w), w);  // P - light, see angularSegment
    float phi0 = atan(x0 - g.tP, h);
    float phi1 = atan(x1 - g.tP, h);
    vec4 lobe = AIRLIGHT_NO_LOBE;
#ifndef AIRLIGHT_LUT
    if (L.info.x == kLightSpot) {
        if (penumbra) lobe = spotPenumbraLobeOf(L.position.xyz, w, L.direction.xyz, L.spot.x, L.spot.y);
        if (L.info.y < 0) whole = true;
    }
#endif
    int pieces = whole ? 1 : min(uSpotPieces, kMaxPieces);
#ifndef LIGHTS_NO_COOKIE
    if (!whole && L.info.x == kLightSpot && L.info.y >= 0) {
        pieces = clamp(int(ceil(abs(phi1 - phi0) / cookieTexelAngle(L))), pieces, max(pieces, kMaxCookiePieces));
    }
#endif
    // Bit k: piece k begins a run (its angular factor differs from the run's first piece's).
    uint begins[kMaxPieces / 32];
    for (int i = 0; i < kMaxPieces / 32; ++i) begins[i] = 0u;
    vec3 first = vec3(-1.0);
    for (int k = 0; k < pieces; ++k) {
        vec3 a = pieceIntensity(L, m, h, w, phi0, phi1, k, pieces, whole);
        vec3 tolerance = vec3(kRunTolerance * max(max(first.r, first.g), first.b));
        if (k == 0 || any(greaterThan(abs(a - first), tolerance))) {
            begins[k >> 5] |= 1u << uint(k & 31);
            first = a;
        }
    }
    vec3 sum = vec3(0.0);
    int begin = 0;
    while (begin < pieces) {
        // The next run's first piece: the lowest bit above `begin`, else the end.
        int end = pieces;
        for (int word = (begin + 1) >> 5; word < (pieces + 31) >> 5; ++word) {
            uint bits = begins[word];
            int low = (begin + 1) - 32 * word;  // bits below it belong to this run or an earlier one
            if (low > 0) bits &= ~((1u << uint(low)) - 1u);
            if (bits != 0u) {
                end = min(pieces, 32 * word + findLSB(bits));
                break;
            }
        }
        vec3 a = pieceIntensity(L, m, h, w, phi0, phi1, begin, pieces, whole);
        if (any(greaterThan(a, vec3(0.0)))) {
            float xa = pieceEdge(g, h, x0, x1, phi0, phi1, begin, pieces);
            float xb = max(pieceEdge(g, h, x0, x1, phi0, phi1, end, pieces), xa);
            sum += a * unitPointSegment(g, xa, xb, lobe);
        }
        begin = end;
    }
    return sum;
}

// A spot light's segment. A_spot and the cookie depend on the direction from the light, which turns
// along the segment, so they do not factor out of the integral. The segment is cut where it crosses the
// cones (spotConeCuts); outside the outer cone a part adds nothing, inside the inner cone (no cookie)
// A_spot = 1 and the part is exact, in the penumbra exact too with the segment integral (A_spot's lobe),
// and under a cookie (or with the lookup table) it takes uSpotPieces or more equal-angle pieces
// (angularPieces).
vec3 angularSegment(GpuLight L, vec3 w, RayLightGeometry g, float x0, float x1) {
    SpotCuts cuts = spotConeCuts(L, w, g, x0, x1);
    bool cookie = L.info.y >= 0;
    vec3 sum = vec3(0.0);
    for (int i = 0; i < cuts.n; ++i) {
        float xa = cuts.breaks[i];
        float xb = i + 1 < cuts.n ? cuts.breaks[i + 1] : x1;
        if (!(xb > xa)) continue;
        int zone = spotZone(L, cuts, w, g.tP, xa, xb);
        if (zone == kSpotDark) continue;
        sum += angularPieces(L, w, g, cuts.h, xa, xb, zone == kSpotInside && !cookie, zone == kSpotPenumbra);
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
        return front.y > front.x ? angularPieces(L, w, g, h, front.x, front.y, false, false) : vec3(0.0);
    }
    return unitPointSegment(g, x0, x1, AIRLIGHT_NO_LOBE) * L.radiant.rgb;
#else
    // One segment integral for both: a point light's angular factor is 1, a VPL's its cosine lobe around
    // the emitter normal, or its cell's solid angle (lights.glsl, vplHasCell), integrated exactly (not
    // uSpotPieces pieces).
    vec4 lobe = L.info.x == kLightVpl ? cosineLobeOf(L.position.xyz, w, L.direction.xyz) : AIRLIGHT_NO_LOBE;
    return pointSegmentCell(g.tP, g.h, x0, x1, uSigmaS, uSigmaT, uG, 1.0, lobe, lightCellAlong(L, w, g.tP)) *
           L.radiant.rgb;
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
