#version 450 core
// slices/depth.frag: the depth buffer the planes are tested against (depth_test=1), from the distance d of
// each pixel's first surface along its centre ray (the sky: zfar), as view depth d dot(w, forward) through
// slices/plane_depth.glsl. Drawn over the whole target with the depth test set to always pass.
#include "common/host_device.glsl"
#include "slices/plane_depth.glsl"

layout(binding = kFirstFreeTextureUnit) uniform sampler2D uDistance;  // as plane.frag binds it
uniform vec3 uForward;
uniform vec3 uRight;
uniform vec3 uUp;
uniform vec2 uSize;
uniform float uTanHalf;
uniform float uAspect;

void main() {
    // The pixel's centre ray as plane.frag forms it.
    vec2 ndc = 2.0 * gl_FragCoord.xy / uSize - 1.0;
    vec3 w = normalize(uForward + (ndc.x * uTanHalf * uAspect) * uRight + (ndc.y * uTanHalf) * uUp);
    float d = texelFetch(uDistance, ivec2(gl_FragCoord.xy), 0).r;
    gl_FragDepth = 0.5 * ndcDepthAtView(d * dot(w, uForward)) + 0.5;
}
