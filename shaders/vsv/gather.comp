#version 450 core
// vsv/gather.comp: one light's airlight from its voxelized shadow volume, added to uAirlight.
// Each pixel's eye ray is one (alpha, theta) of epipolar space: it reads the grid texel of its alpha
// cell (no interpolation along alpha: visibility there changes only at the occluder) and, with
// INTERP, the two texels of the neighbouring theta cells, blended with the weight wTheta. Phi bits
// k = 0 .. up to phi(d) are the visibility samples along the ray: bit k covers phi in
// [phi0 + k dPhi, phi0 + (k + 1) dPhi], i.e. t in [t(phi_k), t(phi_k+1)] by the law of sines.
//   COMBINE_EXACT: sum over runs of bins with equal visibility v (at most uRunBins bins each) of
//       v * pointSegment(run) * the light's angular factor averaged over the run (Simpson).
//   otherwise (the factorisation of Dobashi et al. / Wyman and Dai 3.1.5): the phi-uniform fraction
//       of lit bits up to phi(d) times the unshadowed airlight over the covered part of [0, d].
//   Direct rays: within one alpha cell of an epipole (EPIPOLE) the grid is degenerate, and a ray that
//       crosses fewer than uDirectBins phi bins up to its fragment (one nearly parallel to the baseline:
//       all of it falls into a bin or two) reads too few visibility samples. Such a ray skips the grid and
//       tests the shadow map itself (the shared lookup) at the middle of uDirectSegments segments: equal
//       steps of phi for a point or spot light (dense near the light, where the integrand peaks), equal
//       steps of t for a directional one (uEpipoleRule 1, march).
//   The paper's rule (uEpipoleRule 2, Wyman and Dai 2013 Sec. 5): at the epipole a shadow query only asks
//       whether anything lies between the eye and the light, so a ray in the cell toward the light is lit
//       over all of [0, d] when its fragment lies beyond the light (for a sun: the ray reaches the sky,
//       d = uZfar) and dark otherwise; a ray in the cell away from the light is lit when the eye is.
//       One lookup instead of uDirectSegments, but wrong when an occluder touches the light or the
//       fragment is an occluder beside it, and there the airlight is largest.
// Also writes (lit fraction, interpolated visibility of the fragment's own voxel, alpha cell, theta cell
// or -1 where a direct ray replaced the grid).
layout(local_size_x = 8, local_size_y = 8) in;

#include "common/host_device.glsl"
#include "common/airlight.glsl"
#include "common/lights.glsl"
#include "common/shadow_map.glsl"
#include "vsv/bits128.glsl"
#include "common/camera_ray.glsl"
#include "vsv/epipolar_uniforms.glsl"

layout(binding = kFirstFreeTextureUnit) uniform sampler2D uDistance;
layout(rgba32ui, binding = 0) uniform readonly uimage2DArray uGrid;
layout(rgba32f, binding = 1) uniform image2D uAirlight;
layout(rgba32f, binding = 2) uniform writeonly image2D uVisibility;

uniform int uLight;
#include "common/medium.glsl"  // uSigmaS, uSigmaT, uG
#include "common/work_counters.glsl"
uniform int uRunBins;
uniform int uAccumulate;     // 0: first light (overwrite), 1: add
uniform int uEpipoleToward;  // the alpha = 0 epipole is in view and the grid starts at alpha = 0
uniform int uEpipoleAway;    // the alpha = pi epipole is in view and the grid ends at alpha = pi
uniform float uDirectBins;    // rays crossing fewer phi bins skip the grid (0: only epipole rays)
uniform int uDirectSegments;  // shadow-map tests per direct ray
uniform int uEpipoleRule;     // 1: march the shadow map (direct ray); 2: the paper's fragment-vs-light test
uniform float uZfar;          // the sky's distance (a ray with d >= uZfar hit nothing)
#ifdef FAR_TAIL
// A far camera (scene/ray_reach.h): the grid's phi range ends at the scene's far side. Each ray that goes
// on past it adds the rest, kTailSamples shadow-map tests placed by the light; a direct ray's segments are
// placed by the light too (common/march_samples.glsl), over at most 60 mean free paths.
#define FAR_RAYS
#include "common/airlight_sample.glsl"
#include "common/march_samples.glsl"
uniform float uFarSpan;
const int kTailSamples = 8;
#endif

// Airlight of the ray over [ta, tb] for the whole bin run: the isotropic-source segment integral times
// the light's angular factor (spot falloff, cookie) averaged by Simpson's rule over the run.
vec3 runAirlight(GpuLight L, RayLightGeometry geo, vec3 w, float ta, float tb) {
    if (!(tb > ta)) return vec3(0.0);
    if (L.info.x == kLightDirectional)  // E = I colour everywhere; cos theta against the travel direction
        return L.radiant.rgb * directionalSegment(dot(-L.direction.xyz, w), ta, tb, uSigmaS, uSigmaT, uG, 1.0);
#if defined(LIGHTS_NO_SPOT) && defined(SHADOW_NO_CUBE)
    // The plan found no spot and no point light (suns only): the segment integral of a light with a
    // position is not compiled (llvmpipe would run it for every pixel, whichever lanes need it).
    return vec3(0.0);
#else
    vec3 ia = lightIntensity(L, ta * w);
    vec3 im = lightIntensity(L, 0.5 * (ta + tb) * w);
    vec3 ib = lightIntensity(L, tb * w);
    vec3 angular = (ia + 4.0 * im + ib) / 6.0;
    if (angular == vec3(0.0)) return vec3(0.0);
    return angular * pointSegment(geo.tP, geo.h, ta, tb, uSigmaS, uSigmaT, uG, 1.0);
#endif
}

// This light's airlight added to the pixel's (overwritten for the first light), and its visibility record.
void writePixel(ivec2 texel, vec3 airlight, vec4 visibility) {
    vec4 previous = uAccumulate != 0 ? imageLoad(uAirlight, texel) : vec4(0.0);
    imageStore(uAirlight, texel, vec4(previous.rgb + airlight, 1.0));
    imageStore(uVisibility, texel, visibility);
}

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, uSize))) return;
    GpuLight L = gLights[uLight];
    vec3 w = pixelRay(texel);
    float d = texelFetch(uDistance, texel, 0).r;
    RayLightGeometry geo = rayLightGeometry(L.position.xyz, w);

    EpiSpace S = epiFromUniforms();
    float alpha = epiAlphaOf(S, w);
    int ia = clamp(int(floor(epiAlphaCoord(S, alpha))), 0, uEpiCells.x - 1);
    int j0, j1;
    float wTheta;
#ifdef INTERP
    epiThetaCells(S, epiThetaOf(S, w), true, j0, j1, wTheta);
#else
    epiThetaCells(S, epiThetaOf(S, w), false, j0, j1, wTheta);
#endif

    float phiD = epiPhiOnEyeRay(S, alpha, d);
    float kEnd = (phiD - uEpiPhi.x) / uEpiPhi.y;  // continuous bin coordinate of the fragment
    int bins = clamp(int(ceil(kEnd)), 0, uEpiCells.z);

    bool direct = d > 0.0 && phiD < uDirectBins * uEpiPhi.y;
#ifdef EPIPOLE
    bool towardCell = uEpipoleToward != 0 && alpha < uEpiAlpha.x + uEpiAlpha.y;
    bool awayCell = uEpipoleAway != 0 && alpha > uEpiAlpha.x + (float(uEpiCells.x) - 1.0) * uEpiAlpha.y;
    if (uEpipoleRule == 2 && d > 0.0 && (towardCell || awayCell)) {
        float v;
        if (towardCell)  // beyond the light (its foot point on the ray), or the sky for a sun
            v = (L.info.x == kLightDirectional ? d >= uZfar * (1.0 - 1.0e-6) : d > dot(L.position.xyz, w)) ? 1.0
                                                                                                          : 0.0;
        else  // the eye's own visibility (the eye is at the origin)
            v = shadowVisibilityMedium(L, vec3(0.0));
        vec3 lit = v * runAirlight(L, geo, w, 0.0, d);
        writePixel(texel, lit, vec4(v, shadowVisibility(L, d * w), float(ia), -1.0));
        return;
    }
    if (towardCell || awayCell) direct = true;
#endif
    if (direct) {
        vec3 lit = vec3(0.0), unlit = vec3(0.0);
        bool byT = L.info.x == kLightDirectional || !(phiD > 0.0);
        float ta = 0.0;
#ifdef FAR_TAIL
        // A long ray: the segments placed by the light over its reach, the test at the sample's point.
        vec2 span = vec2(0.0, reachAlongRay(d, uSigmaT));
        bool byLight = span.y > uFarSpan;
#endif
        for (int i = 1; i <= uDirectSegments; ++i) {
            float u = float(i) / float(uDirectSegments);
            float tb = i == uDirectSegments ? d : (byT ? u * d : min(epiTOnEyeRay(S, alpha, u * phiD), d));
            float tm = 0.5 * (ta + tb);
#ifdef FAR_TAIL
            if (byLight) {
                MarchSample m = placeSample(L, w, span, i - 1, uDirectSegments, 0.5, uFarSpan);
                ta = m.x0;
                tb = m.x1;
                tm = m.t;
            }
#endif
            if (tb > ta) {
                vec3 a = runAirlight(L, geo, w, ta, tb);
                unlit += a;
                lit += shadowVisibilityMedium(L, tm * w) * a;
                ta = tb;
            }
        }
        float f = dot(unlit, vec3(1.0)) > 0.0 ? dot(lit, vec3(1.0)) / dot(unlit, vec3(1.0)) : 1.0;
#ifndef COMBINE_EXACT
        lit = f * unlit;  // the factorisation, with the fraction weighted by airlight
#endif
        writePixel(texel, lit, vec4(f, shadowVisibility(L, d * w), float(ia), -1.0));
        return;
    }

    vec3 sum = vec3(0.0);
    vec3 unshadowed = vec3(0.0);
    float litPhi = 0.0, totalPhi = 0.0;
    uvec4 c0 = uvec4(0u), c1 = uvec4(0u);
    // The open run: bins [runStart, k) with visibility runV.
    float runV = -1.0;
    float runTa = 0.0;
    int runLength = 0;
    // The inner loop reads bins until a run closes (its visibility changes, or it reaches uRunBins) and
    // the run is integrated outside it: an invocation group then runs runAirlight once per run, not on
    // every bin (llvmpipe runs the body of an `if` for the whole group whenever one lane takes it).
    int k = 0;
    while (k < bins) {
        bool closed = false;
        float closeTa = 0.0, nextV = 0.0;
        do {
            if ((k & 127) == 0) {
                c0 = imageLoad(uGrid, ivec3(ia, j0, k >> 7));
                c1 = imageLoad(uGrid, ivec3(ia, j1, k >> 7));
                WORK_COUNT(kWorkVoxelsRead, 2);
            }
            int bit = k & 127;
            float v = (1.0 - wTheta) * (testBitFast(c0, bit) ? 0.0 : 1.0) + wTheta * (testBitFast(c1, bit) ? 0.0 : 1.0);
            float phiA = uEpiPhi.x + float(k) * uEpiPhi.y;
            float phiB = min(phiA + uEpiPhi.y, phiD);
            litPhi += v * (phiB - phiA);
            totalPhi += phiB - phiA;
            float ta = k == 0 && phiA <= 0.0 ? 0.0 : min(epiTOnEyeRay(S, alpha, phiA), d);
            if (runLength == 0) {
                runV = v;
                runTa = ta;
            } else if (v != runV || runLength >= uRunBins) {
                closed = true;  // bins [runStart, k) end here; bin k starts the next run
                closeTa = ta;
                nextV = v;
            }
            if (!closed) ++runLength;
            ++k;
        } while (!closed && k < bins);
        if (closed) {
#ifdef COMBINE_EXACT
            if (runV > 0.0) sum += runV * runAirlight(L, geo, w, runTa, closeTa);
#else
            unshadowed += runAirlight(L, geo, w, runTa, closeTa);
#endif
            runV = nextV;
            runTa = closeTa;
            runLength = 1;
        }
    }
    if (runLength > 0) {
        float tEnd = min(epiTOnEyeRay(S, alpha, min(uEpiPhi.x + float(bins) * uEpiPhi.y, phiD)), d);
#ifdef COMBINE_EXACT
        if (runV > 0.0) sum += runV * runAirlight(L, geo, w, runTa, tEnd);
#else
        unshadowed += runAirlight(L, geo, w, runTa, tEnd);
#endif
    }
    float fraction = totalPhi > 0.0 ? litPhi / totalPhi : 1.0;
#ifndef COMBINE_EXACT
    sum = fraction * unshadowed;
#endif
#ifdef FAR_TAIL
    // Past the grid's phi range (the scene's far side), the rest of the ray.
    float tGridEnd = bins > 0 ? min(epiTOnEyeRay(S, alpha, min(uEpiPhi.x + float(bins) * uEpiPhi.y, phiD)), d) : 0.0;
    if (phiD > uEpiPhi.x + float(uEpiCells.z) * uEpiPhi.y)
        sum += tailByTheLight(L, w, vec2(tGridEnd, reachAlongRay(d, uSigmaT)), kTailSamples);
#endif

    // Visibility of the fragment's own voxel, interpolated along theta and phi (listing 2 of the paper).
    float surfaceV = 1.0;
    if (kEnd > 0.0 && kEnd < float(uEpiCells.z)) {
        float kc = kEnd - 0.5;
        int k0 = clamp(int(floor(kc)), 0, uEpiCells.z - 1);
        float wPhi = clamp(kc - float(k0), 0.0, 1.0);
        uvec4 s0 = imageLoad(uGrid, ivec3(ia, j0, k0 >> 7));
        uvec4 s1 = imageLoad(uGrid, ivec3(ia, j1, k0 >> 7));
        WORK_COUNT(kWorkVoxelsRead, 2);
        if ((k0 & 127) == 127) wPhi = 0.0;  // bit k0 + 1 lives in the next texel: stay at k0
        surfaceV = litFractionFast(s0, s1, k0 & 127, wTheta, wPhi);
    }

    writePixel(texel, sum, vec4(fraction, surfaceV, float(ia), float(j0)));
}
