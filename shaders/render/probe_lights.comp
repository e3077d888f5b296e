#version 450 core
// Test and debugging probe of the shared light code. uMode 0: copy every GpuLight and GpuMaterial member
// into uOut as vec4s (layout check of host_device.glsl against C++). uMode 1: for light uLight and each
// eye-relative point uPoints[i], write lightIntensity, unshadowedIrradiance (uSigmaT), shadowVisibility,
// directionToLight and distanceToLight (4 vec4 per point).
#include "common/shadow_map.glsl"
#include "render/materials.glsl"

layout(local_size_x = 1) in;

layout(std430, binding = kFirstFreeSsboBinding) readonly buffer PointBlock { vec4 uPoints[]; };
layout(std430, binding = kFirstFreeSsboBinding + 1) writeonly buffer OutBlock { vec4 uOut[]; };

uniform int uMode;
uniform int uLight;
uniform int uCount;
#include "common/medium.glsl"  // uSigmaS, uSigmaT, uG

void main() {
    if (uMode == 0) {
        for (int i = 0; i < uCount; ++i) {
            GpuLight L = gLights[i];
            int o = 12 * i;
            uOut[o + 0] = L.position;
            uOut[o + 1] = L.direction;
            uOut[o + 2] = L.radiant;
            uOut[o + 3] = L.spot;
            uOut[o + 4] = L.frameX;
            uOut[o + 5] = L.frameY;
            uOut[o + 6] = vec4(L.info);
            uOut[o + 7] = L.shadow;
            for (int c = 0; c < 4; ++c) uOut[o + 8 + c] = L.shadowMatrix[c];
        }
        int base = 12 * uCount;
        for (int i = 0; i < gMaterials.length(); ++i) {
            GpuMaterial m = gMaterials[i];
            uOut[base + 4 * i + 0] = m.baseColour;
            uOut[base + 4 * i + 1] = m.emissive;
            uOut[base + 4 * i + 2] = vec4(m.layers);
            uOut[base + 4 * i + 3] = m.layerSize;
        }
        return;
    }
    GpuLight L = gLights[uLight];
    for (int i = 0; i < uCount; ++i) {
        vec3 p = uPoints[i].xyz;
        uOut[4 * i + 0] = vec4(lightIntensity(L, p), 0.0);
        uOut[4 * i + 1] = vec4(unshadowedIrradiance(L, p, uSigmaT), 0.0);
        uOut[4 * i + 2] = vec4(shadowVisibility(L, p), 0.0, 0.0, 0.0);
        uOut[4 * i + 3] = vec4(directionToLight(L, p), distanceToLight(L, p));
    }
}
