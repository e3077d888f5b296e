// Evaluates shaders/vsv/bits128.glsl for tests/gl/vsv_test.cpp. Input: pairs of uvec4 columns and a
// vec4 of weights per case; output per case and bit k: (testBitPlain, testBitFast, countBits(0, k),
// litFractionFast * 1e6 rounded) as uvec4.
#version 450 core
layout(local_size_x = 128) in;

#include "vsv/bits128.glsl"

layout(std430, binding = 0) readonly buffer Columns { uvec4 columns[]; };
layout(std430, binding = 1) readonly buffer Weights { vec4 weights[]; };
layout(std430, binding = 2) writeonly buffer Outputs { uvec4 outputs[]; };
layout(std430, binding = 3) writeonly buffer Fractions { float fractions[]; };

void main() {
    int k = int(gl_LocalInvocationID.x);
    int c = int(gl_WorkGroupID.x);
    uvec4 a = columns[2 * c];
    uvec4 b = columns[2 * c + 1];
    vec4 w = weights[c];
    outputs[c * 128 + k] = uvec4(testBitPlain(a, k) ? 1u : 0u, testBitFast(a, k) ? 1u : 0u,
                                 uint(countBits(a, 0, k)), uint(countBits(a, k, 128)));
    fractions[c * 128 + k] = litFractionFast(a, b, k, w.x, w.y);
}
