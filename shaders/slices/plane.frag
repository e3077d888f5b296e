#version 450 core
// slices/plane.frag: shades one sampling plane for one light (Mitchell 2004, "Light Shaft Pixel Shader").
// PHYSICAL: the integrand of the project's airlight definition times the plane spacing along this
// pixel's ray, sigma_s p(cos) E V exp(-sigma_t t) dt with dt = delta_s / dot(w, forward), so the sum over
// planes is a midpoint rule of L_air. Otherwise the paper's artistic formula and constants.
// Terms compiled in by defines: SPOT_FALLOFF, COOKIE, SHADOW (nearest, or PCF), NOISE; CHANNEL_MASK
// routes plane i's scalar to channel i mod 4; COUNT_OUTSIDE counts fragments outside the light frustum.
// Output is scaled by uStoreScale (RGBA8 targets hold [0, 1]).

#include "common/host_device.glsl"
#include "common/airlight.glsl"
#include "common/lights.glsl"
#include "common/shadow_map.glsl"

layout(binding = kFirstFreeTextureUnit) uniform sampler2D uDistance;  // Euclidean d per pixel
layout(binding = kFirstFreeTextureUnit + 1) uniform sampler2D uNoise;  // tileable, r and g two noises

uniform int uLight;           // index into gLights
uniform vec3 uForward;
uniform float uSpacing;       // delta s, view depth between planes
uniform float uSigmaS;
uniform float uSigmaT;
uniform float uG;
uniform float uStoreScale;    // value -> stored value
uniform vec3 uColor;          // artistic: the light's colour (no intensity)
uniform float uArtisticUnits; // paper units per scene unit (the paper's constants assume its world)
uniform float uFractionOfMaxShells;  // N / 100 (the paper's maximum of 100 planes)
uniform float uAmbient;       // the paper's ambient term added to 1/r^2 (artistic: 0.35)
uniform float uNoiseTiles;    // noise repeats per light-space unit square ([-1, 1]^2 -> 2 tiles)
uniform vec4 uScroll;         // xy, zw: scroll offsets of the two noise layers (animated by time)
uniform float uPlaneWeight;   // extra per-plane weight (distance-scaled plane count), 1 normally

#ifdef COUNT_OUTSIDE
layout(binding = 0, offset = 0) uniform atomic_uint uOutside;
layout(binding = 0, offset = 4) uniform atomic_uint uShaded;
#endif

in vec3 vPosition;
flat in int vPlane;
layout(location = 0) out vec4 oColor;

// Shadow term: nearest texel (the paper) or 3x3 percentage-closer filtering on the same map and bias.
float visibility(GpuLight L, vec3 p) {
#ifdef PCF
    vec4 clip = L.shadowMatrix * vec4(p, 1.0);
    if (clip.w <= 0.0) return 1.0;
    vec2 ndc = clip.xy / clip.w;
    if (any(greaterThan(abs(ndc), vec2(1.0)))) return 1.0;
    ivec2 size = textureSize(uShadow2D, 0).xy;
    ivec2 centre = ivec2(floor((ndc * 0.5 + 0.5) * vec2(size)));
    float d = shadowDepth(L, p);
    float footprint = (L.info.x == kLightSpot ? d : 1.0) / float(size.x);
    float lit = 0.0;
    for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) {
            ivec2 texel = clamp(centre + ivec2(i, j), ivec2(0), size - 1);
            float stored = texelFetch(uShadow2D, ivec3(texel, L.info.z), 0).r;
            lit += d <= stored + L.shadow.w + L.shadow.z * footprint ? 1.0 : 0.0;
        }
    return lit / 9.0;
#else
    return shadowVisibility(L, p);
#endif
}

void main() {
    GpuLight L = gLights[uLight];
    vec3 p = vPosition;
#ifdef COUNT_OUTSIDE
    // Outside the light's frustum = outside its shadow map's clip volume.
    vec4 lc = L.shadowMatrix * vec4(p, 1.0);
    if (any(greaterThan(abs(lc.xyz), vec3(lc.w)))) atomicCounterIncrement(uOutside);
    atomicCounterIncrement(uShaded);
#endif
    float t = length(p);
    float d = texelFetch(uDistance, ivec2(gl_FragCoord.xy), 0).r;
    // Beyond the first surface (or zfar) the ray has ended: the plane adds nothing there.
    if (t > d) discard;
    vec3 w = p / t;

    bool directional = L.info.x == kLightDirectional;
    vec3 dirFromLight = directional ? L.direction.xyz : normalize(p - L.position.xyz);
    float angular = 1.0;
#ifdef SPOT_FALLOFF
    if (!directional) angular = spotAttenuation(L, dirFromLight);
#endif
    vec3 cookie = vec3(1.0);
#ifdef COOKIE
    if (!directional) cookie = spotCookie(L, dirFromLight);
#endif
    float V = 1.0;
#ifdef SHADOW
    V = visibility(L, p);
#endif
    // Noise: two tileable layers projected from the light (its clip space xy), scrolled apart.
    float noise = 1.0;
#ifdef NOISE
    vec4 nc = L.shadowMatrix * vec4(p, 1.0);
    vec2 luv = nc.xy / nc.w * (0.5 * uNoiseTiles);
    float n1 = texture(uNoise, luv + uScroll.xy).r;
    float n2 = texture(uNoise, luv + uScroll.zw).g;
#endif

    vec3 value;
#ifdef PHYSICAL
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
        E = L.radiant.rgb * angular * cookie * (exp(-uSigmaT * sqrt(r2)) / max(r2, 1.0e-20));
    }
    float dt = uSpacing / dot(w, uForward);
    value = (uSigmaS * noise * phaseHG(cosTheta, uG) * V * exp(-uSigmaT * t) * dt) * E;
#else
    // The paper's constants: compositeNoise 0.015 (0.05 n1 n2 with noise), atten = ambient + 20000 / r^2
    // in the paper's units, scale = 9 / fFractionOfMaxShells; the cookie enters by its luminance.
    float compositeNoise = 0.015;
#ifdef NOISE
    compositeNoise = n1 * n2 * 0.05;
#endif
    float atten = 1.0;
    if (!directional) {
        vec3 ls = (p - L.position.xyz) * uArtisticUnits;
        atten = uAmbient + 20000.0 / dot(ls, ls);
    }
    float scale = 9.0 / uFractionOfMaxShells;
    float lum = dot(cookie, vec3(0.2126, 0.7152, 0.0722));
    value = vec3(compositeNoise * lum * scale * atten * V * angular) * uColor;
#endif
    value *= uPlaneWeight * uStoreScale;

#ifdef CHANNEL_MASK
    // One scalar per plane, routed to channel (plane mod 4); the colour is put back on composite.
    float scalar = dot(value, vec3(1.0 / 3.0));
    vec4 mask = vec4(0.0);
    mask[vPlane & 3] = 1.0;
    oColor = scalar * mask;
#else
    oColor = vec4(value, 0.0);
#endif
}
