// Evaluates shaders/common/airlight.glsl on a list of cases for tests/gl/airlight_glsl_test.cpp.
// Input: three vec4 per case (tP h x0 x1 | sigma_s sigma_t g I0 | cosTheta - - -), float, camera-relative.
// Output: one vec4 per case (pointSegment, directionalSegment, phaseHG, transmittance).
#version 450 core
layout(local_size_x = 64) in;

#include "common/airlight.glsl"

layout(std430, binding = 0) readonly buffer Inputs { vec4 inputs[]; };
layout(std430, binding = 1) writeonly buffer Outputs { vec4 outputs[]; };
uniform int uCount;

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= uCount) return;
    vec4 a = inputs[3 * i];
    vec4 b = inputs[3 * i + 1];
    vec4 c = inputs[3 * i + 2];
    float point = pointSegment(a.x, a.y, a.z, a.w, b.x, b.y, b.z, b.w);
    float directional = directionalSegment(c.x, a.z, a.w, b.x, b.y, b.z, b.w);
    float phase = phaseHG(c.x, b.z);
    float trans = transmittance(b.y, a.z + 1.0);
    outputs[i] = vec4(point, directional, phase, trans);
}
