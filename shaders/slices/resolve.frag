#version 450 core
// slices/resolve.frag: accumulation target -> L_air (RGBA32F). Undoes the store scale; in channel-mask
// mode sums the four channels (each holds every fourth plane, Mitchell 2004 "Quality") and puts the
// light's colour back; BLUR applies the paper's small composite blur (3x3 tent: 1 2 1 / 16, clamp to edge).
layout(binding = 0) uniform sampler2D uAccum;

uniform float uInvStoreScale;
uniform vec3 uMaskColour;  // channel mask: colour / mean(colour) of the light(s)

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
    oAirlight = vec4(value * uInvStoreScale, 1.0);
}
