// Light evaluation for GpuLight (common/host_device.glsl), in eye-relative world space. Implements the
// emission side of the project's definition: E = I * colour * A_spot * cookie * exp(-sigma_t r) / r^2
// (point, spot), E = I * colour (directional), VPL: E = weight * max(0, cos theta_e) * exp(-sigma_t r) / r^2
// (a point) or L_e * Omega_cell * exp(-sigma_t r) (its cell, vplHasCell).
#ifndef LIGHTS_GLSL
#define LIGHTS_GLSL

// Feature switches (gl::ProgramDesc defines): a technique whose plan finds no spot light, or no cookie,
// defines LIGHTS_NO_SPOT or LIGHTS_NO_COOKIE and that code is not compiled. Without them every light
// type is handled at run time.

#include "common/host_device.glsl"
#include "common/solid_angle.glsl"

// The lights as a uniform block (see host_device.glsl for why not the SSBO); count from the caller.
layout(std140, binding = kBindingLightsUniform) uniform GpuLightBlock { GpuLight gLights[kMaxGpuLights]; };
layout(binding = kUnitCookies) uniform sampler2DArray uCookies;

// An area light's VPL stands for its cell of the emitter (render/gpu_lights.cpp: the cells tile the
// emitter with the Gauss-Legendre weights, each holding its node). Far from the emitter that is a point,
// L_e dA cos(theta_e) / r^2; near it a point's kernel spikes like 1 / r^2 (a bright dot in the air and on
// the walls next to each VPL) where the emitter gives at most 2 pi L_e. With `vpl_kernel=cell` (the
// shared parameter, default; position.w = 1) the air and the surfaces see the cell's exact solid angle
// instead: E = L_e Omega_cell(p) exp(-sigma_t r), r the distance to the node, which is the point's
// kernel once the cell is small as seen from p, and bounded by 2 pi L_e next to it. The cell rides in
// the VPL's spot (xyz: a corner, w: its area dA), frameX.xyz and frameY.xyz (its two edges); the phase
// angle, the attenuation and the visibility stay the node's. docs/numerics.md, "A VPL's cell".
bool vplHasCell(GpuLight L) {
#ifdef SHADOW_NO_CUBE
    return false;  // the plan found no point or area light: no VPL, and the code below folds away
#else
    return L.info.x == kLightVpl && L.position.w > 0.0 && L.spot.w > 0.0;  // a cell of no area: the point
#endif
}

// A VPL's cell seen from p (vplHasCell).
float vplCellSolidAngle(GpuLight L, vec3 p) {
    return parallelogramSolidAngle(L.spot.xyz - p, L.frameX.xyz, L.frameY.xyz, L.direction.xyz, L.spot.w);
}

// A VPL cell's angular factor at p, in place of a point's cos(theta_e): Omega_cell(p) r^2 / dA (r2 = r^2
// = |p - D|^2, as the caller has it), so that the point's I / r^2 with I = L_e dA gives L_e Omega_cell.
float vplCellFactor(GpuLight L, vec3 p, float r2) {
    return cellAngularFactor(L.spot.xyz - p, L.frameX.xyz, L.frameY.xyz, L.direction.xyz, L.spot.w, r2);
}

// distanceToLight() of a directional light.
const float kInfiniteDistance = 1.0e30;

// IEC 61966-2-1 sRGB decoding of a unorm value (the texture holds the file's sRGB bytes as RGBA8; the
// texture unit's own sRGB decode is approximate on llvmpipe).
vec3 srgbToLinear(vec3 c) {
    return mix(pow((c + 0.055) / 1.055, vec3(2.4)), c / 12.92, lessThanEqual(c, vec3(0.04045)));
}

// Linear RGB of one texel of an sRGB-byte layer.
vec3 fetchLinearRgb(sampler2DArray tex, ivec3 texel) { return srgbToLinear(texelFetch(tex, texel, 0).rgb); }

// Bilinear filter of the decoded texels of a layer of a texture array (decode, then filter), clamp to
// edge, v = 0 at texel row 0 (the image's top row), texel (i, j) centred at ((i + 0.5) / w, (j + 0.5) / h)
// of a w x h image stored in the [0, w) x [0, h) corner of the layer. Filtering by hand keeps the weights
// in fp32 (hardware filtering may quantise them), mirroring scene::sampleLinearRgb.
vec3 sampleLayerLinearRgb(sampler2DArray tex, int layer, vec2 uv, vec2 size) {
    vec2 f = clamp(uv, 0.0, 1.0) * size - 0.5;
    vec2 f0 = floor(f);
    vec2 a = f - f0;
    ivec2 maxTexel = ivec2(size) - 1;
    ivec2 i0 = clamp(ivec2(f0), ivec2(0), maxTexel);
    ivec2 i1 = clamp(ivec2(f0) + 1, ivec2(0), maxTexel);
    vec3 c00 = fetchLinearRgb(tex, ivec3(i0.x, i0.y, layer));
    vec3 c10 = fetchLinearRgb(tex, ivec3(i1.x, i0.y, layer));
    vec3 c01 = fetchLinearRgb(tex, ivec3(i0.x, i1.y, layer));
    vec3 c11 = fetchLinearRgb(tex, ivec3(i1.x, i1.y, layer));
    return mix(mix(c00, c10, a.x), mix(c01, c11, a.x), a.y);
}

// Unit vector from p toward the light (directional: against the travel direction).
vec3 directionToLight(GpuLight L, vec3 p) {
    if (L.info.x == kLightDirectional) return -L.direction.xyz;
    return normalize(L.position.xyz - p);
}

// Distance from p to the light, scene units (kInfiniteDistance for directional lights).
float distanceToLight(GpuLight L, vec3 p) {
    if (L.info.x == kLightDirectional) return kInfiniteDistance;
    return length(L.position.xyz - p);
}

// KHR_lights_punctual angular attenuation: clamp(cd * scale + offset, 0, 1)^2, cd = cos(axis, light->p).
float spotAttenuation(GpuLight L, vec3 dirFromLight) {
    float cd = dot(L.direction.xyz, dirFromLight);
    float a = clamp(cd * L.spot.x + L.spot.y, 0.0, 1.0);
    return a * a;
}

// cos(inner) of a spot: A_spot = 1 from there in (cd * scale + offset >= 1), the penumbra between it and
// cos(outer) (L.spot.w).
float spotCosInner(GpuLight L) {
    return min((1.0 - L.spot.y) / L.spot.x, 1.0);
}

// Cookie projected over the outer cone: in the light frame (x right, y up, z axis),
// uv = 0.5 + 0.5 (x, y) / (z tan(outer)), v = 0 at the top row; 1 without a cookie.
vec3 spotCookie(GpuLight L, vec3 dirFromLight) {
#ifdef LIGHTS_NO_COOKIE
    return vec3(1.0);  // the technique's plan says no light has a cookie: not compiled
#endif
    if (L.info.y < 0) return vec3(1.0);
    float z = dot(L.direction.xyz, dirFromLight);
    if (z <= 0.0) return vec3(0.0);  // behind the light: outside every cone (A_spot = 0 there too)
    vec2 xy = vec2(dot(L.frameX.xyz, dirFromLight), dot(L.frameY.xyz, dirFromLight));
    vec2 uv = 0.5 + 0.5 * xy / (z * L.spot.z);
    return sampleLayerLinearRgb(uCookies, L.info.y, uv, vec2(L.frameX.w, L.frameY.w));
}

// The angle one cookie texel spans as seen from a spot light, across the width: the cookie covers
// 2 atan(tan(outer)) over frameX.w texels. Quadratures that follow the cookie step by it (polyvol's pieces,
// slices' slab nodes).
float cookieTexelAngle(GpuLight L) {
    return 2.0 * atan(L.spot.z) / max(L.frameX.w, 1.0);
}

// The light's angular emission toward p, without distance terms: colour * I * A_spot * cookie (spot),
// colour * I (point, directional), weight * max(0, cos theta_e) (VPL).
vec3 lightIntensity(GpuLight L, vec3 p) {
    int type = L.info.x;
    if (type == kLightPoint || type == kLightDirectional) return L.radiant.rgb;
    vec3 dirFromLight = normalize(p - L.position.xyz);
#ifndef LIGHTS_NO_SPOT
    if (type == kLightSpot) {
        float a = spotAttenuation(L, dirFromLight);
        if (a == 0.0) return vec3(0.0);
        return L.radiant.rgb * a * spotCookie(L, dirFromLight);
    }
#endif
    // VPL: cosine lobe around the emitter normal.
    return L.radiant.rgb * max(0.0, dot(L.direction.xyz, dirFromLight));
}

// The part [t0, t1] of the eye ray x = t w, t in [0, d], where a light can add airlight, so that samples
// along the ray are spent there and never depend on d alone (a camera's zfar of 1e6): at most 60 mean
// free paths from the eye (exp(-60) < 1e-26 of what nearer points add), and for a spot light its outer
// cone, outside which A_spot is 0. The cone test solves |v|^2 cos^2 = (v . axis)^2 for v = t w - P on the
// forward nappe; it is widened a little and falls back to the whole ray when degenerate, so it can only
// include too much, never cut a lit stretch. Empty when t0 >= t1.
// The part of [0, d] within kReachMeanFreePaths mean free paths of the eye: past it every light counts
// as spent (exp(-60) < 1e-26 of what nearer points add).
float reachAlongRay(float d, float sigma_t) {
    return sigma_t > 0.0 ? min(d, float(kReachMeanFreePaths) / sigma_t) : d;
}

vec2 litInterval(GpuLight L, vec3 w, float d, float sigma_t) {
    float far = reachAlongRay(d, sigma_t);
    vec2 r = vec2(0.0, far);
#ifndef LIGHTS_NO_SPOT
    if (L.info.x != kLightSpot) return r;
    vec3 P = L.position.xyz;
    vec3 D = L.direction.xyz;
    float c = L.spot.w;  // cos(outer) in [0, 1)
    float a1 = dot(w, D), b1 = -dot(P, D);  // v . D = a1 t + b1
    float c2 = c * c;
    float A = a1 * a1 - c2;
    float B = 2.0 * (a1 * b1 + c2 * dot(w, P));
    float C = b1 * b1 - c2 * dot(P, P);
    float scale = length(P) + far;
    float pad = 1.0e-3 * scale;
    if (abs(A) < 1.0e-4) return r;  // the ray runs almost along the cone's surface: keep it whole
    float disc = B * B - 4.0 * A * C;
    if (disc < 0.0) {
        // No crossing: the ray is wholly inside the double cone (A > 0) or wholly outside (A < 0).
        if (A < 0.0) return vec2(1.0, 0.0);
        // Inside: the forward nappe is where v . D >= 0.
        float tAxis = -b1 / a1;
        return a1 > 0.0 ? vec2(max(0.0, tAxis - pad), far) : vec2(0.0, min(far, tAxis + pad));
    }
    float q = -0.5 * (B + (B >= 0.0 ? 1.0 : -1.0) * sqrt(disc));
    float t1 = q / A, t2 = C / q;
    if (t1 > t2) { float tmp = t1; t1 = t2; t2 = tmp; }
    vec2 seg;
    if (A < 0.0) {
        // Inside the double cone between the roots; one nappe or the other (the midpoint says which).
        if (a1 * 0.5 * (t1 + t2) + b1 < 0.0) return vec2(1.0, 0.0);
        float grow = pad + 1.0e-3 * (t2 - t1);
        seg = vec2(t1 - grow, t2 + grow);
    } else {
        // Inside before t1 and after t2; the forward nappe is the end the ray travels along the axis.
        seg = a1 > 0.0 ? vec2(t2 - pad - 1.0e-3 * abs(t2), 3.0e38) : vec2(-3.0e38, t1 + pad + 1.0e-3 * abs(t1));
    }
    r = vec2(max(r.x, seg.x), min(r.y, seg.y));
    if (any(isnan(r))) return vec2(0.0, far);
#endif
    return r;
}

// E of the definition at p: lightIntensity * exp(-sigma_t r) / r^2 for point-like lights, I * colour for
// directional ones (no attenuation on the light side). No visibility.
vec3 unshadowedIrradiance(GpuLight L, vec3 p, float sigma_t) {
    if (L.info.x == kLightDirectional) return L.radiant.rgb;
    vec3 d = L.position.xyz - p;
    float r2 = dot(d, d);
    // A VPL's cell: L_e times its solid angle (vplHasCell), bounded next to the emitter.
    if (vplHasCell(L)) return L.radiant.rgb / L.spot.w * vplCellSolidAngle(L, p) * exp(-sigma_t * sqrt(r2));
    // r -> 0 is a true singularity of the definition; the floor only keeps it finite.
    return lightIntensity(L, p) * (exp(-sigma_t * sqrt(r2)) / max(r2, 1.0e-20));
}

#endif  // LIGHTS_GLSL
