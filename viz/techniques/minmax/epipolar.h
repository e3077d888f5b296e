// Epipolar coordinates of Chen et al. 2011, section 3.2 and Figure 2, in eye-relative world space (the eye
// at the origin). Mirrored line by line in shaders/minmax/epipolar.glsl.
//
// Every slice is a half-plane bounded by the epipolar axis: the line through the eye toward the light
// (spot/point: a = normalize(light position); directional: a = -travel direction, the light at infinity).
// Point lights use the spot's formulas throughout (gamma is the angle at the light); they differ only in
// the gamma range of the rectified map, which is the cone for a spot and, for a point light shining in
// every direction, per slice the range its camera rays reach (EpipolarFrame::withGammaRange).
//   alpha in (-pi, pi]: the half-plane, the angle of its in-plane perpendicular e(alpha) = cos(alpha) u +
//         sin(alpha) v around a ((u, v, a) right-handed; u is turned toward the screen centre's slice, so
//         the slices that cross the screen form one interval of alpha unless the epipole is on screen).
//   beta in [0, pi]:   the camera ray within the slice, its angle to a.
//   gamma:             the light ray within the slice. Spot, point: the angle at the light between the
//         direction light -> eye (-a) and light -> point, in [0, pi] (a half-plane sees the light's
//         directions from -a round to +a; the other half of the plane is the slice alpha + pi).
//         Directional: the distance rho of the light ray from the axis (light rays are parallel to a).
// A light behind the camera needs no special case: a points backward and visible rays have beta > pi/2.
// Along a camera ray (alpha, beta fixed) gamma grows monotonically from 0 with the distance t:
//   spot:        gamma = atan2(t sin(beta), D - t cos(beta)),  t = D sin(gamma) / sin(beta + gamma)
//   directional: gamma = t sin(beta),                          t = gamma / sin(beta)
// and along a light ray (alpha, gamma fixed) beta grows monotonically with the distance travelled, so
// a point is lit exactly when its beta is below the beta of the occluder ending its light ray: the
// rectified shadow map S[alpha, gamma] stores that beta, and lit <=> beta < S (section 3.3).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <glm/glm.hpp>

namespace viz::minmax {

// Values shared with shaders/minmax/epipolar.glsl (kKindSpot, kKindDirectional, kKindPoint).
enum class LightKind { Spot = 0, Directional = 1, Point = 2 };

// S for a light ray that nothing blocks (or that leaves the shadow map): above every beta.
inline constexpr float kUnblocked = 4.0f;
// S for a column outside a spot's cone: below every beta, so the tree calls it shadowed (A_spot = 0).
inline constexpr float kOutsideCone = -1.0f;

template <typename Real>
struct EpipolarFrame {
    using Vec3 = glm::vec<3, Real>;
    LightKind kind = LightKind::Spot;
    Vec3 axis{0, 0, 1};  // a
    Vec3 u{1, 0, 0}, v{0, 1, 0};
    Real lightDistance = 1;  // D = |light - eye| (spot, point); unused for directional
    // Rectified map: `slices` rows at alpha_i = alphaLo + i alphaSpacing (wrapping around the circle when
    // the epipole is on screen), `columns` texels over gamma in [gammaLo, gammaHi].
    int slices = 1, columns = 1;
    bool wrap = true;
    Real alphaLo = -std::numbers::pi_v<Real>, alphaSpacing = Real(2) * std::numbers::pi_v<Real>;
    Real gammaLo = 0, gammaHi = 1;

    Real columnWidth() const { return (gammaHi - gammaLo) / Real(columns); }
    Real sliceAlpha(int row) const { return alphaLo + Real(row) * alphaSpacing; }
    // The same frame with the gamma range of one row: a point light's rows each cover their own range
    // (minmax.row_gamma), so column arithmetic for a row uses that row's frame.
    EpipolarFrame withGammaRange(Real lo, Real hi) const {
        EpipolarFrame f = *this;
        f.gammaLo = lo;
        f.gammaHi = hi;
        return f;
    }
};

// The frame of a light given eye-relative position (spot, point) or travel direction (directional).
template <typename Real>
EpipolarFrame<Real> makeFrame(LightKind kind, glm::vec<3, Real> lightPosition, glm::vec<3, Real> travelDirection) {
    using Vec3 = glm::vec<3, Real>;
    EpipolarFrame<Real> f;
    f.kind = kind;
    if (kind != LightKind::Directional) {
        f.lightDistance = glm::length(lightPosition);
        f.axis = lightPosition / f.lightDistance;
    } else {
        f.axis = -glm::normalize(travelDirection);
    }
    const Vec3 helper = std::abs(f.axis.y) < Real(0.9) ? Vec3(0, 1, 0) : Vec3(1, 0, 0);
    f.u = glm::normalize(glm::cross(helper, f.axis));
    f.v = glm::cross(f.axis, f.u);
    return f;
}

// alpha in (-pi, pi] of a direction or point (any point off the axis).
template <typename Real>
Real alphaOf(const EpipolarFrame<Real>& f, glm::vec<3, Real> p) {
    return std::atan2(glm::dot(p, f.v), glm::dot(p, f.u));
}

// Turns u and v about the axis so that alpha = 0 is the slice of direction p.
template <typename Real>
void centreAlphaOn(EpipolarFrame<Real>& f, glm::vec<3, Real> p) {
    const Real a = alphaOf(f, p);
    const glm::vec<3, Real> u = std::cos(a) * f.u + std::sin(a) * f.v;
    f.u = u;
    f.v = glm::cross(f.axis, u);
}

// beta in [0, pi] of a ray direction (or of a point: the ray from the eye through it).
template <typename Real>
Real betaOf(const EpipolarFrame<Real>& f, glm::vec<3, Real> p) {
    return std::atan2(glm::length(glm::cross(p, f.axis)), glm::dot(p, f.axis));
}

// gamma of a point given its in-plane coordinates z = dot(p, a) and rho = distance from the axis.
template <typename Real>
Real gammaOfPlane(const EpipolarFrame<Real>& f, Real z, Real rho) {
    if (f.kind == LightKind::Directional) return rho;
    return std::atan2(rho, f.lightDistance - z);
}

template <typename Real>
Real gammaOf(const EpipolarFrame<Real>& f, glm::vec<3, Real> p) {
    return gammaOfPlane(f, glm::dot(p, f.axis), glm::length(glm::cross(p, f.axis)));
}

// gamma at distance t along the camera ray with angle beta.
template <typename Real>
Real gammaAlongRay(const EpipolarFrame<Real>& f, Real beta, Real t) {
    return gammaOfPlane(f, t * std::cos(beta), t * std::sin(beta));
}

// The distance t along the camera ray beta at which it meets light ray gamma (inverse of gammaAlongRay);
// +inf when they do not meet (spot: gamma >= pi - beta; directional: beta = 0 or pi).
template <typename Real>
Real distanceAtGamma(const EpipolarFrame<Real>& f, Real beta, Real gamma) {
    if (f.kind == LightKind::Directional) {
        const Real s = std::sin(beta);
        return s > Real(0) ? gamma / s : std::numeric_limits<Real>::infinity();
    }
    const Real s = std::sin(beta + gamma);
    return s > Real(0) ? f.lightDistance * std::sin(gamma) / s : std::numeric_limits<Real>::infinity();
}

// Unit vector e(alpha) of a slice (in-plane, perpendicular to the axis).
template <typename Real>
glm::vec<3, Real> slicePerpendicular(const EpipolarFrame<Real>& f, Real alpha) {
    return std::cos(alpha) * f.u + std::sin(alpha) * f.v;
}

// The world point with epipolar coordinates (alpha, beta, gamma): the camera ray (alpha, beta) at its
// meeting with light ray gamma.
template <typename Real>
glm::vec<3, Real> pointOf(const EpipolarFrame<Real>& f, Real alpha, Real beta, Real gamma) {
    const Real t = distanceAtGamma(f, beta, gamma);
    return t * (std::cos(beta) * f.axis + std::sin(beta) * slicePerpendicular(f, alpha));
}

// Unit direction light -> point of light ray (alpha, gamma) (spot, point): the cube-map lookup direction.
template <typename Real>
glm::vec<3, Real> lightRayDirection(const EpipolarFrame<Real>& f, Real alpha, Real gamma) {
    return -std::cos(gamma) * f.axis + std::sin(gamma) * slicePerpendicular(f, alpha);
}

// A point on light ray (alpha, gamma): spot, point: the unit step from the light; directional: the point of the
// ray in the plane through the eye perpendicular to a. Either projects onto the light ray's shadow texel
// (every point of a light ray does).
template <typename Real>
glm::vec<3, Real> lightRayPoint(const EpipolarFrame<Real>& f, Real alpha, Real gamma) {
    const glm::vec<3, Real> e = slicePerpendicular(f, alpha);
    if (f.kind == LightKind::Directional) return gamma * e;
    return f.lightDistance * f.axis + (-std::cos(gamma) * f.axis + std::sin(gamma) * e);
}

// beta of the occluder on light ray gamma. `stored` is the shadow map's biased threshold: spot, point: the
// distance from the light up to which points are lit; directional: the depth dot(p, travel) up to which
// points are lit.
template <typename Real>
Real occluderBeta(const EpipolarFrame<Real>& f, Real gamma, Real stored) {
    if (f.kind == LightKind::Directional) return std::atan2(gamma, -stored);
    return std::atan2(stored * std::sin(gamma), f.lightDistance - stored * std::cos(gamma));
}

// Row of the nearest slice to alpha, and the continuous column of gamma (texel j covers [j, j + 1)).
template <typename Real>
int sliceRow(const EpipolarFrame<Real>& f, Real alpha) {
    const int row = int(std::floor((alpha - f.alphaLo) / f.alphaSpacing + Real(0.5)));
    if (f.wrap) return ((row % f.slices) + f.slices) % f.slices;
    return std::clamp(row, 0, f.slices - 1);
}
template <typename Real>
Real columnOf(const EpipolarFrame<Real>& f, Real gamma) {
    return (gamma - f.gammaLo) / f.columnWidth();
}
template <typename Real>
Real gammaOfColumn(const EpipolarFrame<Real>& f, Real column) {
    return f.gammaLo + column * f.columnWidth();
}

// |d alpha| between neighbouring pixels, wrapped to [0, pi].
template <typename Real>
Real alphaStep(Real a0, Real a1) {
    Real d = std::abs(a1 - a0);
    return std::min(d, Real(2) * std::numbers::pi_v<Real> - d);
}

}  // namespace viz::minmax
