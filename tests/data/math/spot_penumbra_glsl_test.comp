// Evaluates spotPenumbraSegment of shaders/common/airlight.glsl on a list of cases for
// tests/gl/airlight_glsl_test.cpp. Input: four vec4 per case (D x0 | w x1 | axis scale | offset sigma_s
// sigma_t g), float, camera-relative, I0 = 1. Output: one float per case.
#version 450 core
layout(local_size_x = 64) in;

#include "common/airlight.glsl"

layout(std430, binding = 0) readonly buffer Inputs { vec4 inputs[]; };
layout(std430, binding = 1) writeonly buffer Outputs { float outputs[]; };
uniform int uCount;

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= uCount) return;
    vec4 a = inputs[4 * i];
    vec4 b = inputs[4 * i + 1];
    vec4 c = inputs[4 * i + 2];
    vec4 m = inputs[4 * i + 3];
    outputs[i] = spotPenumbraSegment(a.xyz, b.xyz, c.xyz, c.w, m.x, a.w, b.w, m.y, m.z, m.w, 1.0);
}
