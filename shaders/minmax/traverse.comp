#version 450 core
// minmax/traverse.comp: per pixel, find the camera ray's (alpha, beta) directly (camera rays are not
// rectified), pick the nearest slice, and walk its 1D min-max tree (Chen et al. 2011, Figure 5, with both
// section 3.5 optimisations: climb at most one level per step, and delay the integral's update until the
// next unlit node or the end). Each lit run of columns [c0, c1) becomes a distance interval [t0, t1] of the
// camera ray, integrated with the closed form of common/airlight.glsl (`integrand=analytic`).
// Mirrored step by step by minmax::integratePixel (pixel_mirror.h).
// One dispatch per light; results are added to uAirlight. uMode = 1 marches the whole image instead (a
// light the epipolar path does not handle: area-light VPLs, and point lights with point_lights=march).
// EPIPOLAR_POINT (a point light in the scene): a point light's row has its own gamma range (selectRow).
layout(local_size_x = 8, local_size_y = 8) in;

#include "common/host_device.glsl"
#include "common/airlight.glsl"
#include "common/lights.glsl"
#include "common/spot_cone.glsl"
#include "common/shadow_map.glsl"
#include "minmax/epipolar.glsl"
#include "minmax/camera_ray.glsl"

layout(binding = kFirstFreeTextureUnit) uniform sampler2D uDistance;  // Euclidean t of the first surface
layout(binding = kFirstFreeTextureUnit + 1) uniform sampler2D uTree;  // rg32f: (min, max), x = node, y = row
layout(rgba32f, binding = 0) uniform image2D uAirlight;
layout(r32f, binding = 1) uniform image2D uVisited;
layout(r32f, binding = 2) uniform image2D uNearMask;
layout(rgba32f, binding = 3) uniform writeonly image2D uRayCoords;

uniform int uLight;
uniform int uMode;           // 0: epipolar traversal, 1: brute-force march of every pixel
uniform bool uLinear;        // scan the leaves instead of walking the tree (traversal=linear)
uniform bool uWriteCoords;   // store (row, beta, cEnd, d) for the CPU mirror
uniform int uPieces;         // spot: gamma pieces across the cone with their own A_spot * cookie
uniform int uMarchSamples;   // brute-force samples per ray
uniform int uVplSamples;     // the same for an area light's VPL (its cell's kernel: bounded, smooth)
uniform vec4 uEpipoles;      // xy epipole, zw anti-epipole, GL pixel coordinates (y up); far away if none
uniform float uEpipoleRadius;
#include "common/medium.glsl"  // uSigmaS, uSigmaT, uG
#include "common/airlight_sample.glsl"

#ifdef FAR_RAYS
uniform float uFarSpan;    // a span longer than this is sampled by the light (common/march_samples.glsl)
uniform float uAxisReach;  // scene::depthOfInterest: past it a ray on the epipolar axis keeps its visibility
#else
const float uFarSpan = 3.0e38;
const float uAxisReach = 3.0e38;
#endif
#include "common/march_samples.glsl"

// A light with a position can walk this dispatch (a spot, or a point light with EPIPOLAR_POINT); without
// one (the plan's LIGHTS_NO_SPOT and no EPIPOLAR_POINT: only suns) their segment integrals are not
// compiled, since llvmpipe runs every inlined copy for the whole invocation group, whichever lanes need it.
#if !defined(LIGHTS_NO_SPOT) || defined(EPIPOLAR_POINT)
#define MINMAX_POSITIONAL_LIGHT
#endif

// Brute force for lights without an epipolar path (raymarch's midpoint rule): uMarchSamples samples
// (uVplSamples for a VPL) uniform in t over [0, d] (or, with a far camera, by the light: placeSample),
// each the integrand sigma_s p E V exp(-sigma_t t) dt at its point. No loops inside the loop: llvmpipe
// ends all loops of an invocation together after 65535 iterations.
vec3 march(GpuLight L, vec3 w, float d) {
    vec2 span = vec2(0.0, d);
#ifdef FAR_RAYS
    span.y = reachAlongRay(d, uSigmaT);  // litInterval's reach (60 mean free paths)
#endif
    vec3 sum = vec3(0.0);
    int samples = L.info.x == kLightVpl ? uVplSamples : uMarchSamples;
    for (int i = 0; i < samples; ++i) {
        WORK_COUNT(kWorkRaySamples, 1);
        MarchSample m = placeSample(L, w, span, i, samples, 0.5, uFarSpan);
        float t = m.t;
        vec3 x = t * w;
        float V = shadowVisibility(L, x);
        if (V == 0.0) continue;
        float cosTheta = dot(directionToLight(L, x), w);
        sum += airlightSample(V, cosTheta, unshadowedIrradiance(L, x, uSigmaT), t, m.dt);
    }
    return sum;
}

// Brute force near the epipole: the midpoint rule in gamma instead of t. For a spot gamma is the angle at
// the light, so samples crowd where the ray passes the light, and the Jacobian
// dt/dgamma = D sin(beta) / sin^2(beta + gamma) = r^2 / (D sin(beta)) cancels the 1/r^2 peak: the integrand
// in gamma is smooth. Directional: gamma = t sin(beta), dt/dgamma = 1 / sin(beta). Each sample looks up
// the shadow map directly (no rectification).
vec3 marchGamma(GpuLight L, vec3 w, float beta, float d) {
    float gammaEnd = gammaAlongRay(beta, d);
    vec3 sum = vec3(0.0);
#ifdef FAR_RAYS
    // A sun's light rays beyond the map's reach (gammaHi) miss every occluder, as in the traversal: that
    // part of the ray is lit and added in closed form; the samples stay where the map is.
    if (uKind == kKindDirectional && gammaEnd > MINMAX_GAMMA_HI) {
        float tHi = min(distanceAtGamma(beta, MINMAX_GAMMA_HI), d);
        sum += directionalSegment(dot(directionToLight(L, tHi * w), w), tHi, d, uSigmaS, uSigmaT, uG, 1.0) *
               L.radiant.rgb;
        gammaEnd = MINMAX_GAMMA_HI;
    }
#endif
    float step = gammaEnd / float(uMarchSamples);
    float sinBeta = sin(beta);
    for (int i = 0; i < uMarchSamples; ++i) {
        WORK_COUNT(kWorkRaySamples, 1);
        float gamma = (float(i) + 0.5) * step;
        float t = min(distanceAtGamma(beta, gamma), d);
        vec3 x = t * w;
        if (shadowVisibility(L, x) == 0.0) continue;
        float jacobian;
        if (uKind == kKindDirectional) {
            jacobian = 1.0 / sinBeta;
        } else {
            float s = sin(beta + gamma);
            jacobian = uLightDistance * sinBeta / (s * s);
        }
        float cosTheta = dot(directionToLight(L, x), w);
        sum += airlightSample(1.0, cosTheta, unshadowedIrradiance(L, x, uSigmaT), t, jacobian * step);
    }
    return sum;
}

// A ray on the epipolar axis (beta = 0 or pi to float precision) runs through a spot's position and has
// no gamma parametrisation (marchGamma divides by sin(beta)): it is marched in t instead, each interval
// with the closed form of the unshadowed airlight (pointSegment / directionalSegment, which keep the
// 1/r^2 peak at the light finite and exact) times the shadow test and the angular factor at its middle.
// At most kAxisSamples intervals: pointSegment loops about 150 times inside, and llvmpipe ends all loops
// of an invocation together after 65535 iterations.
const int kAxisSamples = 256;
vec3 marchAxis(GpuLight L, vec3 w, float d) {
    RayLightGeometry g = rayLightGeometry(L.position.xyz, w);
    int n = min(uMarchSamples, kAxisSamples);
    // With a far camera the intervals end at the scene's far side: past it the ray runs along one light
    // ray, so its visibility no longer changes and the rest is one closed-form segment with the last V.
    float reach = min(d, uAxisReach);
    float dt = reach / float(n);
    vec3 sum = vec3(0.0);
    float lastV = 1.0;
    for (int i = 0; i < n; ++i) {
        float t = (float(i) + 0.5) * dt;
        vec3 x = t * w;
        lastV = shadowVisibility(L, x);
        if (lastV == 0.0) continue;
        float x0 = float(i) * dt;
        float x1 = float(i + 1) * dt;
        if (uKind == kKindDirectional) {
            sum += directionalSegment(dot(directionToLight(L, x), w), x0, x1, uSigmaS, uSigmaT, uG, 1.0) *
                   L.radiant.rgb;
        } else {
#ifdef MINMAX_POSITIONAL_LIGHT
            // The angular factor needs a direction from the light: none at the light's own position.
            vec3 I = distance(x, L.position.xyz) > 0.0 ? lightIntensity(L, x) : vec3(0.0);
            sum += pointSegment(g.tP, g.h, x0, x1, uSigmaS, uSigmaT, uG, 1.0) * I;
#endif
        }
    }
    if (d > reach && lastV > 0.0) {
        vec3 x = d * w;
        if (uKind == kKindDirectional) {
            sum += directionalSegment(dot(directionToLight(L, x), w), reach, d, uSigmaS, uSigmaT, uG, 1.0) *
                   L.radiant.rgb;
        } else {
#ifdef MINMAX_POSITIONAL_LIGHT
            vec3 I = distance(x, L.position.xyz) > 0.0 ? lightIntensity(L, x) : vec3(0.0);
            sum += pointSegment(g.tP, g.h, reach, d, uSigmaS, uSigmaT, uG, 1.0) * I;
#endif
        }
    }
    return sum;
}

// The camera ray's distance at column c (c >= cEnd: the ray's end d).
float distanceAtColumn(float beta, float c, float cEnd, float d) {
    if (c >= cEnd) return d;
    return min(distanceAtGamma(beta, gammaOfColumn(c)), d);
}

// L_air over the lit run of columns [c0, c1) (analytic integrand).
vec3 integrateRunAnalytic(GpuLight L, vec3 w, RayLightGeometry g, float beta, float c0, float c1, float cEnd, float d) {
    if (uKind == kKindDirectional) {
        float t0 = distanceAtColumn(beta, c0, cEnd, d);
        float t1 = distanceAtColumn(beta, c1, cEnd, d);
        return directionalSegment(cos(beta), t0, t1, uSigmaS, uSigmaT, uG, 1.0) * L.radiant.rgb;
    }
#ifdef EPIPOLAR_POINT
    if (uKind == kKindPoint) {
        // Point: the emission colour * I is the same in every direction: one closed-form segment.
        float t0 = distanceAtColumn(beta, c0, cEnd, d);
        float t1 = distanceAtColumn(beta, c1, cEnd, d);
        if (t1 <= t0) return vec3(0.0);
        return pointSegment(g.tP, g.h, t0, t1, uSigmaS, uSigmaT, uG, 1.0) * L.radiant.rgb;
    }
#endif
#ifdef LIGHTS_NO_SPOT
    return vec3(0.0);  // no spot in the scene: only suns (and point lights, above) reach this
#elif defined(LIGHTS_NO_COOKIE)
    // Spot without a cookie: the run cut where it crosses the cones (common/spot_cone.glsl), each part one
    // segment integral: A_spot = 1 inside the inner cone, the square of a lobe in the penumbra
    // (docs/numerics.md#spot-penumbra), nothing outside. One call site in the loop: llvmpipe runs every
    // inlined copy of the segment integral for the whole invocation group.
    float t0 = distanceAtColumn(beta, c0, cEnd, d);
    float t1 = distanceAtColumn(beta, c1, cEnd, d);
    if (!(t1 > t0)) return vec3(0.0);
    SpotCuts cuts = spotConeCuts(L, w, g, t0, t1);
    vec4 penumbra = spotPenumbraLobeOf(L.position.xyz, w, L.direction.xyz, L.spot.x, L.spot.y);
    float sum = 0.0;
    for (int i = 0; i < cuts.n; ++i) {
        float ta = cuts.breaks[i];
        float tb = i + 1 < cuts.n ? cuts.breaks[i + 1] : t1;
        if (!(tb > ta)) continue;
        int zone = spotZone(L, cuts, w, g.tP, ta, tb);
        if (zone == kSpotDark) continue;
        sum += pointSegmentWithLobe(g.tP, g.h, ta, tb, uSigmaS, uSigmaT, uG, 1.0,
                                    zone == kSpotInside ? AIRLIGHT_NO_LOBE : penumbra);
    }
    return sum * L.radiant.rgb;
#else
    // Spot with a cookie: A_spot * cookie varies across the cone; pieces on a fixed grid of uPieces cells
    // over [gammaLo, gammaHi] each take it at their middle (uPieces / columns cells per column).
    float cellColumns = float(uColumns) / float(uPieces);
    vec3 sum = vec3(0.0);
    float c = c0;
    // Cells by integer index: c0 / cellColumns may round below a cell boundary that c0 sits on, and a
    // boundary recomputed from c would then not advance.
    for (int cell = int(floor(c0 / cellColumns)) + 1; c < c1; ++cell) {
        float next = min(c1, float(cell) * cellColumns);
        if (next <= c) continue;
        float ta = distanceAtColumn(beta, c, cEnd, d);
        float tb = distanceAtColumn(beta, next, cEnd, d);
        float tm = distanceAtColumn(beta, 0.5 * (c + next), cEnd, d);
        vec3 I = lightIntensity(L, tm * w);
        if (tb > ta && I != vec3(0.0)) sum += pointSegment(g.tP, g.h, ta, tb, uSigmaS, uSigmaT, uG, 1.0) * I;
        c = next;
    }
    return sum;
#endif
}

#ifdef INTEGRAND_SVD
// Low-rank integrand (`integrand=svd`, low_rank.h): each lit run adds the difference of the prefix sums of
// Gamma_i T at its ends (hardware linear filtering between the table's texels, which are coarser than the
// columns); the sum is weighted by B_i(beta) / sin(beta) once at the end of the walk. A spot's T changes
// with alpha (its cone's edge, its cookie): with uBlendRows (slice_blend=linear) the sums are interpolated
// between the tables of the two slices either side of the pixel's ray, gPrefixRow and gPrefixRow1 with
// weight gPrefixBlend, instead of read from the nearest slice's alone (the paper), whose T is up to half a
// slice off the ray's.
layout(binding = kFirstFreeTextureUnit + 2) uniform sampler2DArray uPrefix;
// The rank: a compile-time constant (MINMAX_RANK, from the run's settings), so that the loops over it unroll
// and the per-rank sums stay in registers instead of a dynamically indexed array.
const int kRank = MINMAX_RANK;
uniform int uPrefixTexels;
uniform int uPrefixRows;
uniform bool uBlendRows;
uniform float uBetaLo;
uniform float uBetaHi;
// B_i at 64 beta samples (inclusive ends), rank-major, four to a vec4 (see prefix.comp).
uniform vec4 uBetaBasis[8 * 16];
float betaBasisAt(int j) { return uBetaBasis[j >> 2][j & 3]; }
vec4 gAccumulated[6];
int gPrefixRow = 0, gPrefixRow1 = 0;
float gPrefixBlend = 0.0;

// The table rows a ray at angle alpha in slice row `row` reads.
void selectPrefixRows(float alpha, int row) {
    gPrefixRow = gPrefixRow1 = uPrefixRows == 1 ? 0 : row;
    gPrefixBlend = 0.0;
    if (uBlendRows && uPrefixRows > 1) {
        float x = slicePosition(alpha);
        float below = floor(x);
        gPrefixRow = wrapRow(int(below));
        gPrefixRow1 = wrapRow(int(below) + 1);
        gPrefixBlend = x - below;
    }
}

vec4 prefixDifference(float u0, float u1, int row, int layer) {
    float v = (float(row) + 0.5) / float(uPrefixRows);
    return texture(uPrefix, vec3(u1, v, float(layer))) - texture(uPrefix, vec3(u0, v, float(layer)));
}

void accumulateRun(float c0, float c1) {
    float scale = float(uPrefixTexels) / float(uColumns);
    float u0 = (c0 * scale + 0.5) / float(uPrefixTexels + 1);
    float u1 = (c1 * scale + 0.5) / float(uPrefixTexels + 1);
    int layers = (3 * kRank + 3) / 4;
    for (int layer = 0; layer < layers; ++layer) {
        vec4 sum = prefixDifference(u0, u1, gPrefixRow, layer);
        if (gPrefixBlend > 0.0) sum = mix(sum, prefixDifference(u0, u1, gPrefixRow1, layer), gPrefixBlend);
        gAccumulated[layer] += sum;
    }
}

float betaBasis(int i, float beta) {
    float x = clamp((beta - uBetaLo) / (uBetaHi - uBetaLo), 0.0, 1.0) * 63.0;
    int k = min(int(floor(x)), 62);
    return mix(betaBasisAt(i * 64 + k), betaBasisAt(i * 64 + k + 1), x - float(k));
}

vec3 lowRankResult(float beta) {
    vec3 sum = vec3(0.0);
    for (int i = 0; i < kRank; ++i) {
        float b = betaBasis(i, beta);
        for (int c = 0; c < 3; ++c) {
            int q = 3 * i + c;
            sum[c] += b * gAccumulated[q / 4][q % 4];
        }
    }
    return sum / sin(beta);
}
#endif

vec3 integrateRun(GpuLight L, vec3 w, RayLightGeometry g, float beta, float c0, float c1, float cEnd, float d) {
#ifdef INTEGRAND_SVD
    WORK_COUNT(kWorkClosedFormSegments, 1);  // the run's integral: two prefix-table lookups per layer
    accumulateRun(c0, c1);
    return vec3(0.0);
#else
    return integrateRunAnalytic(L, w, g, beta, c0, c1, cEnd, d);
#endif
}

vec2 treeNode(int node, int row) { return texelFetch(uTree, ivec2(node, row), 0).rg; }

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, uSize))) return;
    WORK_PIXEL(texel);
    GpuLight L = gLights[uLight];
    vec3 w = pixelRay(texel);
    float d = texelFetch(uDistance, texel, 0).r;
    vec3 sum = vec3(0.0);
    float visited = 0.0;

    bool brute = uMode == 1;
#ifdef NEAR_EPIPOLE
    vec2 centre = vec2(texel) + 0.5;
    bool near = min(distance(centre, uEpipoles.xy), distance(centre, uEpipoles.zw)) < uEpipoleRadius;
    if (uMode == 0 && near) {
        brute = true;
        imageStore(uNearMask, texel, vec4(1.0));
    }
#endif
    // A ray along the epipolar axis lies in every slice: it is marched wherever it falls, also with the
    // near-epipole pass off.
    bool onAxis = uMode == 0 && onEpipolarAxis(w, uAxis);
    if (uMode == 1) {
        sum = march(L, w, d);
    } else if (onAxis) {
        sum = marchAxis(L, w, d);
    } else if (brute) {
        sum = marchGamma(L, w, betaOf(w), d);
    } else {
        float beta = betaOf(w);
        float alpha = alphaOf(w);
        int row = sliceRow(alpha);
        selectRow(row);
        float cEnd = max(columnOf(gammaAlongRay(beta, d)), 0.0);
        float end = min(cEnd, float(uColumns));
        RayLightGeometry g = rayLightGeometry(L.position.xyz, w);
        if (uWriteCoords) imageStore(uRayCoords, texel, vec4(float(row), beta, cEnd, d));
#ifdef INTEGRAND_SVD
        for (int layer = 0; layer < 6; ++layer) gAccumulated[layer] = vec4(0.0);
        selectPrefixRows(alpha, row);
#endif
        float runBegin = -1.0, runEnd = -1.0;
        if (uLinear) {
            for (int j = 0; j < uColumns && float(j) < end; ++j) {
                visited += 1.0;
                WORK_COUNT(kWorkTreeNodes, 1);
                if (beta < treeNode(uColumns + j, row).r) {
                    if (runBegin < 0.0) runBegin = float(j);
                    runEnd = min(end, float(j + 1));
                } else if (runBegin >= 0.0) {
                    sum += integrateRun(L, w, g, beta, runBegin, runEnd, cEnd, d);
                    runBegin = -1.0;
                }
            }
        } else {
            // Node k at level l = findMSB(k) covers columns [lo, lo + width), width = columns >> l.
            // The inner loop walks until a lit run closes (or the walk ends) and the run is integrated
            // outside it: an invocation group then executes the integral once per run, not on every node
            // visit (llvmpipe runs the body of an `if` for the whole group whenever one lane takes it).
            int node = 1;
            int width = uColumns;
            int lo = 0;
            bool more = end > 0.0;
            while (more) {
                bool closed = false;
                do {
                    visited += 1.0;
                    WORK_COUNT(kWorkTreeNodes, 1);
                    vec2 mm = treeNode(node, row);
                    if (mm.x <= beta && beta < mm.y) {
                        node = node * 2;  // mixed: descend to the left child
                    } else {
                        if (beta < mm.x) {  // lit: open or extend the run (its integral is added later)
                            if (runBegin < 0.0) runBegin = float(lo);
                            runEnd = min(end, float(lo + width));
                        } else if (runBegin >= 0.0) {  // shadowed: the open run closes
                            closed = true;
                        }
                        node = node + 1;                      // the next node at this level ...
                        if ((node & 1) == 0) node = node / 2;  // ... or its parent: at most one level up
                        // A power of two here is the first node of a level: the walk went past the row's end.
                        if (bitCount(node) == 1) more = false;
                    }
                    int level = findMSB(node);
                    width = uColumns >> level;
                    lo = (node - (1 << level)) * width;
                } while (more && !closed && end > float(lo));
                if (closed) {
                    sum += integrateRun(L, w, g, beta, runBegin, runEnd, cEnd, d);
                    runBegin = -1.0;
                }
                more = more && closed && end > float(lo);
            }
        }
        if (runBegin >= 0.0) sum += integrateRun(L, w, g, beta, runBegin, runEnd, cEnd, d);
#ifdef INTEGRAND_SVD
        sum += lowRankResult(beta);
#endif
        // Directional: beyond gammaHi the light rays miss the shadow map, so they are lit (closed form in
        // both integrand modes: the tables end at gammaHi).
        if (uKind == kKindDirectional && cEnd > float(uColumns)) {
            sum += integrateRunAnalytic(L, w, g, beta, float(uColumns), cEnd, cEnd, d);
        }
    }
    vec4 previous = imageLoad(uAirlight, texel);
    imageStore(uAirlight, texel, vec4(previous.rgb + sum, 1.0));
    float previousVisited = imageLoad(uVisited, texel).r;
    imageStore(uVisited, texel, vec4(previousVisited + visited));
}
