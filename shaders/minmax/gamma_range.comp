#version 450 core
// minmax/gamma_range.comp: the gamma range of each slice of a point light. A point light shines in every
// direction, so the rectified map is not cut to a cone: row i only needs the light rays its pixels' camera
// rays cross, gamma in [0, gamma(beta, d)] (gamma grows from 0 at the eye to its largest value at the
// ray's end d; t = 0 is the eye, so every range starts at 0). Each pixel takes the same slice and gamma as
// traverse.comp (same functions, same float operations) and raises its row's maximum with atomicMax on the
// float's bits (non-negative floats order like their bit patterns). Rays on the epipolar axis have no
// slice and are marched; they are left out.
layout(local_size_x = 8, local_size_y = 8) in;

#include "common/host_device.glsl"
#include "minmax/epipolar.glsl"
#include "minmax/camera_ray.glsl"

layout(binding = kFirstFreeTextureUnit) uniform sampler2D uDistance;  // Euclidean t of the first surface

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, uSize))) return;
    vec3 w = pixelRay(texel);
    if (onEpipolarAxis(w, uAxis)) return;
    float d = texelFetch(uDistance, texel, 0).r;
    float gamma = gammaAlongRay(betaOf(w), d);
    if (!(gamma > 0.0)) return;
    atomicMax(gRowGammaHi[sliceRow(alphaOf(w))], floatBitsToUint(gamma));
}
