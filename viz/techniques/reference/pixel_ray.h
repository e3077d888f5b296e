// The reference's work for one eye ray, shared by the full-frame reference and the ray inspector:
// where along [0, d] each emitter is visible, L_air over those lit intervals, and the integrand at a
// point (for plots). o is the eye, w the unit ray direction.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "techniques/reference/emitters.h"
#include "techniques/reference/ray_integrals.h"
#include "techniques/reference/ray_tracer.h"

namespace viz::reference {

// One VisibilitySearch per point emitter, then one per directional emitter (PreparedLights' order). The
// search covers [0, min(d, 60 / sigma_t)] and, on a span longer than 8 radii of the occluders' bounds,
// puts half its uniform samples inside those bounds (SearchSpan; the policy: scene/ray_reach.h).
std::vector<VisibilitySearch> rayVisibility(const RayTracer& tracer, const PreparedLights& lights,
                                            const glm::dvec3& o, const glm::dvec3& w, double d, int samples,
                                            double sigmaT);


// L_air = the sum over emitters of their exact in-scattered radiance over their lit intervals.
glm::dvec3 rayAirlight(const PreparedLights& lights, const glm::dvec3& o, const glm::dvec3& w,
                       const std::vector<VisibilitySearch>& lit, const MediumParams& medium);

// The integrand sigma_s p(cos theta) E(t) V(t) exp(-sigma_t t) at distance t along the ray (RGB), V from
// the lit intervals.
glm::dvec3 rayIntegrand(const PreparedLights& lights, const glm::dvec3& o, const glm::dvec3& w, double t,
                        const std::vector<VisibilitySearch>& lit, const MediumParams& medium);

}  // namespace viz::reference
