// Solid angles of flat emitters: an area light's VPL stands for its cell of the emitter (lights.glsl,
// vplHasCell), whose solid angle the air and the surfaces see, pointwise and inside the segment
// integral (airlight.glsl, pointSegmentCell).
#ifndef SOLID_ANGLE_GLSL
#define SOLID_ANGLE_GLSL

#include "common/constants.glsl"

// Solid angle of the parallelogram with corner c (relative to the viewpoint), edges eU, eV and unit
// normal n toward its lit side, seen from the origin; 0 from behind or in its plane. Two triangles
// (c, c + eU, c + eU + eV) and (c, c + eU + eV, c + eV), each 2 atan(|triple| / denominator) (Van
// Oosterom and Strackee 1983); their triple products are both c . (eU x eV), taken as |c . n| area
// rather than from the long vectors, so that a far cell keeps its precision.
const float PARALLELOGRAM_PLANE_TOLERANCE = 1.0e-6;

// atan2(y, x) for y >= 0, to a few float ulps: a GPU's atan is accurate to about 1e-6 absolute only
// (llvmpipe: 1e-5 relative at a solid angle of 0.5, 2e-5 at 0.015 and worse further away, where a far
// cell's triangles are thin). Reduced to [0, 1] by atan(q) = pi/2 - atan(1/q), halved twice by
// atan(q) = 2 atan(q / (1 + sqrt(1 + q^2))) to q <= tan(pi/16), then its series to q^11 (error below
// 1e-10).
float triangleAtan(float y, float x) {
    if (!(x != 0.0)) return 0.5 * kPi;
    float q = y / abs(x);
    bool inverted = q > 1.0;
    if (inverted) q = 1.0 / q;
    q = q / (1.0 + sqrt(1.0 + q * q));
    q = q / (1.0 + sqrt(1.0 + q * q));
    float q2 = q * q;
    float a = 4.0 * q * (1.0 - q2 * (1.0 / 3.0 - q2 * (1.0 / 5.0 - q2 * (1.0 / 7.0 - q2 * (1.0 / 9.0 - q2 * (1.0 / 11.0))))));
    if (inverted) a = 0.5 * kPi - a;
    return x > 0.0 ? a : kPi - a;
}

float parallelogramSolidAngle(vec3 c, vec3 eU, vec3 eV, vec3 n, float area) {
    float height = -dot(c, n);  // the viewpoint's height above the plane
    float lc = length(c);
    // In the plane (to PARALLELOGRAM_PLANE_TOLERANCE of the distances at hand) the answer jumps between 0
    // and 2 pi with the rounding of the viewpoint: a surface in the emitter's own plane (the emitter
    // itself) is lit by none of it.
    if (!(height > PARALLELOGRAM_PLANE_TOLERANCE * (lc + sqrt(area)))) return 0.0;
    float triple = height * area;
    vec3 b = c + eU, d = c + eV;
    vec3 e = b + eV;
    float lb = length(b), le = length(e), ld = length(d);
    float first = triangleAtan(triple, lc * lb * le + dot(c, b) * le + dot(c, e) * lb + dot(b, e) * lc);
    float second = triangleAtan(triple, lc * le * ld + dot(c, e) * ld + dot(c, d) * le + dot(e, d) * lc);
    return 2.0 * (first + second);
}

// A cell's angular factor at the viewpoint (c its corner from there, n its emitting side, r2 the squared
// distance to the VPL that stands for it, as the caller has it): Omega_cell r^2 / dA, in place of a point
// light's cos(theta_e), so that the point's L_e dA / r^2 gives L_e Omega_cell.
float cellAngularFactor(vec3 c, vec3 eU, vec3 eV, vec3 n, float area, float r2) {
    return parallelogramSolidAngle(c, eU, eV, n, area) * (r2 / area);
}

#endif  // SOLID_ANGLE_GLSL
