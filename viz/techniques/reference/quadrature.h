// Quadrature rules used by the reference: globally adaptive Gauss-Kronrod (7/15 points) for smooth
// pieces of a ray integral, and Gauss-Legendre nodes of any order for the emitter product rule.
#pragma once

#include <functional>
#include <vector>

#include <glm/glm.hpp>

namespace viz::reference {

struct QuadratureResult {
    glm::dvec3 value{0.0};
    double errorEstimate = 0.0;  // sum over accepted intervals of max-channel |K15 - G7|
    int evaluations = 0;
    bool converged = true;
};

// Integral over [a, b] of an RGB integrand. The interval list is refined (always splitting the interval
// with the largest error) until the summed error estimate is below max(absTol, relTol * |value|) or
// maxIntervals is reached. Each piece must be smooth: pass kinks as separate calls.
QuadratureResult integrateAdaptive(const std::function<glm::dvec3(double)>& f, double a, double b,
                                   double relTol, double absTol, int maxIntervals = 400);


}  // namespace viz::reference
