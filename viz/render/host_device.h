// C++ view of shaders/common/host_device.glsl (the structs and binding points are declared there once)
// plus layout checks: std430 places each vec4/ivec4 at a multiple of 16 and a mat4 as four vec4 columns.
#pragma once

#include <cstddef>

#include <glm/glm.hpp>

#include "scene/ray_reach.h"

// Relative to this header, so no extra include directory is needed by anyone who includes it.
#include "../../shaders/common/host_device.glsl"

namespace viz::render {

using GpuMaterialCpu = hd::GpuMaterial;
using GpuLightCpu = hd::GpuLight;

static_assert(sizeof(glm::vec4) == 16 && sizeof(glm::ivec4) == 16 && sizeof(glm::mat4) == 64);
static_assert(sizeof(GpuMaterialCpu) == 64);
static_assert(offsetof(GpuMaterialCpu, emissive) == 16);
static_assert(offsetof(GpuMaterialCpu, layers) == 32);
static_assert(offsetof(GpuMaterialCpu, layerSize) == 48);
static_assert(sizeof(GpuLightCpu) == 192);  // a multiple of 16: std140 arrays agree with std430
static_assert(offsetof(GpuLightCpu, direction) == 16);
static_assert(offsetof(GpuLightCpu, radiant) == 32);
static_assert(offsetof(GpuLightCpu, spot) == 48);
static_assert(offsetof(GpuLightCpu, frameX) == 64);
static_assert(offsetof(GpuLightCpu, frameY) == 80);
static_assert(offsetof(GpuLightCpu, info) == 96);
static_assert(offsetof(GpuLightCpu, shadow) == 112);
static_assert(offsetof(GpuLightCpu, shadowMatrix) == 128);

// A spot or point light at the eye itself (a flashlight held at the camera): its eye-relative position is 0
// in float, as the shaders get it. Every camera ray then starts at the light and is one of its light rays.
inline bool atEye(glm::vec3 eyeRelativePosition) { return glm::all(glm::equal(eyeRelativePosition, glm::vec3(0.0f))); }
inline bool atEye(const GpuLightCpu& L) {
    return L.info.x != hd::kLightDirectional && atEye(glm::vec3(L.position));
}

// The shaders' reach along a ray (reachAlongRay in common/lights.glsl) is the CPU's (scene/ray_reach.h).
static_assert(double(hd::kReachMeanFreePaths) == scene::kReachMeanFreePaths);

}  // namespace viz::render
