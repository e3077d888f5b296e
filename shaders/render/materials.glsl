// Materials of render::GpuScene: the SSBO and the base-colour/emission texture array.
#ifndef MATERIALS_GLSL
#define MATERIALS_GLSL

#include "common/host_device.glsl"
#include "common/lights.glsl"

layout(std430, binding = kBindingMaterials) readonly buffer GpuMaterialBlock { GpuMaterial gMaterials[]; };
layout(binding = kUnitMaterialTextures) uniform sampler2DArray uMaterialTextures;

// albedo = baseColorFactor.rgb * sRGB-decoded base-colour texture at uv.
vec3 materialAlbedo(GpuMaterial m, vec2 uv) {
    vec3 albedo = m.baseColour.rgb;
    if (m.layers.x >= 0) albedo *= sampleLayerLinearRgb(uMaterialTextures, m.layers.x, uv, m.layerSize.xy);
    return albedo;
}

// Emitted radiance L_e = emissiveFactor * strength * sRGB-decoded emission texture at uv.
vec3 materialEmission(GpuMaterial m, vec2 uv) {
    vec3 le = m.emissive.rgb;
    if (m.layers.y >= 0 && le != vec3(0.0)) {
        le *= sampleLayerLinearRgb(uMaterialTextures, m.layers.y, uv, m.layerSize.zw);
    }
    return le;
}

#endif  // MATERIALS_GLSL
