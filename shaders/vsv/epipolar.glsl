// Epipolar coordinates of a voxelized shadow volume, GLSL mirror of viz/techniques/vsv/epipolar.h
// (see there for the definitions of alpha, theta, phi and the law-of-sines relations). Eye-relative
// world space: the eye at the origin, the light at s.D * s.b.
#ifndef VSV_EPIPOLAR_GLSL
#define VSV_EPIPOLAR_GLSL

#include "common/constants.glsl"

struct EpiSpace {
    vec3 b;          // baseline direction eye -> light
    vec3 u;          // theta = 0 direction, perpendicular to b
    vec3 v;          // cross(b, u)
    float D;         // eye-light distance; 0 for a directional light (phi then holds the offset y of a
                     // light line from the eye's line: y = t sin(alpha) along an eye ray)
    ivec3 cells;     // (nAlpha, nTheta, nPhi)
    vec2 alpha;      // (alpha0, dAlpha)
    vec3 theta;      // (thetaCentre, thetaHalf, dTheta)
    vec2 phi;        // (phi0, dPhi)
    bool thetaFull;  // theta covers the circle: neighbours wrap
};

float epiWrapAngle(float a) { return a - 2.0 * kPi * floor((a + kPi) / (2.0 * kPi)); }

float epiAlphaOf(EpiSpace s, vec3 w) { return atan(length(cross(w, s.b)), dot(w, s.b)); }
float epiThetaOf(EpiSpace s, vec3 w) { return atan(dot(w, s.v), dot(w, s.u)); }
vec3 epiLightRay(EpiSpace s, float theta, float phi) {
    return -cos(phi) * s.b + sin(phi) * (cos(theta) * s.u + sin(theta) * s.v);
}
float epiPhiOnEyeRay(EpiSpace s, float alpha, float t) {
    if (s.D <= 0.0) return t * sin(alpha);
    return atan(t * sin(alpha), s.D - t * cos(alpha));
}
float epiAlphaOnLightRay(EpiSpace s, float phi, float r) { return atan(r * sin(phi), s.D - r * cos(phi)); }
// t at which the eye ray alpha reaches phi; a huge value when it never does (alpha + phi >= pi).
float epiTOnEyeRay(EpiSpace s, float alpha, float phi) {
    if (s.D <= 0.0) return sin(alpha) > 0.0 ? phi / sin(alpha) : 3.0e38;
    float sn = sin(alpha + phi);
    if (alpha + phi >= kPi || sn <= 0.0) return 3.0e38;
    return s.D * sin(phi) / sn;
}
float epiAlphaCoord(EpiSpace s, float alpha) { return (alpha - s.alpha.x) / s.alpha.y; }
float epiThetaCoord(EpiSpace s, float theta) { return (epiWrapAngle(theta - s.theta.x) + s.theta.y) / s.theta.z; }
float epiThetaAtCell(EpiSpace s, float coord) { return s.theta.x - s.theta.y + coord * s.theta.z; }

// The two theta cells an eye ray reads and the weight of the second (INTERP), or the nearest cell.
void epiThetaCells(EpiSpace s, float theta, bool interp, out int j0, out int j1, out float wTheta) {
    float ct = epiThetaCoord(s, theta) - 0.5;
    j0 = interp ? int(floor(ct)) : int(floor(ct + 0.5));
    wTheta = interp ? ct - float(j0) : 0.0;
    j1 = j0 + 1;
    if (s.thetaFull) {
        j0 = (j0 + s.cells.y) % s.cells.y;
        j1 = (j1 + s.cells.y) % s.cells.y;
    } else {
        j0 = clamp(j0, 0, s.cells.y - 1);
        j1 = clamp(j1, 0, s.cells.y - 1);
    }
}

#endif  // VSV_EPIPOLAR_GLSL
