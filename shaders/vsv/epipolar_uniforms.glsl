// The one epipolar space of a vsv pass, as uniforms (set by VsvTechnique::setEpipolar).
#ifndef VSV_EPIPOLAR_UNIFORMS_GLSL
#define VSV_EPIPOLAR_UNIFORMS_GLSL

#include "vsv/epipolar.glsl"

uniform vec3 uEpiB;
uniform vec3 uEpiU;
uniform vec3 uEpiV;
uniform float uEpiD;
uniform ivec3 uEpiCells;
uniform vec2 uEpiAlpha;
uniform vec3 uEpiTheta;
uniform vec2 uEpiPhi;
uniform int uEpiThetaFull;

EpiSpace epiFromUniforms() {
    return EpiSpace(uEpiB, uEpiU, uEpiV, uEpiD, uEpiCells, uEpiAlpha, uEpiTheta, uEpiPhi, uEpiThetaFull != 0);
}

#endif  // VSV_EPIPOLAR_UNIFORMS_GLSL
