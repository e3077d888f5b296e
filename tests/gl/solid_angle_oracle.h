// The solid angle of a rectangle by its corner formula, in double: the tests' independent side for the
// shaders' two-triangle parallelogramSolidAngle (shaders/common/solid_angle.glsl).
#pragma once

#include <cmath>

#include <glm/glm.hpp>

namespace viz::testing {

// The rectangle with corner c, perpendicular edges eU and eV and unit normal n toward its lit side, seen
// from p; 0 from behind or in its plane. In the rectangle's frame with p at height z above the origin,
// Omega = sum over the corners (a, b) of +-atan(a b / (z |(a, b, z)|)).
inline double rectangleSolidAngle(glm::dvec3 c, glm::dvec3 eU, glm::dvec3 eV, glm::dvec3 n, glm::dvec3 p) {
    const glm::dvec3 d = p - c;
    const double z = glm::dot(d, n);
    if (!(z > 0.0)) return 0.0;
    const double lu = glm::length(eU), lv = glm::length(eV);
    const double pu = glm::dot(d, eU) / lu, pv = glm::dot(d, eV) / lv;
    const auto f = [z](double a, double b) { return std::atan(a * b / (z * std::sqrt(a * a + b * b + z * z))); };
    return f(lu - pu, lv - pv) - f(-pu, lv - pv) - f(lu - pu, -pv) + f(-pu, -pv);
}

}  // namespace viz::testing
