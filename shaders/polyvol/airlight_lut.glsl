// The airlight lookup table (viz/techniques/polyvol/airlight_lut.h for the channels, the axes and the
// algebra): unit-intensity point-light airlight of [x0, x1] from three premultiplied channels.
#ifndef POLYVOL_AIRLIGHT_LUT_GLSL
#define POLYVOL_AIRLIGHT_LUT_GLSL
#ifdef AIRLIGHT_LUT

layout(binding = kFirstFreeTextureUnit + 1) uniform sampler2D uAirlightLut;  // RGB32F, read with texelFetch

// AirlightLut::kTauMin, kTauMax, log of both, and columnSpan() = asinh(kTauMax / s(kTauMin)).
const float LUT_TAU_MIN = 1.0e-9;
const float LUT_TAU_MAX = 200.0;
const float LUT_LOG_TAU_MIN = -20.723265837;
const float LUT_LOG_TAU_MAX = 5.298317367;
const float LUT_COLUMN_SPAN = 26.714730385;

// Column coordinate in [0, 1] of |u| in the row of tauH: asinh(|u| / s) / span, s = tauH / (1 + tauH);
// 0 is the foot point.
float lutColumn(float u, float tauH) {
    float s = tauH / (1.0 + tauH);
    return clamp(stableAsinh(min(abs(u), LUT_TAU_MAX) / s) / LUT_COLUMN_SPAN, 0.0, 1.0);
}

float lutRow(float tauH) {
    return clamp((log(tauH) - LUT_LOG_TAU_MIN) / (LUT_LOG_TAU_MAX - LUT_LOG_TAU_MIN), 0.0, 1.0);
}

// Bilinear sample between the four nearest texels, weights in float (hardware filtering keeps only 8
// fractional bits on many GPUs: docs/numerics.md#lookup-tables), with the first and last texels on the
// axis ends.
vec3 lutSample(float u, float tauH) {
    ivec2 size = textureSize(uAirlightLut, 0);
    vec2 f = vec2(lutColumn(u, tauH), lutRow(tauH)) * vec2(size - 1);
    ivec2 i0 = min(ivec2(f), size - 2);
    vec2 t = f - vec2(i0);
    vec3 a = texelFetch(uAirlightLut, i0, 0).rgb;
    vec3 b = texelFetch(uAirlightLut, i0 + ivec2(1, 0), 0).rgb;
    vec3 c = texelFetch(uAirlightLut, i0 + ivec2(0, 1), 0).rgb;
    vec3 d = texelFetch(uAirlightLut, i0 + ivec2(1, 1), 0).rgb;
    return mix(mix(a, b, t.x), mix(c, d, t.x), t.y);
}

// rho - |u| = tau_h^2 / (rho + |u|), without the cancellation: the decay factored out of channel C
// (AirlightLut::nearSideDecay).
float lutNearSideDecay(float u, float tauH) { return tauH * tauH / (sqrt(u * u + tauH * tauH) + u); }

float lutPointSegment(float tP, float h, float x0, float x1, float sigma_s, float sigma_t, float g) {
    if (!(x1 > x0) || !(sigma_s > 0.0)) return 0.0;
    float tauH = sigma_t * h;
    // Below the table's rows (sigma_t = 0, or a ray within 1e-9 optical units of the light): the closed
    // form. The rows could be extended, but the columns would have to cover |u| / tau_h up to
    // kTauMax / tau_h, and such rays are rare.
    if (!(tauH >= LUT_TAU_MIN)) return pointSegment(tP, h, x0, x1, sigma_s, sigma_t, g, 1.0);
    float s0 = x0 - tP;
    float s1 = x1 - tP;
    float sum = 0.0;
    if (s0 < 0.0) {
        // Before the foot point (tP > x0 >= 0 here): A(|u|) grows toward P, C(|u|) e^{-(rho - |u|)} away
        // from it. The same integral as A(near) - A(far) or C(far) - C(near): the form whose larger term
        // is smaller.
        float uNear = sigma_t * max(-s1, 0.0), uFar = -sigma_t * s0;
        vec3 nearP = lutSample(uNear, tauH);
        vec3 farP = lutSample(uFar, tauH);
        float decayFar = lutNearSideDecay(uFar, tauH);
        if (nearP.r <= exp(-decayFar) * farP.b)
            sum += (nearP.r - farP.r) * exp(-sigma_t * tP);
        else
            sum += exp(-sigma_t * tP - decayFar) * farP.b -
                   exp(-sigma_t * tP - lutNearSideDecay(uNear, tauH)) * nearP.b;
    }
    if (s1 > 0.0) {
        float sb = max(s0, 0.0);
        float ub = sigma_t * sb, u1 = sigma_t * s1;
        float rhoB = sqrt(ub * ub + tauH * tauH), rho1 = sqrt(u1 * u1 + tauH * tauH);
        sum += exp(-sigma_t * (tP + sb) - rhoB) * lutSample(ub, tauH).g -
               exp(-sigma_t * x1 - rho1) * lutSample(u1, tauH).g;
    }
    return sigma_s * sigma_t / tauH * sum;
}

#endif  // AIRLIGHT_LUT
#endif  // POLYVOL_AIRLIGHT_LUT_GLSL
