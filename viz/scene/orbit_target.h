// Where the camera's orbit target lies: the point the window's orbit camera turns about and its light
// animation circles, and the centre of the motion paths' camera orbits (scene/motion_path.h).
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace viz::scene {

// Distance along the ray to the nearest triangle of the scene (Moller-Trumbore, brute force over every
// triangle: done once per reset, scenes here have a few thousand triangles), or -1 for a miss.
double firstHit(const Scene& scene, glm::dvec3 origin, glm::dvec3 dir);

// Distance from the scene camera to the orbit target: the first surface on the view axis; failing
// that, where the axis passes closest to the centre of the scene's bounding box; failing that (the
// centre is behind the camera), the box's size; 5 for a scene without geometry.
double orbitDistance(const Scene& scene);

// scene.camera.position + forward * orbitDistance(scene).
glm::dvec3 orbitTarget(const Scene& scene);

}  // namespace viz::scene
