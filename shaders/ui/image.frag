#version 450 core
// Displays one image of a technique: linear HDR colour through exposure and sRGB encoding, or a data
// intermediate mapped from the range [uRange.x, uRange.y] (linear or log10) to grey or a colour map.
// Texels are fetched without filtering, so the internal resolution is upscaled nearest-neighbour.
// NaN shows magenta, +-Inf cyan, and (when asked) negative values green, so that each stands out on
// every colour map. Values the intermediate declares as sentinels ("nothing here": -1 outside a spot's
// cone, say) show as grey diagonal stripes and are never marked negative. Integer and depth textures
// arrive here converted to float.
layout(binding = 0) uniform sampler2D uImage;

// Display modes, mirrored by DisplayMode in app/pane_image.h.
const int kHdrColour = 0;    // c * 2^exposure, clamp, sRGB
const int kRangeColour = 1;  // (c - min) / (max - min) * 2^exposure, clamp, sRGB
const int kGrey = 2;        // (r - min) / (max - min) as grey
const int kSigned = 3;      // r / max(|min|, |max|): blue < 0, white at 0, red > 0
const int kFalse = 4;       // (r - min) / (max - min) through a blue-green-yellow-red ramp
const int kBits = 5;        // each distinct integer value a different colour, 0 black
const int kMask = 6;        // r above the middle of the range: white, else black
const int kCategorical = 7; // floor(r) through a fixed palette of 10 distinct colours (levels, classes)
const int kHeat = 8;        // (r - min) / (max - min): black, purple, orange, pale yellow (error heat maps)

// Channels, mirrored by Channel in app/view_stats.h: 0 RGB, 1-4 R G B A alone, 5 luminance (Rec. 709).
uniform int uChannel;
uniform int uMode;
uniform vec2 uRange;      // linear range, or (with uLog) the log10 of a positive range
uniform bool uLog;        // map log10(value) instead of value (colour and sequential modes); signed: symmetric log
uniform bool uMarkNegative;
uniform float uExposure;  // in stops
uniform bool uFlipY;      // GL-rendered textures keep row 0 at the bottom
uniform int uChannels;    // meaningful channels; a single channel shows as grey in the colour modes
uniform vec4 uView;       // pan and zoom (ui/image_view.h): image uv = uView.xy + (pane - 0.5) / uView.z
uniform float uTexelPixels;  // screen pixels per texel: a grid is drawn between texels above 8
uniform vec4 uSentinels;     // the pane's sentinel values (PaneImage::sentinels), the first uSentinelCount
uniform int uSentinelCount;

in vec2 vPane;
out vec4 fragColour;

vec3 srgbEncode(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

// Piecewise-linear ramp through dark blue, cyan, green, yellow, red; t in [0,1].
vec3 falseColour(float t) {
    const vec3 stops[5] = vec3[5](vec3(0.05, 0.05, 0.35), vec3(0.0, 0.6, 0.9), vec3(0.1, 0.8, 0.2),
                                  vec3(0.95, 0.9, 0.1), vec3(0.85, 0.1, 0.05));
    float x = clamp(t, 0.0, 1.0) * 4.0;
    int i = min(int(x), 3);
    return mix(stops[i], stops[i + 1], x - float(i));
}

// The report's error ramp (viz/report/error_images.cpp), display values; t in [0,1].
vec3 heatColour(float t) {
    const vec3 stops[5] = vec3[5](vec3(0.0), vec3(0.34, 0.06, 0.42), vec3(0.73, 0.21, 0.33),
                                  vec3(0.98, 0.55, 0.04), vec3(0.99, 0.98, 0.55));
    float x = clamp(t, 0.0, 1.0) * 4.0;
    int i = min(int(x), 3);
    return mix(stops[i], stops[i + 1], x - float(i));
}

vec3 categoricalColour(int k) {
    const vec3 palette[10] = vec3[10](vec3(0.12, 0.47, 0.71), vec3(1.0, 0.50, 0.05), vec3(0.17, 0.63, 0.17),
                                      vec3(0.84, 0.15, 0.16), vec3(0.58, 0.40, 0.74), vec3(0.55, 0.34, 0.29),
                                      vec3(0.89, 0.47, 0.76), vec3(0.50, 0.50, 0.50), vec3(0.74, 0.74, 0.13),
                                      vec3(0.09, 0.75, 0.81));
    return palette[((k % 10) + 10) % 10];
}

// Integer hash to a saturated colour, so neighbouring bit patterns look different.
vec3 hashColour(uint v) {
    v ^= v >> 16; v *= 0x7feb352du; v ^= v >> 15; v *= 0x846ca68bu; v ^= v >> 16;
    return vec3(float(v & 255u), float((v >> 8) & 255u), float((v >> 16) & 255u)) / 255.0 * 0.8 + 0.2;
}

bool anyOf(bvec4 a, bvec4 mask) { return any(bvec4(uvec4(a) & uvec4(mask))); }

bool isSentinel(float x) {
    for (int k = 0; k < uSentinelCount; ++k)
        if (x == uSentinels[k]) return true;
    return false;
}

// The sentinel hatch: grey diagonal stripes 3 pixels wide, fixed to the screen.
vec3 sentinelHatch() {
    return mod(floor((gl_FragCoord.x + gl_FragCoord.y) / 3.0), 2.0) < 1.0 ? vec3(0.36, 0.35, 0.40) : vec3(0.17, 0.16, 0.20);
}

// Position of x in the range, unclamped (mirrors mapToUnit in app/view_stats.cpp).
float unit(float x) {
    float span = max(uRange.y - uRange.x, 1e-30);
    float v = uLog ? log(max(x, 1e-30)) / log(10.0) : x;
    return (v - uRange.x) / span;
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
            fragColour = vec4(0.18, 0.18, 0.2, 1.0);
            return;
        }
    }
    vec4 v = texelFetch(uImage, texel, 0);
    // Only the meaningful channels count (a one-channel texture reads back g = b = 0, a = 1).
    bvec4 meaningful = bvec4(true, uChannels > 1, uChannels > 2, uChannels > 3);
    if (anyOf(isnan(v), meaningful)) {
        fragColour = vec4(1.0, 0.0, 1.0, 1.0);
        return;
    }
    if (anyOf(isinf(v), meaningful)) {
        fragColour = vec4(0.0, 1.0, 1.0, 1.0);
        return;
    }
    bvec4 sentinel = bvec4(isSentinel(v.r), isSentinel(v.g), isSentinel(v.b), isSentinel(v.a));
    if (uMarkNegative && anyOf(bvec4(uvec4(lessThan(v, vec4(0.0))) & uvec4(not(sentinel))), meaningful)) {
        fragColour = vec4(0.3, 1.0, 0.2, 1.0);
        return;
    }
    if (uChannels == 1) v.rgb = v.rrr;
    if (uChannel >= 1 && uChannel <= 4) {
        v.rgb = vec3(v[uChannel - 1]);
    } else if (uChannel == 5) {
        v.rgb = vec3(dot(v.rgb, vec3(0.2126, 0.7152, 0.0722)));
    }
    if (uMode != kHdrColour && isSentinel(v.r)) {
        fragColour = vec4(sentinelHatch(), 1.0);
        return;
    }
    uvec4 raw = uvec4(max(v, 0.0));
    float t = unit(v.r);
    vec3 c;
    if (uMode == kHdrColour) {
        c = srgbEncode(v.rgb * exp2(uExposure));
    } else if (uMode == kRangeColour) {
        c = srgbEncode(vec3(unit(v.r), unit(v.g), unit(v.b)) * exp2(uExposure));
    } else if (uMode == kGrey) {
        c = vec3(clamp(t, 0.0, 1.0));
    } else if (uMode == kSigned) {
        // Mirrors signedUnit in app/view_stats.cpp (the log scale is a symmetric log over four decades).
        float s = v.r / max(max(abs(uRange.x), abs(uRange.y)), 1e-30);
        if (uLog) s = sign(s) * log(1.0 + abs(s) * 1e4) / log(1.0 + 1e4);
        s = clamp(s, -1.0, 1.0);
        c = s < 0.0 ? mix(vec3(1.0), vec3(0.1, 0.3, 0.9), -s) : mix(vec3(1.0), vec3(0.9, 0.15, 0.1), s);
    } else if (uMode == kFalse) {
        c = falseColour(t);
    } else if (uMode == kBits) {
        c = raw.r == 0u ? vec3(0.0) : hashColour(raw.r);
    } else if (uMode == kCategorical) {
        c = categoricalColour(int(floor(v.r)));
    } else if (uMode == kHeat) {
        c = heatColour(t);
    } else {
        c = vec3(t > 0.5 ? 1.0 : 0.0);
    }
    fragColour = vec4(c, 1.0);
}
