#version 450 core
// Surface pass: per pixel, the Euclidean eye distance and the unattenuated surface radiance of the
// definition: L_e on the emitting side of an emitter + albedo / pi * sum_lights E * max(0, n.l) * V,
// n the interpolated normal flipped toward the eye. Surfaces beyond uZfar count as misses (sky).
#include "common/constants.glsl"
#include "common/shadow_map.glsl"
#include "render/materials.glsl"

// Depth and stencil are tested before the shader (SurfacePass: equal to the prepass's depth, the first
// such fragment only), so that it runs once a pixel even though it may discard.
layout(early_fragment_tests) in;

uniform float uZfar;
#include "common/medium.glsl"  // uSigmaS, uSigmaT, uG
uniform int uLightCount;

in vec3 vPosition;  // eye-relative: the eye is at the origin
in vec3 vNormal;
in vec2 vUv;
flat in uint vMaterial;

layout(location = 0) out float oDistance;
layout(location = 1) out vec4 oRadiance;

void main() {
    WORK_PIXEL(gl_FragCoord.xy);
    WORK_COUNT(kWorkFragments, 1);
    float dist = length(vPosition);
    if (dist > uZfar) WORK_DISCARD;
    vec3 toEye = -vPosition / dist;
    GpuMaterial m = gMaterials[vMaterial];

    vec3 n = normalize(vNormal);
    // Emitters' vertex normals are their light's normal, so this is "sees the emitting side".
    bool front = dot(n, toEye) >= 0.0;
    if (!front) n = -n;

    vec3 radiance = front ? materialEmission(m, vUv) : vec3(0.0);
    vec3 albedo = materialAlbedo(m, vUv);
    vec3 sum = vec3(0.0);
    for (int i = 0; i < uLightCount; ++i) {
        GpuLight L = gLights[i];
        float cosSurface = dot(n, directionToLight(L, vPosition));
        if (cosSurface <= 0.0) continue;
        vec3 E = unshadowedIrradiance(L, vPosition, uSigmaT);
        if (E == vec3(0.0)) continue;
        sum += E * cosSurface * shadowVisibilitySurface(L, vPosition, n);
    }
    radiance += albedo / kPi * sum;

    oDistance = dist;
    oRadiance = vec4(radiance, 1.0);
}
