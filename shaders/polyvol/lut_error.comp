#version 450 core
// polyvol/lut_error.comp (airlight=lut): the table's error against the closed form it was built from, per
// pixel: |lut - analytic| / analytic of the unit-intensity unshadowed airlight of [0, d] along the pixel's
// ray, the largest over the point-like lights (directional lights do not use the table).
layout(local_size_x = 8, local_size_y = 8) in;

#include "polyvol/segment.glsl"

layout(binding = kFirstFreeTextureUnit) uniform sampler2D uDistance;
layout(r32f, binding = 0) uniform writeonly image2D uError;
uniform int uLightCount;

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, uSize))) return;
    float d = texelFetch(uDistance, texel, 0).r;
    vec3 w = fragmentRay(vec2(texel) + 0.5);
    float worst = 0.0;
    for (int i = 0; i < uLightCount; ++i) {
        GpuLight L = gLights[i];
        if (L.info.x == kLightDirectional) continue;
        RayLightGeometry g = rayLightGeometry(L.position.xyz, w);
        float exact = pointSegment(g.tP, g.h, 0.0, d, uSigmaS, uSigmaT, uG, 1.0);
        float table = lutPointSegment(g.tP, g.h, 0.0, d, uSigmaS, uSigmaT, uG);
        if (exact > 0.0) worst = max(worst, abs(table - exact) / exact);
    }
    imageStore(uError, texel, vec4(worst));
}
