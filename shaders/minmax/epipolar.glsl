// Epipolar coordinates (Chen et al. 2011, section 3.2), eye-relative world space: the float mirror of
// viz/techniques/minmax/epipolar.h (same names and steps; see there for the definitions of alpha, beta,
// gamma and the rectified map S). The frame comes from uniforms set by the technique.
#ifndef MINMAX_EPIPOLAR_GLSL
#define MINMAX_EPIPOLAR_GLSL

const int kKindSpot = 0;
const int kKindDirectional = 1;
const int kKindPoint = 2;  // the spot's formulas; per-row gamma ranges (EPIPOLAR_POINT below)
const float kUnblocked = 4.0;     // S of a light ray nothing blocks: above every beta
const float kOutsideCone = -1.0;  // S outside a spot's cone: below every beta
const float kInfinity = 1.0 / 0.0;

uniform int uKind;
uniform vec3 uAxis;  // a: toward the light
uniform vec3 uU;
uniform vec3 uV;
uniform float uLightDistance;  // D (spot)
uniform int uSlices;
uniform int uColumns;
uniform bool uWrap;
uniform float uAlphaLo;
uniform float uAlphaSpacing;
uniform float uGammaLo;
uniform float uGammaHi;

#ifdef EPIPOLAR_POINT
// A point light shines in every direction, so its rows are not cut to a cone: row i covers
// gamma in [0, gRowGammaHi[i]], the largest gamma its pixels' rays reach at their distance d (written by
// minmax/gamma_range.comp as float bits with atomicMax: non-negative floats order like their bits).
// selectRow() loads a row's range before any column arithmetic; spot and directional lights keep the
// uniforms (the define is off when the scene has no point light: those programs are unchanged).
layout(std430, binding = kFirstFreeSsboBinding) buffer RowGammaBlock { uint gRowGammaHi[]; };
const float kMinRowGamma = 1.0e-6;  // an empty row (no pixel) keeps a positive column width
float gGammaLo = 0.0;
float gGammaHi = 1.0;
void selectRow(int row) {
    if (uKind == kKindPoint) {
        gGammaLo = 0.0;
        gGammaHi = max(uintBitsToFloat(gRowGammaHi[row]), kMinRowGamma);
    } else {
        gGammaLo = uGammaLo;
        gGammaHi = uGammaHi;
    }
}
#define MINMAX_GAMMA_LO gGammaLo
#define MINMAX_GAMMA_HI gGammaHi
#else
void selectRow(int row) {}
#define MINMAX_GAMMA_LO uGammaLo
#define MINMAX_GAMMA_HI uGammaHi
#endif

float columnWidth() { return (MINMAX_GAMMA_HI - MINMAX_GAMMA_LO) / float(uColumns); }
float sliceAlpha(int row) { return uAlphaLo + float(row) * uAlphaSpacing; }

float alphaOf(vec3 p) { return atan(dot(p, uV), dot(p, uU)); }
float betaOf(vec3 p) { return atan(length(cross(p, uAxis)), dot(p, uAxis)); }

float gammaOfPlane(float z, float rho) {
    if (uKind == kKindDirectional) return rho;
    return atan(rho, uLightDistance - z);
}

float gammaAlongRay(float beta, float t) { return gammaOfPlane(t * cos(beta), t * sin(beta)); }

float distanceAtGamma(float beta, float gamma) {
    if (uKind == kKindDirectional) {
        float s = sin(beta);
        return s > 0.0 ? gamma / s : kInfinity;
    }
    float s = sin(beta + gamma);
    return s > 0.0 ? uLightDistance * sin(gamma) / s : kInfinity;
}

vec3 slicePerpendicular(float alpha) { return cos(alpha) * uU + sin(alpha) * uV; }

vec3 lightRayPoint(float alpha, float gamma) {
    vec3 e = slicePerpendicular(alpha);
    if (uKind == kKindDirectional) return gamma * e;
    return uLightDistance * uAxis + (-cos(gamma) * uAxis + sin(gamma) * e);
}

float occluderBeta(float gamma, float stored) {
    if (uKind == kKindDirectional) return atan(gamma, -stored);
    return atan(stored * sin(gamma), uLightDistance - stored * cos(gamma));
}

// Row `row` of the rectified map, wrapped around the circle of slices (uWrap) or clamped to its ends.
int wrapRow(int row) {
    if (uWrap) return ((row % uSlices) + uSlices) % uSlices;
    return clamp(row, 0, uSlices - 1);
}
// The slice position of angle alpha in rows (row k's slice at k); the nearest slice's row is sliceRow.
float slicePosition(float alpha) { return (alpha - uAlphaLo) / uAlphaSpacing; }
int sliceRow(float alpha) { return wrapRow(int(floor(slicePosition(alpha) + 0.5))); }

float columnOf(float gamma) { return (gamma - MINMAX_GAMMA_LO) / columnWidth(); }
float gammaOfColumn(float column) { return MINMAX_GAMMA_LO + column * columnWidth(); }

#endif  // MINMAX_EPIPOLAR_GLSL
