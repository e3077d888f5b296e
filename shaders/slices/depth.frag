#version 450 core
// slices/depth.frag: the depth buffer the planes are tested against (depth_test=1), from the distance d of
// each pixel's first surface along its centre ray (the sky: zfar), as view depth d dot(w, forward) through
// slices/plane_depth.glsl. Drawn over the whole target with the depth test set to always pass.
#include "common/host_device.glsl"
#include "slices/plane_depth.glsl"

#include "slices/pixel_ray.glsl"

layout(binding = kFirstFreeTextureUnit) uniform sampler2D uDistance;  // as plane.frag binds it

void main() {
    vec3 w = pixelRay(gl_FragCoord.xy);  // the ray plane.frag tests d along
    float d = texelFetch(uDistance, ivec2(gl_FragCoord.xy), 0).r;
    gl_FragDepth = 0.5 * ndcDepthAtView(d * dot(w, uForward)) + 0.5;
}
