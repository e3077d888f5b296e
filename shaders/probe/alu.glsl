// The throughput probe's arithmetic (gl/throughput_probe.h), one copy for its compute and fragment passes:
// uIterations steps of x = x a + b on four independent vec4 chains (16 fused multiply-adds a step, four
// chains so that a step does not wait on the one before). a and b are uniforms, so no compiler can fold
// the loop; the probe sets a = 1 and b = 1/1024, which keeps every value a multiple of 1/1024 below 2^14 and
// so exact in fp32: the result is a closed form the tests check on every pixel.
#ifndef PROBE_ALU_GLSL
#define PROBE_ALU_GLSL

uniform int uIterations;
uniform float uA;
uniform float uB;

// The chains' start: the pixel's column, row and their sum modulo 1024, over 1024.
vec4 probeStart(ivec2 pixel) {
    return vec4(float(pixel.x & 1023), float(pixel.y & 1023), float((pixel.x + pixel.y) & 1023), 0.0) / 1024.0;
}

vec4 probeAlu(ivec2 pixel) {
    vec4 s = probeStart(pixel);
    vec4 c0 = s, c1 = s + 0.25, c2 = s + 0.5, c3 = s + 0.75;
    vec4 a = vec4(uA), b = vec4(uB);
    for (int i = 0; i < uIterations; ++i) {
        c0 = fma(c0, a, b);
        c1 = fma(c1, a, b);
        c2 = fma(c2, a, b);
        c3 = fma(c3, a, b);
    }
    return c0 + c1 + c2 + c3;
}

#endif  // PROBE_ALU_GLSL
