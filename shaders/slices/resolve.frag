#version 450 core
// slices/resolve.frag: accumulation target -> L_air (RGBA32F). Undoes the store scale; in channel-mask
// mode sums the four channels (each holds every fourth plane, Mitchell 2004 "Quality") and puts the
// light's colour back; BLUR applies the paper's small composite blur (3x3 tent: 1 2 1 / 16, clamp to edge).
// FAR_TAIL (a far camera: the shared planes end at the scene's far side, uPlanesEnd, scene/ray_reach.h):
// each pixel whose ray goes on past it adds that part of the ray for the unbounded lights (point, VPL,
// directional unless boxed), kTailSamples samples per light placed by the light (common/march_samples.glsl)
// with the shadow-map test; spots are bounded by their frustum's planes.
layout(binding = 0) uniform sampler2D uAccum;

uniform float uInvStoreScale;
uniform vec3 uMaskColour;  // channel mask: colour / mean(colour) of the light(s)

#ifdef FAR_TAIL
#define FAR_RAYS
#include "common/host_device.glsl"
#include "common/airlight.glsl"
#include "common/lights.glsl"
#include "common/shadow_map.glsl"
#include "common/camera_ray.glsl"
#include "common/medium.glsl"
#include "common/airlight_sample.glsl"
#include "common/march_samples.glsl"
layout(binding = kFirstFreeTextureUnit) uniform sampler2D uDistance;  // Euclidean d per pixel
uniform float uPlanesEnd;      // view depth where the unbounded planes end
uniform int uLightCount;
uniform int uBoxedDirectional;  // 1: directional lights have planes of their own, bounded by their box
const int kTailSamples = 8;

vec3 farTail(ivec2 texel) {
    vec3 w = pixelRay(texel);
    float d = texelFetch(uDistance, texel, 0).r;
    vec2 span = vec2(uPlanesEnd / dot(w, uForward), reachAlongRay(d, uSigmaT));
    vec3 sum = vec3(0.0);
    for (int li = 0; li < uLightCount; ++li) {
        GpuLight L = gLights[li];
        if (L.info.x == kLightSpot || (uBoxedDirectional != 0 && L.info.x == kLightDirectional)) continue;
        sum += tailByTheLight(L, w, span, kTailSamples);
    }
    return sum;
}
#endif

layout(location = 0) out vec4 oAirlight;

vec3 decode(ivec2 texel) {
    ivec2 size = textureSize(uAccum, 0);
    vec4 a = texelFetch(uAccum, clamp(texel, ivec2(0), size - 1), 0);
#ifdef CHANNEL_MASK
    return (a.r + a.g + a.b + a.a) * uMaskColour;
#else
    return a.rgb;
#endif
}

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
#ifdef BLUR
    vec3 sum = vec3(0.0);
    for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) {
            float w = float((2 - abs(i)) * (2 - abs(j)));
            sum += w * decode(texel + ivec2(i, j));
        }
    vec3 value = sum / 16.0;
#else
    vec3 value = decode(texel);
#endif
    vec3 airlight = value * uInvStoreScale;
#ifdef FAR_TAIL
    airlight += farTail(texel);
#endif
    oAirlight = vec4(airlight, 1.0);
}
