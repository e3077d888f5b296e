// The host side of shaders/common/camera_ray.glsl: the camera frame every per-pixel shader builds its
// rays from, set by this one helper.
#pragma once

#include "gl/program.h"
#include "scene/scene.h"

namespace viz::render {

// Sets uSize, uForward, uRight, uUp, uTanHalf and uAspect of a program that includes
// common/camera_ray.glsl, for an image of width x height pixels (floats of scene::pixelRay's terms).
void bindCameraRay(const gl::Program& program, const scene::Camera& camera, int width, int height);

}  // namespace viz::render
