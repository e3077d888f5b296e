#version 450 core
// raymarch/march.comp: brute-force single scattering. For each pixel and light, N samples along the eye
// ray over the part of [0, d] (d from the surface pass) the light can reach (litInterval: a spot's cone,
// 60 mean free paths), each tested against the light's shadow map; uniform in t, or on a very long span
// by the light's importance (FAR_RAYS, placeSample). Plain mode is
// the midpoint rule of the integrand; EXACT integrates the unshadowed airlight analytically over each
// sample's interval and weights it by the visibility at the sample (NAIVE_CLOSED_FORM, a teaching mode:
// with Sun et al.'s textbook formula instead of the stable pointSegment). Output: L_air (rgba32f) and the lit
// fraction of the samples. All positions are eye-relative (the eye at the origin).
// The (light, sample) pairs are flattened to k = light * N + sample and each dispatch runs the pairs
// [uPairBegin, uPairEnd), adding to what earlier dispatches stored: llvmpipe stops every loop of an
// invocation after 65,535 iterations in total (all loops counted together), which a single dispatch
// of many samples, lights and exact segments would exceed, silently cutting the ray short.
layout(local_size_x = 8, local_size_y = 8) in;

#include "common/host_device.glsl"
#ifdef NAIVE_CLOSED_FORM
#define AIRLIGHT_NAIVE_CLOSED_FORM
#endif
#include "common/airlight.glsl"
#include "common/lights.glsl"
#include "common/vpl_cell.glsl"
#include "common/shadow_map.glsl"
#include "common/camera_ray.glsl"

layout(binding = kFirstFreeTextureUnit) uniform sampler2D uDistance;  // Euclidean t of the first surface
layout(rgba32f, binding = 0) uniform image2D uAirlight;     // running sum over the dispatches
layout(r32f, binding = 1) uniform image2D uLitFraction;     // running count of lit samples, then the fraction

uniform int uSamples;
uniform int uLightCount;
#include "common/medium.glsl"  // uSigmaS, uSigmaT, uG
#include "common/airlight_sample.glsl"
uniform uint uSeed;          // jitter=white: the hash's seed (moves every frame with jitter_time=per-frame)
#ifdef JITTER_BLUE
layout(binding = kFirstFreeTextureUnit + 1) uniform sampler2D uBlueNoise;  // 64x64 tile, values in (0, 1)
#endif
uniform float uBlueShift;    // jitter=blue: added to the tile's value, modulo 1 (steps every frame)
uniform int uPairBegin;  // first (light, sample) pair of this dispatch
uniform int uPairEnd;    // one past the last
uniform bool uFirst;     // the first dispatch starts the sums at zero
uniform bool uLast;      // the last dispatch turns the lit count into a fraction
uniform float uFarSpan;  // a lit span longer than this (8 radii of the scene's bounds) is sampled by the light
#include "common/march_samples.glsl"

// PCG-style integer hash -> [0, 1): jitter=white's offset, fixed per pixel, sample and seed (deterministic).
float hashToUnit(uvec3 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * v.z; v.y += v.z * v.x; v.z += v.x * v.y;
    v ^= v >> 16u;
    v.x += v.y * v.z; v.y += v.z * v.x; v.z += v.x * v.y;
    return float(v.x >> 8u) * (1.0 / 16777216.0);
}

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, uSize))) return;
    WORK_PIXEL(texel);

    vec3 w = pixelRay(texel);
    float d = texelFetch(uDistance, texel, 0).r;

    vec3 sum = uFirst ? vec3(0.0) : imageLoad(uAirlight, texel).rgb;
    float litSamples = uFirst ? 0.0 : imageLoad(uLitFraction, texel).r;
    for (int k = uPairBegin; k < uPairEnd; ++k) {
        int li = k / uSamples;
        int i = k - li * uSamples;
        GpuLight L = gLights[li];
        vec2 span = litInterval(L, w, d, uSigmaT);
        if (span.y <= span.x) continue;  // the light reaches no part of this ray: no samples, none lit
#if defined(JITTER_BLUE)
        // One offset for every interval of the pixel's ray: the tile spreads neighbouring pixels' offsets
        // evenly, so the banding of a coarse N becomes fine grain instead of white noise's clumps.
        float u = fract(texelFetch(uBlueNoise, texel & 63, 0).r + uBlueShift);
#elif defined(JITTER)
        float u = hashToUnit(uvec3(uint(texel.x) + uint(texel.y) * 65536u, uint(i), uSeed + uint(li)));
#else
        float u = 0.5;
#endif
        MarchSample m = placeSample(L, w, span, i, uSamples, u, uFarSpan);
        float t = m.t;
        vec3 x = t * w;
        WORK_COUNT(kWorkRaySamples, 1);
#ifdef SHADOW_LOOKUP_MESH
        float V = shadowVisibilityMesh(L, x);  // depth linear across the polyvol mesh's triangles
#else
        float V = shadowVisibilityMedium(L, x);
#endif
        litSamples += V;
        if (V == 0.0) continue;
        // cos theta = dot(direction light->point, direction point->eye) = dot(toLight, w).
        vec3 toLight = directionToLight(L, x);
        float cosTheta = dot(toLight, w);
#ifdef EXACT
        float x0 = m.x0;
        float x1 = m.x1;
        if (L.info.x == kLightDirectional) {
            sum += V * directionalSegment(cosTheta, x0, x1, uSigmaS, uSigmaT, uG, 1.0) * L.radiant.rgb;
        } else {
            // t_P and h of the ray relative to the light (docs/numerics.md#notation); the unit-intensity
            // isotropic segment times the light's angular factor at the sample (a spot's falloff and cookie).
#ifdef NAIVE_CLOSED_FORM
            // Teaching mode (closed_form=naive): the textbook evaluation that fails in the stiff cases.
            sum += V * pointSegmentNaive(L.position.xyz, w, x0, x1, uSigmaS, uSigmaT, 1.0) * lightIntensity(L, x);
#else
            if (L.info.x == kLightVpl) {
                // An area light's VPL: its cosine lobe integrated exactly over the interval too, or its
                // cell's solid angle (lights.glsl, vplHasCell).
                RayLightGeometry g = rayLightGeometry(L.position.xyz, w);
                vec4 lobe = cosineLobeOf(L.position.xyz, w, L.direction.xyz);
                AirlightCell cell = lightCellAlong(L, w, g.tP);
                sum += V * pointSegmentCell(g.tP, g.h, x0, x1, uSigmaS, uSigmaT, uG, 1.0, lobe, cell) * L.radiant.rgb;
            } else {
                RayLightGeometry g = rayLightGeometry(L.position.xyz, w);
                sum += V * pointSegment(g.tP, g.h, x0, x1, uSigmaS, uSigmaT, uG, 1.0) * lightIntensity(L, x);
            }
#endif
        }
#else
        vec3 E = unshadowedIrradiance(L, x, uSigmaT);
        sum += airlightSample(V, cosTheta, E, t, m.dt);
#endif
    }
    float lit = uLast ? (uLightCount > 0 ? litSamples / float(uLightCount * uSamples) : 0.0) : litSamples;
    imageStore(uAirlight, texel, vec4(sum, 1.0));
    imageStore(uLitFraction, texel, vec4(lit));
}
