// A spot light's cones along an eye ray: the C++ mirror of shaders/common/spot_cone.glsl (same names,
// argument order and steps), for CPU mirrors of the shaders (minmax's picked pixel). The ray is cut where
// it crosses the outer and inner cones and the plane through the light normal to the axis, so that on
// each part A_spot is 0, 1 or the square of a smooth lobe (docs/numerics.md#spot-penumbra).
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "shared/airlight.h"

namespace viz::airlight {

// The direction from the light to the ray's point at angle phi: (m / h) cos(phi) + w sin(phi).
template <typename Real>
glm::vec<3, Real> directionFromLight(glm::vec<3, Real> m, Real h, glm::vec<3, Real> w, Real phi) {
    return glm::normalize((m / h) * std::cos(phi) + w * std::sin(phi));
}

// The cuts of [x0, x1]: breaks[0] = x0, then the crossings in order; part i is [breaks[i], breaks[i + 1]]
// and the last ends at x1. m = P - light and h (floored at 1e-7 |tP|) for the directions.
template <typename Real>
struct SpotCuts {
    Real breaks[8] = {};
    int n = 0;
    glm::vec<3, Real> m{0};
    Real h = 0;
};

// Roots in (x0, x1) of the double cone of half-angle acos(c) around the unit axis a through the light,
// appended to the cuts (see coneRoots in spot_cone.glsl for the derivation and why every coefficient is
// formed relative to the foot point).
template <typename Real>
void coneRoots(glm::vec<3, Real> m, Real h, glm::vec<3, Real> w, Real tP, glm::vec<3, Real> a, Real c, Real x0, Real x1,
               SpotCuts<Real>& cuts) {
    const Real wa = glm::dot(w, a), ma = glm::dot(m, a);
    const Real S = std::max(std::max(h, std::abs(x0 - tP)), std::min(std::abs(x1 - tP), Real(1e30)));
    const Real A = wa * wa - c * c;
    const Real B = Real(2) * ma * wa;
    const Real C = ma * ma - c * c * h * h;
    Real r[2];
    int k = 0;
    if (std::abs(A) * S < Real(1e-7) * (std::abs(B) + std::abs(C) / S + Real(1e-30))) {
        if (B != Real(0)) r[k++] = -C / B;
    } else {
        const Real disc = Real(4) * c * c * (ma * ma + A * h * h);
        if (disc >= Real(0)) {
            const Real q = Real(-0.5) * (B + (B >= Real(0) ? Real(1) : Real(-1)) * std::sqrt(disc));
            r[k++] = q / A;
            if (q != Real(0)) r[k++] = C / q;
        }
    }
    for (int i = 0; i < k; ++i) {
        const Real t = tP + r[i];
        if (t > x0 && t < x1 && cuts.n < 8) cuts.breaks[cuts.n++] = t;
    }
}

// A spot at D (camera-relative) with unit axis a, cos(outer) cosOuter and cos(inner) cosInner.
template <typename Real>
SpotCuts<Real> spotConeCuts(glm::vec<3, Real> D, glm::vec<3, Real> a, Real cosOuter, Real cosInner,
                            glm::vec<3, Real> w, RayLightGeometry<Real> g, Real x0, Real x1) {
    SpotCuts<Real> c;
    c.h = std::max(g.h, Real(1e-7) * std::max(std::abs(g.tP), Real(1e-20)));
    c.m = glm::cross(glm::cross(D, w), w);  // P - light from cross products
    c.breaks[c.n++] = x0;
    coneRoots(c.m, c.h, w, g.tP, a, cosOuter, x0, x1, c);
    coneRoots(c.m, c.h, w, g.tP, a, cosInner, x0, x1, c);
    const Real wa = glm::dot(w, a);
    if (wa != Real(0)) {
        const Real tPlane = g.tP - glm::dot(c.m, a) / wa;
        if (tPlane > x0 && tPlane < x1 && c.n < 8) c.breaks[c.n++] = tPlane;
    }
    std::sort(c.breaks, c.breaks + c.n);
    return c;
}

// Where a part [xa, xb] of the cuts lies, classified at its middle.
enum class SpotZone { Dark, Penumbra, Inside };

template <typename Real>
SpotZone spotZone(glm::vec<3, Real> a, Real cosOuter, Real cosInner, const SpotCuts<Real>& c, glm::vec<3, Real> w,
                  Real tP, Real xa, Real xb) {
    const Real cd = glm::dot(directionFromLight(c.m, c.h, w, std::atan2(Real(0.5) * (xa + xb) - tP, c.h)), a);
    return cd <= cosOuter ? SpotZone::Dark : (cd >= cosInner ? SpotZone::Inside : SpotZone::Penumbra);
}

}  // namespace viz::airlight
