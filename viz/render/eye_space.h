// Eye-relative world space ("view-origin space"): world translated so the camera is at the origin, axes
// unchanged. Everything on the GPU lives there, because fp32 world coordinates far from the origin lose
// airlight accuracy (docs/numerics.md#camera-relative-coordinates). Translations are formed in double and
// rounded once.
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace viz::render {

// Model matrix taking the world positions stored in the vertex buffer to eye-relative space:
// translate(-eye), rounded to float once. Why this is enough: the scene keeps vertex positions as fp32
// already, so a vertex far from the origin carries an absolute error of ~|p| * 6e-8; rounding -eye adds
// an error of the same order, and the sum p + (-eye) of two nearby floats is then almost exact. What
// would lose accuracy is composing the translation with the projection in float, which we never do.
glm::mat4 eyeRelativeModel(const glm::dvec3& eye);

// View (camera at the origin, looking along camera.forward) times scene::projectionMatrix, in double,
// rounded once: maps eye-relative world to clip space of a width x height image.
glm::mat4 eyeRelativeViewProjection(const scene::Camera& camera, int width, int height);

// A world-space point in eye-relative space, in double, rounded once.
inline glm::vec3 toEyeRelative(const glm::dvec3& p, const glm::dvec3& eye) { return glm::vec3(p - eye); }

}  // namespace viz::render
