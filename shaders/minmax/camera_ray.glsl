// The camera ray for minmax/traverse.comp and minmax/gamma_range.comp, which must agree on every pixel's
// ray to the bit (the row ranges of a point light are the largest gamma the traversal will ask for): both
// call common/camera_ray.glsl's pixelRay.
#ifndef MINMAX_CAMERA_RAY_GLSL
#define MINMAX_CAMERA_RAY_GLSL

#include "common/camera_ray.glsl"

// A ray along the epipolar axis lies in every slice and has no gamma parametrisation.
bool onEpipolarAxis(vec3 w, vec3 axis) { return length(cross(w, axis)) < 1e-5; }

#endif  // MINMAX_CAMERA_RAY_GLSL
