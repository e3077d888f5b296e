#version 450 core
// Final composite: final = surfaceRadiance * exp(-sigma_t * d) + L_air, per pixel (texel-exact: the
// target has the size of the inputs). Inputs: RGBA32F surface radiance, R32F distance d, airlight.
layout(binding = 0) uniform sampler2D uSurface;
layout(binding = 1) uniform sampler2D uDistance;
layout(binding = 2) uniform sampler2D uAirlight;
#include "common/medium.glsl"  // uSigmaS, uSigmaT, uG

layout(location = 0) out vec4 oFinal;

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    vec3 surface = texelFetch(uSurface, texel, 0).rgb;
    float d = texelFetch(uDistance, texel, 0).r;
    vec3 air = texelFetch(uAirlight, texel, 0).rgb;
    oFinal = vec4(surface * exp(-uSigmaT * d) + air, 1.0);
}
