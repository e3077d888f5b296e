#version 450 core
// vsv/voxelize.comp: rectification of the shadow map into the epipolar grid. One invocation per light
// ray (theta cell j, phi bit k; for a directional light a light line, see epipolar.h): the ray's first
// occluder r (the shadow map's linear distance) becomes
// the alpha cell of that occluder, and bit k of word k >> 5 of texel (alpha cell, j) is set (an atomic
// OR: several light rays of one theta can land in one texel). Also writes the occluder's continuous
// alpha coordinate (-1: no occluder in the grid) for inspection and tests.
layout(local_size_x = 8, local_size_y = 8) in;

#include "common/host_device.glsl"
#include "common/lights.glsl"
#include "common/shadow_map.glsl"
#include "vsv/epipolar_uniforms.glsl"
#include "common/work_counters.glsl"

layout(r32ui, binding = 0) uniform coherent uimage2DArray uWords;  // (nAlpha, nTheta, nPhi / 32)
layout(r32f, binding = 1) uniform writeonly image2D uOccluder;     // (nPhi, nTheta)

uniform int uLight;
uniform float uAlphaBias;  // cells; negative pushes the shadow away from the light
uniform float uPhiBias;    // cells; the light ray of bit k is sampled at phi cell k + 0.5 + uPhiBias

// Distance from the light along direction dir at which the light ray counts as blocked: the stored
// linear distance pushed back by the bias of the shared medium lookup (shaders/common/shadow_map.glsl,
// shadowVisibilityMedium: on a spot's map a point at distance r is lit when r <= stored + shadow.w; on a
// cube when r <= stored + shadow.w + shadow.z r / size, i.e. up to r = (stored + shadow.w) /
// (1 - shadow.z / size)), so the grid and shadowVisibilityMedium agree on every point. A huge value when
// nothing was rendered there or the direction leaves the map.
float occluderDistance(GpuLight L, vec3 dir) {
    int layer = L.info.z;
    if (layer < 0) return 3.0e38;
    float stored = 3.0e38;
    int size = 1;
#ifndef SHADOW_NO_2D
    if (L.info.x == kLightSpot) {
        vec4 clip = L.shadowMatrix * vec4(L.position.xyz + dir, 1.0);
        if (clip.w <= 0.0) return 3.0e38;
        vec2 ndc = clip.xy / clip.w;
        if (any(greaterThan(abs(ndc), vec2(1.0)))) return 3.0e38;
        float limit = shadowLitLimit2D(L, ndc, 0.0, stored);
        return stored < L.shadow.y ? limit : 3.0e38;
    } else
#endif
    {
#ifndef SHADOW_NO_CUBE
        stored = cubeLookup(uShadowCube, layer, dir);
        size = textureSize(uShadowCube, 0).x;
#else
        return 3.0e38;
#endif
    }
    if (!(stored < L.shadow.y)) return 3.0e38;
    return (stored + L.shadow.w) / max(1.0e-3, 1.0 - L.shadow.z / float(size));
}

void main() {
    ivec2 id = ivec2(gl_GlobalInvocationID.xy);
    int k = id.x;
    int j = id.y;
    if (k >= uEpiCells.z || j >= uEpiCells.y) return;
    GpuLight L = gLights[uLight];
    EpiSpace S = epiFromUniforms();
    float theta = epiThetaAtCell(S, float(j) + 0.5);
    float phi = uEpiPhi.x + (float(k) + 0.5 + uPhiBias) * uEpiPhi.y;
    float coord = -1.0;
    float c = 1.0e30;
#ifndef SHADOW_NO_2D
    if (L.info.x == kLightDirectional) {
        // Light line at offset y = phi from the eye's line: its points y e + x b; the orthographic map
        // stores dot(p, travel) = -x, so the occluder sits at x = -stored, alpha = atan(y, x).
        vec3 e = cos(theta) * S.u + sin(theta) * S.v;
        vec4 clip = L.shadowMatrix * vec4(phi * e, 1.0);
        vec2 ndc = clip.xy / clip.w;
        if (phi > 0.0 && all(lessThanEqual(abs(ndc), vec2(1.0)))) {
            float stored;
            float blocked = shadowLitLimit2D(L, ndc, 0.0, stored);
            if (L.info.z >= 0 && stored < L.shadow.y) c = epiAlphaCoord(S, atan(phi, -blocked)) - uAlphaBias;
        }
    } else
#endif
    if (phi > 0.0 && phi < kPi) {
        float r = occluderDistance(L, epiLightRay(S, theta, phi));
        if (r < 1.0e38) c = epiAlphaCoord(S, epiAlphaOnLightRay(S, phi, r)) - uAlphaBias;
    }
    if (c < float(uEpiCells.x)) {
        int cell = max(0, int(floor(c)));
        imageAtomicOr(uWords, ivec3(cell, j, k >> 5), 1u << uint(k & 31));
        WORK_COUNT(kWorkVoxelsWritten, 1);
        coord = max(c, 0.0);
    }
    imageStore(uOccluder, ivec2(k, j), vec4(coord));
}
