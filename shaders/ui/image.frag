#version 450 core
// Displays one image of a technique: linear HDR colour through exposure and sRGB encoding, or a data
// intermediate mapped from its suggested range [uRange.x, uRange.y] to grey or false colour.
// Texels are fetched without filtering, so the internal resolution is upscaled nearest-neighbour.
// NaN and Inf show as magenta. Integer and depth textures arrive here converted to float.
layout(binding = 0) uniform sampler2D uImage;

// Display modes, mirrored by DisplayMode in app/gui.cpp.
const int kHdrColor = 0;   // c * 2^exposure, clamp, sRGB
const int kRangeColor = 1; // (c - min) / (max - min) * 2^exposure, clamp, sRGB
const int kGrey = 2;       // (r - min) / (max - min) as grey
const int kSigned = 3;     // r / max(|min|, |max|): blue < 0, white at 0, red > 0
const int kFalse = 4;      // (r - min) / (max - min) through a blue-green-yellow-red ramp
const int kBits = 5;       // each distinct integer value a different colour, 0 black
const int kMask = 6;       // r above the middle of the range: white, else black

uniform int uMode;
uniform vec2 uRange;
uniform float uExposure;  // in stops
uniform bool uFlipY;      // GL-rendered textures keep row 0 at the bottom
uniform int uChannels;    // meaningful channels; a single channel shows as grey in the colour modes
uniform vec4 uView;       // pan and zoom (ui/image_view.h): image uv = uView.xy + (pane - 0.5) / uView.z
uniform float uTexelPixels;  // screen pixels per texel: a grid is drawn between texels above 8

in vec2 vPane;
out vec4 fragColor;

vec3 srgbEncode(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

// Piecewise-linear ramp through dark blue, cyan, green, yellow, red; t in [0,1].
vec3 falseColor(float t) {
    const vec3 stops[5] = vec3[5](vec3(0.05, 0.05, 0.35), vec3(0.0, 0.6, 0.9), vec3(0.1, 0.8, 0.2),
                                  vec3(0.95, 0.9, 0.1), vec3(0.85, 0.1, 0.05));
    float x = clamp(t, 0.0, 1.0) * 4.0;
    int i = min(int(x), 3);
    return mix(stops[i], stops[i + 1], x - float(i));
}

// Integer hash to a saturated colour, so neighbouring bit patterns look different.
vec3 hashColor(uint v) {
    v ^= v >> 16; v *= 0x7feb352du; v ^= v >> 15; v *= 0x846ca68bu; v ^= v >> 16;
    return vec3(float(v & 255u), float((v >> 8) & 255u), float((v >> 16) & 255u)) / 255.0 * 0.8 + 0.2;
}

void main() {
    ivec2 size = textureSize(uImage, 0);
    vec2 view = uView.xy + (vPane - 0.5) / uView.z;  // image uv, row 0 at the top
    vec2 uv = vec2(view.x, uFlipY ? 1.0 - view.y : view.y);
    ivec2 texel = clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1);
    // Zoomed in far enough to tell texels apart: a thin dark line along each texel's edges.
    if (uTexelPixels >= 8.0) {
        vec2 f = fract(view * vec2(size));
        float edge = 1.0 / uTexelPixels;
        if (f.x < edge || f.y < edge) {
            fragColor = vec4(0.18, 0.18, 0.2, 1.0);
            return;
        }
    }
    vec4 v = texelFetch(uImage, texel, 0);
    if (any(isnan(v)) || any(isinf(v))) {
        fragColor = vec4(1.0, 0.0, 1.0, 1.0);
        return;
    }
    uvec4 raw = uvec4(max(v, 0.0));
    if (uChannels == 1) v.rgb = v.rrr;
    float span = max(uRange.y - uRange.x, 1e-30);
    float t = (v.r - uRange.x) / span;
    vec3 c;
    if (uMode == kHdrColor) {
        c = srgbEncode(v.rgb * exp2(uExposure));
    } else if (uMode == kRangeColor) {
        c = srgbEncode((v.rgb - uRange.x) / span * exp2(uExposure));
    } else if (uMode == kGrey) {
        c = vec3(clamp(t, 0.0, 1.0));
    } else if (uMode == kSigned) {
        float s = clamp(v.r / max(max(abs(uRange.x), abs(uRange.y)), 1e-30), -1.0, 1.0);
        c = s < 0.0 ? mix(vec3(1.0), vec3(0.1, 0.3, 0.9), -s) : mix(vec3(1.0), vec3(0.9, 0.15, 0.1), s);
    } else if (uMode == kFalse) {
        c = falseColor(t);
    } else if (uMode == kBits) {
        c = raw.r == 0u ? vec3(0.0) : hashColor(raw.r);
    } else {
        c = vec3(t > 0.5 ? 1.0 : 0.0);
    }
    fragColor = vec4(c, 1.0);
}
