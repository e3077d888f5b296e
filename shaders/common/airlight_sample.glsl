// One sample of the midpoint rule along an eye ray: the single-scattering integrand
// sigma_s p_HG(cos theta) E V exp(-sigma_t t) dt with the medium's block (medium.glsl). Every technique
// that sums it along a ray calls this one copy: raymarch's march, minmax's brute-force lights and its
// march in gamma (dt: the Jacobian times the step), slices' planes (V: visibility times the noise that
// scales the density), ivsv's gather (in phi: E times the Jacobian r^2 / h of t).
#ifndef COMMON_AIRLIGHT_SAMPLE_GLSL
#define COMMON_AIRLIGHT_SAMPLE_GLSL

#include "common/airlight.glsl"
#include "common/medium.glsl"

// V: visibility of the sample (0 .. 1), cosTheta: cosine of the scattering angle (direction to the light
// against the ray), E: the light's unshadowed irradiance at the sample, t: its distance from the eye, dt:
// the interval it stands for.
vec3 airlightSample(float V, float cosTheta, vec3 E, float t, float dt) {
    return V * uSigmaS * phaseHG(cosTheta, uG) * E * exp(-uSigmaT * t) * dt;
}

#endif
