// Moving a light along the window's orbit animation (P, a lesson's `animate: light orbit`) and the motion
// paths (scene/motion_path.h): rotations of a light about an axis through its aim point.
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace viz::scene {

// Rodrigues' rotation of `v` about the unit vector `axis` by `angle` radians (right-handed). Angle 0
// returns v unchanged, bit for bit.
glm::dvec3 rotateAbout(glm::dvec3 v, glm::dvec3 axis, double angle);

// Half-angle of the orbit cone.
constexpr double kOrbitTilt = 0.2617993877991494;  // 15 degrees

// The light at `turn` turns of its orbit (1 = one full turn; any real number, negative turns go the other
// way): it circles its aim point on a cone of half-angle kOrbitTilt whose surface holds its own position,
// so whole turns are exactly where it started. A spot keeps pointing at the aim point (on its axis, as
// far from the light as `centre`); a point light circles `centre`; a directional light's direction sweeps
// the same cone. Throws InputError for an area light (its emitter is geometry).
Light orbitLight(const Light& light, glm::dvec3 centre, double turn);

// The point a light turns about: `centre` for a point light, the point on a spot's axis as far from it as
// `centre`; unused for a directional light (its direction turns).
glm::dvec3 lightAim(const Light& light, glm::dvec3 centre);

}  // namespace viz::scene
