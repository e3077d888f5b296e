// Evaluates cosineLobeSegment of shaders/common/airlight.glsl on a list of cases for
// tests/gl/airlight_glsl_test.cpp. Input: three vec4 per case (D x0 | w x1 | n -), one vec4 of medium
// (sigma_s sigma_t g I0), float, camera-relative. Output: one float per case.
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
    outputs[i] = cosineLobeSegment(a.xyz, b.xyz, c.xyz, a.w, b.w, m.x, m.y, m.z, m.w);
}
