// Shadow-map visibility V(p) for a GpuLight (1 = lit), in eye-relative world space: the nearest texel
// of a cube map; for a 2D map the nearest texel corrected along smooth surfaces (shadowStored2D).
// Every map stores a linear distance in scene units (render::ShadowMaps): the distance to the light
// (spot, point, VPL) or the depth dot(p, direction) along a directional light's travel direction.
// Bias: p is lit when  d(p) <= stored + L.shadow.w + L.shadow.z * footprint,  footprint = d(p) / size for
// perspective and cube maps and 1 / size for orthographic maps (shadow.z = 2 texels' worth, see
// gpu_lights.cpp). Points outside a 2D map's frustum or without a map are lit.
#ifndef SHADOW_MAP_GLSL
#define SHADOW_MAP_GLSL

// Feature switches: SHADOW_NO_2D (no spot or directional light) and SHADOW_NO_CUBE (no point light or
// VPL) leave the corresponding lookup out of the compiled shader. SHADOW_LOOKUP_MESH adds
// shadowVisibilityMesh (the polyvol mesh's reconstruction, for exactness comparisons).

#include "common/host_device.glsl"
#include "common/lights.glsl"
#include "common/work_counters.glsl"

layout(binding = kUnitShadow2D) uniform sampler2DArray uShadow2D;
layout(binding = kUnitShadowCube) uniform sampler2DArray uShadowCube;
layout(binding = kUnitShadowCubeVpl) uniform sampler2DArray uShadowCubeVpl;

// The value a shadow map stores for a surface at p (shaders/render/shadow.frag writes the same).
float shadowDepth(GpuLight L, vec3 p) {
    if (L.info.x == kLightDirectional) return dot(p, L.direction.xyz);
    return length(p - L.position.xyz);
}

// Cube faces (+X, -X, +Y, -Y, +Z, -Z): view direction and up vector, the same table as
// render::cubeFaceBasis in shadow_maps.cpp. Face f was rendered with lookAt(light, light + forward, up)
// and a 90-degree square perspective, so ndc = (dot(right, d), dot(trueUp, d)) / dot(forward, d).
void cubeFaceBasis(int face, out vec3 forward, out vec3 up) {
    int axis = face >> 1;
    float s = (face & 1) == 0 ? 1.0 : -1.0;
    forward = vec3(0.0);
    forward[axis] = s;
    up = axis == 1 ? vec3(0.0, 0.0, s) : vec3(0.0, -1.0, 0.0);
}

// Nearest texel of a cube stored as 6 layers (cube * 6 + face) of a 2D array, for direction d != 0.
float cubeLookup(sampler2DArray maps, int cube, vec3 d) {
    vec3 a = abs(d);
    int axis = (a.x >= a.y && a.x >= a.z) ? 0 : (a.y >= a.z ? 1 : 2);
    int face = 2 * axis + (d[axis] < 0.0 ? 1 : 0);
    vec3 forward, up;
    cubeFaceBasis(face, forward, up);
    vec3 right = cross(forward, up);
    vec3 trueUp = cross(right, forward);
    vec2 ndc = vec2(dot(right, d), dot(trueUp, d)) / dot(forward, d);
    ivec2 size = textureSize(maps, 0).xy;
    ivec2 texel = clamp(ivec2(floor((ndc * 0.5 + 0.5) * vec2(size))), ivec2(0), size - 1);
    WORK_COUNT(kWorkShadowTexels, 1);
    return texelFetch(maps, ivec3(texel, 6 * cube + face), 0).r;
}

#ifndef SHADOW_NO_2D
// How far the two one-sided differences of a texel's depth along one map axis may disagree (relative to
// the larger) for the texel and its neighbours to count as one smooth surface.
const float kShadowSmoothTolerance = 0.25;

// The depth a 2D map gives at ndc (|ndc| <= 1): the nearest texel's stored value, moved to ndc along each
// map axis by that axis's slope where the texel and its two neighbours on the axis lie on one smooth
// surface (their one-sided differences agree). A texel stores the depth at its centre; on a surface seen
// at a grazing angle one texel spans a large depth range, and a point up to half a texel times that slope
// behind the surface read as in front of it: light leaked through thin ceilings and walls under a low
// sun (the stiff case sun-grazing-ceiling). Next to a depth discontinuity the differences disagree and the
// nearest value is kept, so silhouettes stay where nearest-texel sampling puts them. Exact on planes.
float shadowStored2D(GpuLight L, vec2 ndc) {
    ivec2 size = textureSize(uShadow2D, 0).xy;
    vec2 f = (ndc * 0.5 + 0.5) * vec2(size);
    // Nearest texel: GL row 0 is at ndc.y = -1, as the map was rendered.
    ivec2 c = clamp(ivec2(floor(f)), ivec2(0), size - 1);
    int layer = L.info.z;
    float s0 = texelFetch(uShadow2D, ivec3(c, layer), 0).r;
    WORK_COUNT(kWorkShadowTexels, 1);
    if (!(s0 < L.shadow.y)) return s0;  // nothing rendered there
    vec2 offset = clamp(f - (vec2(c) + 0.5), vec2(-0.5), vec2(0.5));
    float corrected = s0;
    for (int axis = 0; axis < 2; ++axis) {
        ivec2 e = axis == 0 ? ivec2(1, 0) : ivec2(0, 1);
        ivec2 lo = c - e, hi = c + e;
        if (any(lessThan(lo, ivec2(0))) || any(greaterThanEqual(hi, size))) continue;
        float sl = texelFetch(uShadow2D, ivec3(lo, layer), 0).r;
        float sh = texelFetch(uShadow2D, ivec3(hi, layer), 0).r;
        WORK_COUNT(kWorkShadowTexels, 2);
        if (!(sl < L.shadow.y && sh < L.shadow.y)) continue;
        float dl = s0 - sl, dh = sh - s0;
        if (abs(dh - dl) > kShadowSmoothTolerance * max(abs(dl), abs(dh)) + L.shadow.w) continue;
        corrected += (offset[axis] >= 0.0 ? dh : dl) * offset[axis];
    }
    return corrected;
}

// The largest distance (spot) or depth (directional) a point on the light ray through ndc may have and
// read lit: d <= stored + shadow.w + shadow.z footprint solved for d, surfaceBias2D as in
// shadowVisibilityBiased. Grids built from light rays (minmax's rectified map, vsv's voxels) read it so
// that they and the lookup agree on every point. `stored` returns shadowStored2D (>= shadow.y: nothing
// rendered there).
float shadowLitLimit2D(GpuLight L, vec2 ndc, float surfaceBias2D, out float stored) {
    stored = shadowStored2D(L, ndc);
    float footprintBias = surfaceBias2D * L.shadow.z / float(textureSize(uShadow2D, 0).x);
    return L.info.x == kLightSpot ? (stored + L.shadow.w) / (1.0 - footprintBias)
                                  : stored + L.shadow.w + footprintBias;
}
#endif

// surfaceBias2D scales a 2D map's footprint term of the bias (1 for surfaces, 0 for points of the medium).
float shadowVisibilityBiased(GpuLight L, vec3 p, float surfaceBias2D) {
    int layer = L.info.z;
    if (layer < 0) return 1.0;
    WORK_COUNT(kWorkShadowLookups, 1);
    int type = L.info.x;
    float d = shadowDepth(L, p);
    float stored;
    float footprint;
#ifndef SHADOW_NO_2D
    if (type == kLightSpot || type == kLightDirectional) {
        vec4 clip = L.shadowMatrix * vec4(p, 1.0);
        if (clip.w <= 0.0) return 1.0;
        vec2 ndc = clip.xy / clip.w;
        if (any(greaterThan(abs(ndc), vec2(1.0)))) return 1.0;
        stored = shadowStored2D(L, ndc);
        footprint = surfaceBias2D * (type == kLightSpot ? d : 1.0) / float(textureSize(uShadow2D, 0).x);
    } else
#endif
#ifndef SHADOW_NO_CUBE
    {
        vec3 dir = p - L.position.xyz;
        if (dir == vec3(0.0)) return 1.0;
        bool vpl = type == kLightVpl;
        stored = vpl ? cubeLookup(uShadowCubeVpl, layer, dir) : cubeLookup(uShadowCube, layer, dir);
        footprint = d / float(vpl ? textureSize(uShadowCubeVpl, 0).x : textureSize(uShadowCube, 0).x);
    }
#else
    {
        return 1.0;  // no cube-mapped light in the scene: not compiled
    }
#endif
    return d <= stored + L.shadow.w + L.shadow.z * footprint ? 1.0 : 0.0;
}

// Visibility of a point on a surface: the bias keeps a lit receiver from shadowing itself (acne).
float shadowVisibility(GpuLight L, vec3 p) { return shadowVisibilityBiased(L, p, 1.0); }

// Visibility of a point of the medium. Such a point is no receiver that could shadow itself, so a 2D map
// (whose depth shadowStored2D reconstructs along smooth surfaces) keeps only the constant part of the
// bias: the footprint part lit a band behind every thin wall, two texels deep (the stiff case
// sun-grazing-ceiling). Cube maps have no reconstruction and keep the whole bias.
float shadowVisibilityMedium(GpuLight L, vec3 p) { return shadowVisibilityBiased(L, p, 0.0); }

#ifdef SHADOW_LOOKUP_MESH
// Visibility as the polygonal light volume of polyvol sees it (shaders/polyvol/volume.vert): spot and
// directional maps are reconstructed as triangles between texel centres (two per quad of four, split
// along (i, j) -> (i + 1, j + 1)), linear across each triangle in world space, with no bias; spot texels
// outside the cone or under a dark cookie texel (brightest channel < 1/512) sit at the light. Point is
// lit when it lies between the light (the map's near plane) and that surface. Points outside the spot
// grid are unlit (the volume is closed there); cube maps keep the nearest-texel rule.
const float SHADOW_MESH_COOKIE_MASK = 1.0 / 512.0;

// Direction from the light through ndc (x, y) of a perspective shadow matrix: the intersection of the
// planes clip.x = x clip.w and clip.y = y clip.w, which both contain the light, oriented toward w > 0.
vec3 shadowMeshRayDirection(mat4 m, vec2 ndc) {
    vec3 r0 = vec3(m[0][0], m[1][0], m[2][0]);
    vec3 r1 = vec3(m[0][1], m[1][1], m[2][1]);
    vec3 r3 = vec3(m[0][3], m[1][3], m[2][3]);
    vec3 d = normalize(cross(r0 - ndc.x * r3, r1 - ndc.y * r3));
    return dot(d, r3) < 0.0 ? -d : d;
}

float shadowVisibilityMesh(GpuLight L, vec3 p) {
    int layer = L.info.z;
    if (layer < 0) return 1.0;
    int type = L.info.x;
    if (type != kLightSpot && type != kLightDirectional) return shadowVisibility(L, p);
    WORK_COUNT(kWorkShadowLookups, 1);
    vec4 clip = L.shadowMatrix * vec4(p, 1.0);
    bool spot = type == kLightSpot;
    if (clip.w <= 0.0) return spot ? 0.0 : 1.0;
    vec2 ndc = clip.xy / clip.w;
    int n = textureSize(uShadow2D, 0).x;
    vec2 f = (ndc * 0.5 + 0.5) * float(n) - 0.5;
    ivec2 q = ivec2(floor(f));
    if (any(lessThan(q, ivec2(0))) || any(greaterThan(q, ivec2(n - 2)))) return spot ? 0.0 : 1.0;
    vec2 a = f - vec2(q);
    ivec2 c1 = a.x >= a.y ? ivec2(1, 0) : ivec2(1, 1);
    ivec2 c2 = a.x >= a.y ? ivec2(1, 1) : ivec2(0, 1);
    ivec2 t[3] = ivec2[3](q, q + c1, q + c2);
    float s[3];
    for (int k = 0; k < 3; ++k) s[k] = texelFetch(uShadow2D, ivec3(t[k], layer), 0).r;
    WORK_COUNT(kWorkShadowTexels, 3);
    if (!spot) {
        // Orthographic: world position is affine in ndc, so the surface depth is the barycentric mix.
        vec2 b = a.x >= a.y ? vec2(a.x - a.y, a.y) : vec2(a.x, a.y - a.x);  // weights of t[1], t[2]
        float depth = s[0] + b.x * (s[1] - s[0]) + b.y * (s[2] - s[0]);
        return dot(p, L.direction.xyz) <= depth ? 1.0 : 0.0;
    }
    vec3 v[3];
    for (int k = 0; k < 3; ++k) {
        vec2 texelNdc = (vec2(t[k]) + 0.5) * (2.0 / float(n)) - 1.0;
        vec3 dir = shadowMeshRayDirection(L.shadowMatrix, texelNdc);
        bool dark = spotAttenuation(L, dir) == 0.0;
#ifndef LIGHTS_NO_COOKIE
        vec3 cookie = spotCookie(L, dir);
        dark = dark || max(cookie.r, max(cookie.g, cookie.b)) < SHADOW_MESH_COOKIE_MASK;
#endif
        if (dark) return 0.0;  // a wall of the cone: the triangle contains the light
        v[k] = dir * s[k];
    }
    vec3 u = p - L.position.xyz;
    vec3 nrm = cross(v[1] - v[0], v[2] - v[0]);
    float denom = dot(nrm, u);
    if (denom == 0.0) return 0.0;
    // u * tHit lies on the triangle's plane; lit when p is not beyond it (tHit >= 1).
    float tHit = dot(nrm, v[0]) / denom;
    return tHit >= 1.0 ? 1.0 : 0.0;
}
#endif  // SHADOW_LOOKUP_MESH

// The slope part of the bias in scene units at p: L.shadow.z texel footprints (two texels' width).
float shadowSlopeBias(GpuLight L, vec3 p) {
    int type = L.info.x;
    if (L.info.z < 0) return 0.0;
    if (type == kLightDirectional) return L.shadow.z / float(textureSize(uShadow2D, 0).x);
    float d = shadowDepth(L, p);
    int size = type == kLightSpot ? textureSize(uShadow2D, 0).x
             : type == kLightVpl ? textureSize(uShadowCubeVpl, 0).x : textureSize(uShadowCube, 0).x;
    return L.shadow.z * d / float(size);
}

// Visibility of a surface point with unit normal n (facing the light side being shaded). The lookup
// moves off the surface along n by the slope bias: a receiver tilted steeply away from the light
// otherwise shadows itself in a speckled pattern (acne), because one texel covers a long stretch of it.
float shadowVisibilitySurface(GpuLight L, vec3 p, vec3 n) {
    return shadowVisibility(L, p + n * shadowSlopeBias(L, p));
}

#endif  // SHADOW_MAP_GLSL
