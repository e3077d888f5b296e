// Epipolar coordinates of voxelized shadow volumes (Wyman 2011; reviewed in Wyman and Dai 2013, 2.6),
// pure CPU, mirrored in shaders/vsv/epipolar.glsl. Space: eye-relative world (the eye E at the origin),
// light at L, baseline b = L / |L|, D = |L|.
//   theta: the half-plane through the baseline containing the point, angle around b measured from u
//          toward v (u, v, b orthonormal); theta in (-pi, pi].
//   alpha: angle at the eye between b and the eye ray, [0, pi]; one (alpha, theta) = one eye ray.
//   phi:   angle at the light between -b (toward the eye) and the light ray, [0, pi]; one (theta, phi)
//          = one light ray.
// In the triangle (E, L, P): t = |P - E| = D sin(phi) / sin(alpha + phi) (law of sines), and along an
// eye ray phi grows monotonically from 0 (t = 0) to pi - alpha (t -> inf); along a light ray alpha grows
// from 0 (at L) to pi - phi. So a voxel (alpha, theta, phi) is shadowed when the light ray (theta, phi)
// met an occluder at an alpha' <= alpha: occlusion extrudes toward larger alpha (a prefix OR along alpha).
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/glm.hpp>

namespace viz::vsv {

// A directional light has its "position" at infinity in direction b (against the travel direction):
// light rays in a half-plane are then parallel lines, told apart by their distance y from the line of
// the eye, and the phi axis of the grid holds y instead of an angle: along an eye ray y = t sin(alpha),
// and a light line y meets an occluder at signed position x along b at alpha = atan2(y, x).
struct EpipolarFrame {
    glm::dvec3 light{0.0};  // eye-relative light position (directional: 0)
    double D = 1.0;         // |light| (directional: 0)
    bool directional = false;
    glm::dvec3 b{0.0, 0.0, 1.0}, u{1.0, 0.0, 0.0}, v{0.0, 1.0, 0.0};
};

inline EpipolarFrame makeFrame(const glm::dvec3& light) {
    EpipolarFrame f;
    f.light = light;
    f.D = glm::length(light);
    f.b = light / f.D;
    // u: perpendicular to b, from the world axis least aligned with it.
    const glm::dvec3 a = glm::abs(f.b);
    const glm::dvec3 axis = a.x <= a.y && a.x <= a.z ? glm::dvec3(1, 0, 0)
                          : a.y <= a.z                ? glm::dvec3(0, 1, 0)
                                                      : glm::dvec3(0, 0, 1);
    f.u = glm::normalize(glm::cross(f.b, axis));
    f.v = glm::cross(f.b, f.u);
    return f;
}

inline EpipolarFrame makeDirectionalFrame(const glm::dvec3& travel) {
    EpipolarFrame f = makeFrame(-glm::normalize(travel));
    f.light = glm::dvec3(0.0);
    f.D = 0.0;
    f.directional = true;
    return f;
}

// alpha of the eye ray with unit direction w (atan2 form: accurate near 0 and pi).
inline double alphaOf(const EpipolarFrame& f, const glm::dvec3& w) {
    return std::atan2(glm::length(glm::cross(w, f.b)), glm::dot(w, f.b));
}
// theta of a direction (or of a point: the same half-plane) not on the baseline.
inline double thetaOf(const EpipolarFrame& f, const glm::dvec3& w) {
    return std::atan2(glm::dot(w, f.v), glm::dot(w, f.u));
}
// Unit eye ray direction of (alpha, theta).
inline glm::dvec3 eyeRay(const EpipolarFrame& f, double alpha, double theta) {
    return std::cos(alpha) * f.b + std::sin(alpha) * (std::cos(theta) * f.u + std::sin(theta) * f.v);
}
// Unit light ray direction of (theta, phi), from the light.
inline glm::dvec3 lightRay(const EpipolarFrame& f, double theta, double phi) {
    return -std::cos(phi) * f.b + std::sin(phi) * (std::cos(theta) * f.u + std::sin(theta) * f.v);
}
// phi of the point at distance t along the eye ray of angle alpha.
inline double phiOnEyeRay(const EpipolarFrame& f, double alpha, double t) {
    if (f.directional) return t * std::sin(alpha);
    return std::atan2(t * std::sin(alpha), f.D - t * std::cos(alpha));
}
// alpha of the point at distance r from the light along the light ray of angle phi.
inline double alphaOnLightRay(const EpipolarFrame& f, double phi, double r) {
    return std::atan2(r * std::sin(phi), f.D - r * std::cos(phi));
}
// Distance t along the eye ray alpha at which phi is reached; +inf when alpha + phi >= pi.
inline double tOnEyeRay(const EpipolarFrame& f, double alpha, double phi) {
    if (f.directional) return std::sin(alpha) > 0.0 ? phi / std::sin(alpha) : INFINITY;
    const double s = std::sin(alpha + phi);
    if (alpha + phi >= std::numbers::pi || s <= 0.0) return INFINITY;
    return f.D * std::sin(phi) / s;
}

// The part of epipolar space a grid covers, and its resolution. Theta is stored as a centre and a half
// width so that a range crossing +-pi needs no special case: cell coordinate of theta =
// (wrap(theta - thetaCentre) + thetaHalf) / dTheta, wrap into (-pi, pi].
struct EpipolarGrid {
    int nAlpha = 128, nTheta = 128, nPhi = 128;
    double alpha0 = 0.0, alpha1 = std::numbers::pi;
    double thetaCentre = 0.0, thetaHalf = std::numbers::pi;
    double phi0 = 0.0, phi1 = std::numbers::pi;
    bool thetaFull = true;     // theta covers the whole circle (an epipole is in view): neighbours wrap
    bool epipoleToward = false;  // the epipole toward the light (alpha = 0) is in view
    bool epipoleAway = false;    // the epipole away from the light (alpha = pi) is in view

    double dAlpha() const { return (alpha1 - alpha0) / nAlpha; }
    double dTheta() const { return 2.0 * thetaHalf / nTheta; }
    double dPhi() const { return (phi1 - phi0) / nPhi; }
};

inline double wrapAngle(double a) {
    a = std::fmod(a + std::numbers::pi, 2.0 * std::numbers::pi);
    if (a < 0.0) a += 2.0 * std::numbers::pi;
    return a - std::numbers::pi;
}

// Continuous cell coordinates (cell i covers [i, i + 1)).
inline double alphaCoord(const EpipolarGrid& g, double alpha) { return (alpha - g.alpha0) / g.dAlpha(); }
inline double thetaCoord(const EpipolarGrid& g, double theta) {
    return (wrapAngle(theta - g.thetaCentre) + g.thetaHalf) / g.dTheta();
}
inline double phiCoord(const EpipolarGrid& g, double phi) { return (phi - g.phi0) / g.dPhi(); }
inline double thetaAtCell(const EpipolarGrid& g, double coord) {
    return g.thetaCentre - g.thetaHalf + coord * g.dTheta();
}

// The camera, as the gather sees it: unit forward/right/up, tan of the half fields of view.
struct CameraRays {
    glm::dvec3 forward, right, up;
    double tanX = 1.0, tanY = 1.0;
    glm::dvec3 ray(double ndcX, double ndcY) const {
        return glm::normalize(forward + ndcX * tanX * right + ndcY * tanY * up);
    }
    bool sees(const glm::dvec3& dir) const {
        const double z = glm::dot(dir, forward);
        return z > 0.0 && std::abs(glm::dot(dir, right)) <= tanX * z && std::abs(glm::dot(dir, up)) <= tanY * z;
    }
};

// Optional spot cone: light rays further than `outer` from the axis carry no light.
struct SpotCone {
    bool present = false;
    glm::dvec3 axis{0.0, -1.0, 0.0};
    double outer = std::numbers::pi;
};

// Dynamic range selection (Wyman and Dai 2013, section 5): the grid covers only the part of epipolar
// space the camera sees. alpha and theta: the extremes over the image border (neither angle has an
// extremum inside the image unless an epipole is in it; then alpha reaches 0 or pi and theta wraps
// fully). phi: from 0 (the eye) to the largest phi of a visible point (at t = zfar), narrowed for a spot to the cone's band |phi - beta| <= outer
// (beta = angle between the axis and -b: a ray within `outer` of the axis is within `outer` of beta).
// `margin` widens every range by that many cells (rays at the image edge keep a neighbour).
inline EpipolarGrid selectRanges(const EpipolarFrame& f, const CameraRays& cam, double zfar, const SpotCone& spot,
                                 int nAlpha, int nTheta, int nPhi, bool dynamic = true, double margin = 1.0) {
    constexpr double pi = std::numbers::pi;
    EpipolarGrid g;
    g.nAlpha = nAlpha;
    g.nTheta = nTheta;
    g.nPhi = nPhi;
    g.epipoleToward = cam.sees(f.b);
    g.epipoleAway = cam.sees(-f.b);
    if (!dynamic) {
        g.alpha0 = 0.0;
        g.alpha1 = pi;
        g.thetaCentre = 0.0;
        g.thetaHalf = pi;
        g.thetaFull = true;
        g.phi0 = 0.0;
        g.phi1 = pi;
        return g;
    }
    const double thetaCentre = thetaOf(f, cam.forward);
    double aMin = pi, aMax = 0.0, dMin = pi, dMax = -pi;
    constexpr int kPerEdge = 64;
    for (int e = 0; e < 4; ++e) {
        for (int i = 0; i <= kPerEdge; ++i) {
            const double s = -1.0 + 2.0 * i / kPerEdge;
            const double x = e == 0 ? s : e == 1 ? s : e == 2 ? -1.0 : 1.0;
            const double y = e == 0 ? -1.0 : e == 1 ? 1.0 : s;
            const glm::dvec3 w = cam.ray(x, y);
            const double a = alphaOf(f, w);
            aMin = std::min(aMin, a);
            aMax = std::max(aMax, a);
            const double d = wrapAngle(thetaOf(f, w) - thetaCentre);
            dMin = std::min(dMin, d);
            dMax = std::max(dMax, d);
        }
    }
    if (g.epipoleToward) aMin = 0.0;
    if (g.epipoleAway) aMax = pi;
    // The camera's forward half-plane sits on a theta cell centre: in a view symmetric about it (a light
    // straight above or ahead) the middle image column then reads one cell, as the shadow map's texel
    // there was sampled, instead of blending two cells across a shadow edge that may lie exactly in
    // that half-plane (an occluder face through the light and the eye).
    g.thetaFull = g.epipoleToward || g.epipoleAway || dMax - dMin > 2.0 * pi * 0.95;
    if (g.thetaFull) {
        g.thetaCentre = thetaCentre + pi / nTheta;
        g.thetaHalf = pi;
    } else {
        const double half = std::max(-dMin, dMax) * (1.0 + margin / nTheta);
        g.thetaHalf = std::min(pi, half * nTheta / std::max(1.0, nTheta - 1.0));
        g.thetaCentre = thetaCentre + g.thetaHalf / nTheta;
        if (g.thetaHalf >= pi) g.thetaFull = true;
    }
    const double padA = margin * (aMax - aMin) / nAlpha;
    g.alpha0 = std::max(0.0, aMin - (g.epipoleToward ? 0.0 : padA));
    g.alpha1 = std::min(pi, aMax + (g.epipoleAway ? 0.0 : padA));
    // phi grows along every eye ray, so its largest visible value is at t = zfar; over alpha it is not
    // monotonic (for zfar > D it falls from pi at alpha = 0, for zfar < D it peaks inside), so sample.
    double p0 = 0.0;
    double p1 = 0.0;
    constexpr int kAlphaSamples = 512;
    const double phiCap = f.directional ? zfar : pi;
    for (int i = 0; i <= kAlphaSamples; ++i)
        p1 = std::max(p1, phiOnEyeRay(f, g.alpha0 + (g.alpha1 - g.alpha0) * i / kAlphaSamples, zfar));
    p1 = std::min(phiCap, p1 * (1.0 + 1.0 / kAlphaSamples) + (f.directional ? 0.0 : (g.alpha1 - g.alpha0) / kAlphaSamples));
    if (spot.present) {
        const double beta = std::acos(std::clamp(glm::dot(glm::normalize(spot.axis), -f.b), -1.0, 1.0));
        p0 = std::max(p0, beta - spot.outer);
        p1 = std::min(p1, beta + spot.outer);
    }
    if (!(p1 > p0)) p1 = p0 + 1e-6;  // nothing lit in view: a valid, empty band
    const double padP = margin * (p1 - p0) / nPhi;
    g.phi0 = std::max(0.0, p0 - padP);
    g.phi1 = std::min(phiCap, p1 + padP);
    return g;
}

// Voxelization of one light ray (cell centres of theta and phi): the alpha cell of its first occluder
// at distance r from the light, moved by alphaBias cells (negative pushes the shadow away from the
// light, Wyman and Dai's convention). Returns -1 when the occluder lies beyond the grid's alpha range;
// an occluder before the range shadows the whole column (cell 0).
inline int occluderCell(const EpipolarFrame& f, const EpipolarGrid& g, double phi, double r, double alphaBias) {
    const double c = alphaCoord(g, alphaOnLightRay(f, phi, r)) - alphaBias;
    if (c >= g.nAlpha) return -1;
    return std::max(0, int(std::floor(c)));
}

// Passes of the prefix-OR scan along alpha (each pass doubles the reach): ceil(log2(alpha cells)).
inline int scanPassCount(int alphaCells) {
    int passes = 0;
    while ((1 << passes) < alphaCells) ++passes;
    return passes;
}

}  // namespace viz::vsv
