// One sample of the midpoint rule along an eye ray: the single-scattering integrand
// sigma_s p_HG(cos theta) E V exp(-sigma_t t) dt with the medium's block (medium.glsl). raymarch's march
// and minmax's brute-force lights both sum it, from this one copy, so they agree to the bit where they
// sample the same points. (slices' planes, minmax's march in gamma and ivsv's quadrature fold their own
// factors, the noise, a Jacobian or a lobe, into the product in another order; giving them this function
// would change their images in the last bit.)
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
