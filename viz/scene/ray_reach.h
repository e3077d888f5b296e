// How far along the camera's rays the techniques look. Sampling never depends on zfar alone: a public
// file's camera with zfar 1e6 around a model 10 units across would spread a fixed budget of samples
// (raymarch's N per ray, the reference's visibility search, slices' planes, vsv's phi cells) over a
// million units and miss the model's shafts. Two rules, one policy:
//   - every technique ignores the ray past kReachMeanFreePaths mean free paths (exp(-60) < 1e-26 of
//     what nearer points add; the shaders' reachAlongRay, common/lights.glsl);
//   - a ray longer than kFarSpanRadii radii of the scene's bounds is "far": raymarch and minmax's
//     marches sample it by the light (common/march_samples.glsl), the reference puts half its search
//     inside the bounds; slices and vsv, whose depth samples are shared by every pixel, cover
//     depthOfInterest() instead of zfar, and a ray going on past it adds the rest by the light (FAR_TAIL).
#pragma once

#include "scene/scene.h"

namespace viz::scene {

constexpr double kReachMeanFreePaths = 60.0;
constexpr double kFarSpanRadii = 8.0;

// The lit span beyond which a ray counts as far: kFarSpanRadii radii of the bounds of the meshes (0 without
// meshes: every span is far).
double farSpan(const Scene& scene);
// The longest lit span a ray of the camera can have: zfar, at most kReachMeanFreePaths mean free paths.
double longestLitSpan(const Scene& scene);
// Whether the camera's rays can be far (longestLitSpan > farSpan): the marches' FAR_RAYS feature.
inline bool farRaysPossible(const Scene& scene) { return longestLitSpan(scene) > farSpan(scene); }

// The distance along the camera's rays that shared depth samples cover: zfar, unless zfar is longer than
// kFarSpanRadii radii of the bounds of the meshes; then the farthest corner of those bounds (or point-like
// light) from the eye. Never more than zfar.
double depthOfInterest(const Scene& scene);

}  // namespace viz::scene
