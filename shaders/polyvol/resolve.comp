#version 450 core
// polyvol/resolve.comp: with the origin at the surface (volume.frag), adds c L(0, d) for one light, c =
// the light's signed crossing count in the total's alpha (0 or 1: whether the eye is lit), then zeroes
// that alpha for the next light.
layout(local_size_x = 8, local_size_y = 8) in;

#include "polyvol/segment.glsl"

layout(binding = kFirstFreeTextureUnit) uniform sampler2D uDistance;
layout(rgba32f, binding = 0) uniform image2D uTotal;
layout(rgba32f, binding = 1) uniform image2D uPositive;
layout(rgba32f, binding = 2) uniform image2D uNegative;

uniform int uLightIndex;
uniform int uConstant;

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, uSize))) return;
    vec4 total = imageLoad(uTotal, texel);
    float c = total.a;
    if (c != 0.0) {
        float d = texelFetch(uDistance, texel, 0).r;
        vec3 w = fragmentRay(vec2(texel) + 0.5);
        vec3 base = uConstant != 0 ? vec3(d) : segmentAirlight(gLights[uLightIndex], w, 0.0, d);
        total.rgb += c * base;
        if (c > 0.0) {
            imageStore(uPositive, texel, imageLoad(uPositive, texel) + vec4(c * base, 0.0));
        } else {
            imageStore(uNegative, texel, imageLoad(uNegative, texel) - vec4(c * base, 0.0));
        }
    }
    imageStore(uTotal, texel, vec4(total.rgb, 0.0));
}
