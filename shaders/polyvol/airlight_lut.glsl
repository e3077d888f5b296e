// The airlight lookup table (viz/techniques/polyvol/airlight_lut.h for the channels and the algebra):
// unit-intensity point-light airlight of [x0, x1] from two premultiplied, log-mapped channels.
#ifndef POLYVOL_AIRLIGHT_LUT_GLSL
#define POLYVOL_AIRLIGHT_LUT_GLSL
#ifdef AIRLIGHT_LUT

layout(binding = kFirstFreeTextureUnit + 1) uniform sampler2D uAirlightLut;  // RG32F, linear, clamp

const float LUT_LOG_TAU_MIN = -11.512925465;  // ln 1e-5
const float LUT_LOG_TAU_MAX = 5.298317367;    // ln 200

float lutAxis(float tau) {
    return clamp((log(max(tau, 1.0e-5)) - LUT_LOG_TAU_MIN) / (LUT_LOG_TAU_MAX - LUT_LOG_TAU_MIN), 0.0, 1.0);
}

// Bilinear sample with the axis value v in [0, 1] mapped to the first .. last texel centre.
vec2 lutSample(float u, float tauH) {
    vec2 size = vec2(textureSize(uAirlightLut, 0));
    vec2 v = vec2(lutAxis(u), lutAxis(tauH));
    return texture(uAirlightLut, (v * (size - 1.0) + 0.5) / size).rg;
}

float lutPointSegment(float tP, float h, float x0, float x1, float sigma_s, float sigma_t, float g) {
    if (!(sigma_t > 0.0)) return pointSegment(tP, h, x0, x1, sigma_s, sigma_t, g, 1.0);
    if (!(x1 > x0) || !(sigma_s > 0.0)) return 0.0;
    float tauH = sigma_t * max(h, 1.0e-30);
    float s0 = x0 - tP;
    float s1 = x1 - tP;
    float sum = 0.0;
    if (s0 < 0.0) {
        // Before the foot point (tP > x0 >= 0 here): A(|s|) grows toward P.
        float a1 = lutSample(sigma_t * max(-s1, 0.0), tauH).r;
        float a0 = lutSample(-sigma_t * s0, tauH).r;
        sum += (a1 - a0) * exp(-sigma_t * tP);
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
