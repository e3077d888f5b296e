// Integrals along one eye ray x(t) = o + t w, t in [0, d]: the lit intervals of a light (visibility
// transitions) and the in-scattered radiance of one emitter over one lit interval.
//
// Every integral here is a term of L_air = int sigma_s p(cos theta) E(t) V(t) exp(-sigma_t t) dt.
#pragma once

#include <functional>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "techniques/reference/emitters.h"

namespace viz::reference {

struct MediumParams {
    double sigma_s = 0.0;
    double sigma_t = 0.0;
    double g = 0.0;
};

struct Interval {
    double a = 0.0, b = 0.0;
};

struct VisibilitySearch {
    std::vector<Interval> lit;  // sorted, disjoint, inside [0, d]
    int transitions = 0;        // number of lit/unlit changes found
    double litLength() const {
        double s = 0.0;
        for (const auto& i : lit) s += i.b - i.a;
        return s;
    }
};

// Where a long ray is searched (sampling never depends on d alone: a camera's zfar of 1e6 in a scene 10
// units across). The search covers [0, min(d, reach)]: beyond `reach` (60 mean free paths) the medium
// passes on less than exp(-60) of any light, and the ray counts as unlit there. When that span is longer
// than `farSpan` (8 radii of the scene's bounds), half the uniform samples go to `scene`, the ray's part
// inside the bounds of the occluders, which uniform samples over the whole span would mostly miss.
struct SearchSpan {
    double reach = std::numeric_limits<double>::infinity();
    glm::dvec2 scene{1.0, 0.0};  // empty (x >= y): the ray misses the bounds
    double farSpan = std::numeric_limits<double>::infinity();
};

// Where along [0, d] V(t) = visible(t) is true. V is sampled at `samples` points: half uniform in t,
// half uniform in the angle theta = atan((t - tP) / h) seen from a point light (spacing finest near
// the closest approach, where the integrand peaks); pass h <= 0 for uniform samples only. Each change
// of V between neighbours is bisected until its bracket is below 1e-9 of the searched span.
VisibilitySearch findLitIntervals(const std::function<bool(double)>& visible, double d, int samples,
                                  double tP, double h, const SearchSpan& span = {});

// Ray/emitter geometry: tP = dot(P - o, w) the closest approach, h the distance of the light to the
// line, nHat the unit vector from the closest point of the ray towards... the light's offset
// (P - o - tP w) / h.
struct RayEmitterGeometry {
    double tP = 0.0, h = 0.0;
    glm::dvec3 nHat{0.0};
};
RayEmitterGeometry rayEmitterGeometry(const glm::dvec3& o, const glm::dvec3& w, const glm::dvec3& P);

struct SegmentStats {
    int pieces = 0;
    int evaluations = 0;
    double relError = 0.0;  // largest estimated relative error of a piece
};

// Relative tolerance asked of the adaptive Gauss-Kronrod quadrature of spot, cookie and area pieces.
constexpr double kSegmentRelTol = 1e-11;
// The same for each node of an area cell's rule: the rule itself is accurate to ~1e-5 (area_cells.h),
// so resolving each node's t-integral further only costs time.
constexpr double kCellNodeRelTol = 1e-6;

// int_a^b sigma_s p(cos theta) I(x) exp(-sigma_t (t + r)) / r^2 dt for one point-like emitter
// (the lit interval [a, b] is assumed fully visible). Isotropic emitters use the closed anchored
// quadrature of airlight::pointSegment; spot and Lambertian profiles are integrated in the angle
// theta = atan((t - tP) / h), where dt / r^2 = dtheta / h, split at every kink of the profile.
// relTol: asked of the adaptive quadrature (area-cell nodes ask less: see kCellNodeRelTol).
glm::dvec3 pointEmitterSegment(const PointEmitter& e, const glm::dvec3& o, const glm::dvec3& w, double a,
                               double b, const MediumParams& m, SegmentStats* stats = nullptr,
                               double relTol = kSegmentRelTol);

// int_a^b sigma_s p E_cell(t) exp(-sigma_t t) dt on the ray o + t w, the cell assumed visible over
// [a, b]; E_cell is the cell's emitter integral (each leaf node integrated in t by pointEmitterSegment).
glm::dvec3 cellSegment(const AreaCell& cell, const glm::dvec3& o, const glm::dvec3& w, double a, double b,
                       const MediumParams& m);

// The cell's emitter integral at x: int_cell L_e cos(theta_e) p(cos theta) exp(-sigma_t r) / r^2 dA
// with cos(theta) = dot(dir cell -> x, -w) (the airlight integrand without sigma_s and exp(-sigma_t t)).
glm::dvec3 cellInScatter(const AreaCell& cell, const glm::dvec3& x, const glm::dvec3& w, const MediumParams& m);

// Any point-like emitter over a lit interval: pointEmitterSegment, or cellSegment for an area cell.
glm::dvec3 emitterSegment(const PointEmitter& e, const glm::dvec3& o, const glm::dvec3& w, double a, double b,
                          const MediumParams& m);

// The same for a directional light: int_a^b sigma_s p(cos) E exp(-sigma_t t) dt.
glm::dvec3 directionalSegment(const DirectionalEmitter& e, const glm::dvec3& w, double a, double b,
                              const MediumParams& m);

// Breakpoints (in theta) of a spot or Lambertian profile along the ray, inside (theta0, theta1).
std::vector<double> profileKinks(const PointEmitter& e, const RayEmitterGeometry& g, const glm::dvec3& w,
                                 double theta0, double theta1);

}  // namespace viz::reference
