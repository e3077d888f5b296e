// Evaluates an area light's VPL cell (shaders/common/solid_angle.glsl, airlight.glsl's pointSegmentCell)
// on a list of cases for tests/gl/vpl_cell_test.cpp.
// Input: six vec4 per case, float, eye-relative (the eye at the origin):
//   (node D, x0) | (ray direction w, unit, x1) | (cell corner, sigma_s) | (edge U, sigma_t) | (edge V, g) |
//   (unit normal n, -)
// Output: one vec4 per case: (pointSegmentCell with I0 = the cell's area, i.e. L_e = 1; the cell's solid
// angle seen from the point x0 w; pointSegmentWithLobe of the same VPL as a point, I0 = area; -).
#version 450 core
layout(local_size_x = 64) in;

#include "common/airlight.glsl"

layout(std430, binding = 0) readonly buffer Inputs { vec4 inputs[]; };
layout(std430, binding = 1) writeonly buffer Outputs { vec4 outputs[]; };
uniform int uCount;

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= uCount) return;
    vec3 D = inputs[6 * i].xyz;
    float x0 = inputs[6 * i].w;
    vec3 w = inputs[6 * i + 1].xyz;
    float x1 = inputs[6 * i + 1].w;
    vec3 corner = inputs[6 * i + 2].xyz;
    float sigmaS = inputs[6 * i + 2].w;
    vec3 eU = inputs[6 * i + 3].xyz;
    float sigmaT = inputs[6 * i + 3].w;
    vec3 eV = inputs[6 * i + 4].xyz;
    float g = inputs[6 * i + 4].w;
    vec3 n = inputs[6 * i + 5].xyz;
    float area = length(cross(eU, eV));

    RayLightGeometry geo = rayLightGeometry(D, w);
    vec4 lobe = cosineLobeOf(D, w, n);
    AirlightCell cell = airlightCellOf(corner, eU, eV, n, area, w, geo.tP);
    float segment = pointSegmentCell(geo.tP, geo.h, x0, x1, sigmaS, sigmaT, g, area, lobe, cell);
    float omega = parallelogramSolidAngle(corner - x0 * w, eU, eV, n, area);
    float point = pointSegmentWithLobe(geo.tP, geo.h, x0, x1, sigmaS, sigmaT, g, area, lobe);
    outputs[i] = vec4(segment, omega, point, 0.0);
}
