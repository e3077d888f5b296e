#version 450 core
// slices/plane.frag: shades one sampling plane (Mitchell 2004, "Light Shaft Pixel Shader") for one spot
// light, or for all unbounded lights (point, area-light VPLs, directional) at once.
// PHYSICAL: the integrand of the project's airlight definition times the plane spacing along this
// pixel's ray, sigma_s p(cos) E V exp(-sigma_t t) dt with dt = delta_s / dot(w, forward), so the sum over
// planes is a midpoint rule of L_air. Otherwise the paper's artistic formula and constants.
// Terms compiled in by defines: SPOT_FALLOFF, COOKIE, SHADOW (nearest, or PCF), NOISE; CHANNEL_MASK
// routes plane i's scalar to channel i mod 4; COUNT_OUTSIDE counts fragments outside the light frustum.
// SLAB_EQUIANGULAR (integration=equiangular, physical weighting only): instead of one sample at the
// plane, the fragment integrates its whole slab along the pixel's ray, cut to the surface and to a spot's
// cone (litInterval), with nodes equally spaced in the angle the part subtends at the light, at most
// uSlabAngle radians apart (and one cookie texel; one node for a directional light): t = t_P + h tan(theta), weight
// dtheta / h, so the 1/r^2 of E is integrated exactly and the nodes crowd where a ray passes the light.
// plane.vert widens each plane and its clip planes by the slab (a slab whose plane point misses the light
// volume may still cross it).
// Output is scaled by uStoreScale (RGBA8 targets hold [0, 1]).
// PICK_RAY (a separate draw of the same planes, scissored to the picked pixel, colour writes off): the
// fragment there writes what it computed and did into its plane's record (slices.ray_planes;
// pick_replay.* fills in the planes that made no fragment there).

#include "common/host_device.glsl"
#include "common/airlight.glsl"
#include "common/lights.glsl"
#include "common/shadow_map.glsl"

layout(binding = kFirstFreeTextureUnit) uniform sampler2D uDistance;  // Euclidean d per pixel
layout(binding = kFirstFreeTextureUnit + 1) uniform sampler2D uNoise;  // tileable, r and g two noises

uniform int uLight;           // index into gLights, or -1: every unbounded light (see main)
uniform int uLightCount;
uniform int uBoxedDirectional;  // 1: directional lights are drawn boxed, one by one
#include "slices/pixel_ray.glsl"  // uForward, uRight, uUp, uSize, uTanHalf, uAspect, pixelRay
#include "slices/slab.glsl"    // uSpacing, slabLength
#include "common/medium.glsl"  // uSigmaS, uSigmaT, uG
#include "common/airlight_sample.glsl"
uniform float uStoreScale;    // value -> stored value
uniform float uArtisticUnits; // paper units per scene unit (the paper's constants assume its world)
uniform float uFractionOfMaxShells;  // N / 100 (the paper's maximum of 100 planes)
uniform float uAmbient;       // the paper's ambient term added to 1/r^2 (artistic: 0.35)
uniform int uFalloff;         // artistic: 1 = ambient + 20000 / r^2, 0 = constant intensity
uniform float uNoiseTiles;    // noise repeats per light-space unit square ([-1, 1]^2 -> 2 tiles)
uniform vec4 uScroll;         // xy, zw: scroll offsets of the two noise layers (animated by time)
uniform float uPlaneWeight;   // extra per-plane weight (distance-scaled plane count), 1 normally
#ifdef SLAB_EQUIANGULAR
uniform float uSlabAngle;     // the largest angle between two nodes of a slab, radians
const int kMaxSlabNodes = 64;
flat in vec2 vSlab;           // the slab's view-depth range [s_lo, s_hi]
#endif

#ifdef COUNT_OUTSIDE
layout(binding = 0, offset = 0) uniform atomic_uint uOutside;
layout(binding = 0, offset = 4) uniform atomic_uint uShaded;
uniform int uCountPass;
#endif

#ifdef PICK_RAY
#include "slices/pick_record.glsl"
uniform ivec2 uPickPixel;  // GL window coordinates of the picked pixel (row 0 at the bottom)
uniform int uPickBase;     // this draw set's first record
#endif
// Shadow test results of the lights shade() evaluated for this fragment (the picked pixel's record).
float gVisibilitySum = 0.0;
float gVisibilityCount = 0.0;

// depth_test=1 (plane.vert): the depth test before the shader even where it writes work counters (a
// shader with side effects is otherwise tested after it runs), so the counters count what is shaded. Not
// with COUNT_OUTSIDE (count_fragments=1, which runs without the depth test), whose occlusion-query pass
// counts the fragments it discards.
#ifndef COUNT_OUTSIDE
layout(early_fragment_tests) in;
#endif

flat in float vDepth;  // s_i
flat in int vPlane;
layout(location = 0) out vec4 oColour;

// Shadow term: nearest texel (the paper) or 3x3 percentage-closer filtering on the same map and bias.
float visibility(GpuLight L, vec3 p) {
#ifdef PCF
    if (L.info.x != kLightSpot && L.info.x != kLightDirectional) return shadowVisibilityMedium(L, p);
    vec4 clip = L.shadowMatrix * vec4(p, 1.0);
    if (clip.w <= 0.0) return 1.0;
    vec2 ndc = clip.xy / clip.w;
    if (any(greaterThan(abs(ndc), vec2(1.0)))) return 1.0;
    ivec2 size = textureSize(uShadow2D, 0).xy;
    ivec2 centre = ivec2(floor((ndc * 0.5 + 0.5) * vec2(size)));
    float d = shadowDepth(L, p);
    float footprint = (L.info.x == kLightSpot ? d : 1.0) / float(size.x);
    float lit = 0.0;
    WORK_COUNT(kWorkShadowLookups, 1);
    WORK_COUNT(kWorkShadowTexels, 9);
    for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) {
            ivec2 texel = clamp(centre + ivec2(i, j), ivec2(0), size - 1);
            float stored = texelFetch(uShadow2D, ivec3(texel, L.info.z), 0).r;
            lit += d <= stored + L.shadow.w + L.shadow.z * footprint ? 1.0 : 0.0;
        }
    return lit / 9.0;
#else
    return shadowVisibilityMedium(L, p);
#endif
}

// One light's contribution at distance t along ray w, standing for dt of the ray (SLAB_EQUIANGULAR, a
// point-like light: dt is int dt / r^2 over the node's part, and E leaves out its 1/r^2), before the
// store scale.
vec3 shade(GpuLight L, vec3 w, float t, float dt) {
    vec3 p = t * w;
    int type = L.info.x;
    bool directional = type == kLightDirectional;
    bool spot = type == kLightSpot;
    // At the light itself (a node of a ray through it, integration=equiangular) the direction from it is
    // the ray's own.
    vec3 fromLight = p - L.position.xyz;
    vec3 dirFromLight = directional ? L.direction.xyz : dot(fromLight, fromLight) > 1.0e-30 ? normalize(fromLight) : w;
    float angular = 1.0;
#ifdef SPOT_FALLOFF
    if (spot) angular = spotAttenuation(L, dirFromLight);
#endif
    vec3 cookie = vec3(1.0);
#ifdef COOKIE
    if (spot) cookie = spotCookie(L, dirFromLight);
#endif
    // A VPL (one node of an area light) emits a cosine lobe around the emitter normal as a point; as its
    // cell (lights.glsl, vplHasCell) the cell's solid angle takes the place of lobe and inverse square.
    if (type == kLightVpl) angular = max(0.0, dot(L.direction.xyz, dirFromLight));
    float V = 1.0;
#ifdef SHADOW
    V = visibility(L, p);
#endif
    gVisibilitySum += V;
    gVisibilityCount += 1.0;
    // Noise: two tileable layers projected from the light (spot / directional: its shadow map's clip xy;
    // point lights and VPLs: the eye-relative xz plane), scrolled apart.
#ifdef NOISE
    vec2 luv;
    if (spot || directional) {
        vec4 nc = L.shadowMatrix * vec4(p, 1.0);
        luv = nc.xy / nc.w * (0.5 * uNoiseTiles);
    } else {
        luv = p.xz * (0.1 * uNoiseTiles);
    }
    float n1 = texture(uNoise, luv + uScroll.xy).r;
    float n2 = texture(uNoise, luv + uScroll.zw).g;
#endif

#ifdef PHYSICAL
    float noise = 1.0;
#ifdef NOISE
    noise = 4.0 * n1 * n2;  // mean about 1: noise modulates the density, it does not dim the medium
#endif
    // cos theta = dot(direction light->point, direction point->eye) = dot(dirFromLight, -w).
    float cosTheta = dot(dirFromLight, -w);
    vec3 E;
    if (directional) {
        E = L.radiant.rgb;
    } else {
        vec3 toLight = L.position.xyz - p;
        float r2 = dot(toLight, toLight);
        if (vplHasCell(L)) angular = vplCellFactor(L, p, r2);  // E below is then L_e Omega_cell
#ifdef SLAB_EQUIANGULAR
        E = L.radiant.rgb * angular * cookie * exp(-uSigmaT * sqrt(r2));
#else
        E = L.radiant.rgb * angular * cookie * (exp(-uSigmaT * sqrt(r2)) / max(r2, 1.0e-20));
#endif
    }
    // The noise scales the density where the sample is, as visibility scales what reaches it.
    return airlightSample(V * noise, cosTheta, E, t, dt);
#else
    // The paper's constants: compositeNoise 0.015 (0.05 n1 n2 with noise), atten = ambient + 20000 / r^2
    // in the paper's units, scale = 9 / fFractionOfMaxShells; the cookie enters by its luminance. Colour:
    // the light's, normalised to a maximum of 1 (no intensity).
    float compositeNoise = 0.015;
#ifdef NOISE
    compositeNoise = n1 * n2 * 0.05;
#endif
    float atten = 1.0;
    if (!directional && uFalloff != 0) {
        vec3 ls = (p - L.position.xyz) * uArtisticUnits;
        atten = uAmbient + 20000.0 / dot(ls, ls);
    }
    float scale = 9.0 / uFractionOfMaxShells;
    float lum = dot(cookie, vec3(0.2126, 0.7152, 0.0722));
    vec3 colour = L.radiant.rgb / max(max(L.radiant.r, L.radiant.g), max(L.radiant.b, 1.0e-30));
    return vec3(compositeNoise * lum * scale * atten * V * angular) * colour;
#endif
}

#ifdef SLAB_EQUIANGULAR
// One light's part of L_air over [t0, t1] of ray w (this fragment's slab, cut to the surface d): a
// spot's cone cuts it further; the nodes split the angle it subtends at the light into equal steps of at
// most uSlabAngle. shade() is called once, in the loop (docs/architecture.md, "Shader branches on a CPU
// rasteriser").
vec3 slabIntegral(GpuLight L, vec3 w, float t0, float t1, float d) {
    if (L.info.x == kLightSpot) {
        vec2 lit = litInterval(L, w, d, uSigmaT);
        t0 = max(t0, lit.x);
        t1 = min(t1, lit.y);
    }
    if (!(t1 > t0)) return vec3(0.0);
#if defined(LIGHTS_NO_SPOT) && defined(SHADOW_NO_CUBE)
    // Only suns in the scene (the plan's LIGHTS_NO_SPOT and SHADOW_NO_CUBE): one node at the middle of the
    // cut slab, and the angle code is not compiled (llvmpipe would run it, masked, for every fragment).
    return shade(L, w, 0.5 * (t0 + t1), t1 - t0);
#else
    bool directional = L.info.x == kLightDirectional;
    float tP = 0.0, h = 1.0, a0 = 0.0, step_ = t1 - t0;
    int nodes = 1;
    if (!directional) {
        // Foot point t_P and distance h of the light from the ray; the angle from the foot point, and the
        // angle the part subtends, written without cancellation (both ends on one side: h -> 0 gives
        // (s1 - s0) h / (s0 s1)). h is floored as the closed forms floor it (airlight.glsl).
        RayLightGeometry g = rayLightGeometry(L.position.xyz, w);
        tP = g.tP;
        float s0 = t0 - tP, s1 = t1 - tP;
        h = max(g.h, max(AIRLIGHT_MIN_RELATIVE_H * max(abs(s0), abs(s1)), AIRLIGHT_MIN_ABSOLUTE_H));
        float subtended = atan(h * (s1 - s0), h * h + s0 * s1);
        a0 = atan(s0 / h);
        // Under a cookie the nodes follow its texels, as polyvol's pieces do: a ray passing the apex
        // crosses the whole cookie.
        float stepMax = uSlabAngle;
#ifndef LIGHTS_NO_SPOT
        if (L.info.x == kLightSpot) {
            // A_spot changes across the penumbra, between the outer and the inner cone: unless the part lies
            // wholly inside the inner cone (a convex set: both ends inside means all of it), at most an
            // eighth of the penumbra's angle a node (grate, 160x120, 64 planes: the slabs at the cone's edge
            // were up to 20x too dark with one node, its middle outside the cone).
            float cosInner = spotCosInner(L);
            vec3 axis = L.direction.xyz;
            float cd0 = dot(normalize(t0 * w - L.position.xyz), axis);
            float cd1 = dot(normalize(t1 * w - L.position.xyz), axis);
            if (min(cd0, cd1) < cosInner)
                stepMax = min(stepMax, max(acos(L.spot.w) - acos(cosInner), 8.0e-3) / 8.0);
        }
#endif
#ifdef COOKIE
        if (L.info.x == kLightSpot && L.info.y >= 0) stepMax = min(stepMax, cookieTexelAngle(L));
#endif
        // An area light's VPLs take one node each (still 1/r^2 exact over the slab): there are many of them,
        // and their own spacing, not the slab's, is what limits such a light (tv-room, 128 planes, 320x240:
        // 0.756 with nodes by angle, 0.702 with one; 0.762 with the midpoint rule).
        nodes = L.info.x == kLightVpl ? 1 : clamp(int(ceil(subtended / stepMax)), 1, kMaxSlabNodes);
        step_ = subtended / float(nodes);
    }
    vec3 sum = vec3(0.0);
    for (int j = 0; j < nodes; ++j) {
        // The node at the middle of its angle step, kept inside the part against rounding near +-pi/2.
        float t = directional ? 0.5 * (t0 + t1) : clamp(tP + h * tan(a0 + (float(j) + 0.5) * step_), t0, t1);
        sum += shade(L, w, t, directional ? step_ : step_ / h);
    }
    return sum;
#endif
}
#endif

void main() {
    WORK_PIXEL(gl_FragCoord.xy);
    WORK_COUNT(kWorkFragments, 1);
    // The sample point is where this pixel's centre ray meets the plane dot(p, forward) = s_i. Computed
    // per pixel rather than interpolated, so it does not depend on how clipping re-triangulated the quad.
    vec3 w = pixelRay(gl_FragCoord.xy);
    float t = vDepth / dot(w, uForward);
    vec3 p = t * w;
#ifdef COUNT_OUTSIDE
    // Outside the light's frustum = outside its shadow map's clip volume (uLight >= 0: a clipped light).
    // Counted twice: by atomic counters in the normal pass, and by occlusion queries over extra passes
    // with colour writes off (uCountPass 1: every fragment passes, 2: only those outside pass). p is
    // exact, but a boundary fragment is allowed fp32 rounding (1e-4 of w) before it counts as outside.
    bool outside = false;
    if (uLight >= 0) {
        vec4 lc = gLights[uLight].shadowMatrix * vec4(p, 1.0);
        outside = lc.w <= 0.0 || any(greaterThan(abs(lc.xyz), vec3(lc.w * (1.0 + 1.0e-4))));
    }
    if (uCountPass == 1) { oColour = vec4(0.0); return; }
    if (uCountPass == 2) {
        if (!outside) WORK_DISCARD;
        oColour = vec4(0.0);
        return;
    }
    if (outside) atomicCounterIncrement(uOutside);
    atomicCounterIncrement(uShaded);
#endif
    float d = texelFetch(uDistance, ivec2(gl_FragCoord.xy), 0).r;
    float dt = slabLength(vPlane) / dot(w, uForward);
#ifdef SLAB_EQUIANGULAR
    // The slab along this ray, cut to the surface; it has ended when the slab begins beyond it.
    float slabStart = vSlab.x / dot(w, uForward), slabEnd = min(vSlab.y / dot(w, uForward), d);
    bool beyond = !(slabEnd > slabStart);
#else
    bool beyond = t > d;
#endif
#ifdef PICK_RAY
    // The pick draw is scissored to the picked pixel; the test keeps the records right without it.
    bool picked = ivec2(gl_FragCoord.xy) == uPickPixel;
    int record = uPickBase + vPlane;
    if (picked) gPick[record].where = vec4(float(vPlane), vDepth, t, dt);
    if (picked && beyond) gPick[record].test = vec4(kPickBeyondSurface, -1.0, -1.0, d);  // V: not tested
#endif
    // Beyond the first surface (or zfar) the ray has ended: the plane adds nothing there.
    if (beyond) WORK_DISCARD;

    // One light (uLight >= 0: a spot, or a boxed directional light, drawn clipped to its own volume), or
    // every unbounded light sharing one set of planes over the camera frustum: every light except spots
    // and, with directional_box, directional lights. One loop with one call of shade() for both: a second
    // call in an else branch would be run, masked, by every fragment on llvmpipe.
    vec3 value = vec3(0.0);
    int first = max(uLight, 0);
    int last = uLight >= 0 ? uLight + 1 : uLightCount;
    for (int i = first; i < last; ++i) {
        GpuLight L = gLights[i];
        if (uLight < 0 && (L.info.x == kLightSpot || (uBoxedDirectional != 0 && L.info.x == kLightDirectional)))
            continue;
#ifdef SLAB_EQUIANGULAR
        value += slabIntegral(L, w, slabStart, slabEnd, d);
#else
        value += shade(L, w, t, dt);
#endif
    }
    value *= uPlaneWeight * uStoreScale;

#ifdef CHANNEL_MASK
    // One scalar per plane, routed to channel (plane mod 4); the colour is put back on composite.
    float scalar = dot(value, vec3(1.0 / 3.0));
    vec4 mask = vec4(0.0);
    mask[vPlane & 3] = 1.0;
    oColour = scalar * mask;
#else
    oColour = vec4(value, 0.0);
#endif
#ifdef PICK_RAY
    if (picked) {
        // V: the set's light, or the mean over the unbounded lights; channel: where the mask sent it.
        float V = gVisibilityCount > 0.0 ? gVisibilitySum / gVisibilityCount : 1.0;
#ifdef CHANNEL_MASK
        float channel = float(vPlane & 3);
#else
        float channel = -1.0;
#endif
        gPick[record].test = vec4(kPickAdded, V, channel, d);
        gPick[record].value = oColour;
    }
#endif
}
