#version 450 core
// polyvol/resolve.comp: once per pixel and light, after the light's volume is drawn:
// - origin=surface (volume.frag): adds c L(0, d), c = the light's signed crossing count in the total's
//   alpha (0 or 1: whether the eye is lit), without the ray's chord through the ball around the light;
// - both origins: adds the airlight of that chord, clipped to [0, d] (README, "Rays next to the light":
//   nothing occludes inside the ball, so the chord is lit wherever the light's angular factor is);
// then zeroes the alpha for the next light.
layout(local_size_x = 8, local_size_y = 8) in;

#include "polyvol/segment.glsl"

layout(binding = kFirstFreeTextureUnit) uniform sampler2D uDistance;
layout(rgba32f, binding = 0) uniform image2D uTotal;
layout(rgba32f, binding = 1) uniform image2D uPositive;
layout(rgba32f, binding = 2) uniform image2D uNegative;

uniform int uLightIndex;
uniform int uConstant;
uniform int uOriginAtSurface;
uniform float uNearRadius;

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, uSize))) return;
    vec4 total = imageLoad(uTotal, texel);
    float c = uOriginAtSurface != 0 ? total.a : 0.0;
    float d = texelFetch(uDistance, texel, 0).r;
    vec3 w = fragmentRay(vec2(texel) + 0.5);
    vec3 added = vec3(0.0);
    vec3 positive = vec3(0.0);
    vec3 negative = vec3(0.0);
    if (c != 0.0) {
        vec3 base = uConstant != 0 ? vec3(d) : segmentAirlightOutsideBall(gLights[uLightIndex], w, 0.0, d, uNearRadius);
        added += c * base;
        if (c > 0.0) positive += c * base; else negative -= c * base;
    }
    if (uConstant == 0 && uNearRadius > 0.0) {
        vec3 ball = ballAirlight(gLights[uLightIndex], w, d, uNearRadius);
        added += ball;
        positive += ball;
    }
    if (any(notEqual(positive, vec3(0.0)))) imageStore(uPositive, texel, imageLoad(uPositive, texel) + vec4(positive, 0.0));
    if (any(notEqual(negative, vec3(0.0)))) imageStore(uNegative, texel, imageLoad(uNegative, texel) + vec4(negative, 0.0));
    imageStore(uTotal, texel, vec4(total.rgb + added, 0.0));
}
