// Where one eye ray crosses a light volume, on the CPU: the grid triangles between texel centres (of a
// 2D map or of a cube's six faces) and the closure or the cube seams, with vertices placed as
// shaders/polyvol/volume_grid.glsl places them (float, from the same map values and VolumeGrid), and
// each crossing signed as the volume pass signs its fragment. It shows which faces a pixel's
// polyvol.crossings count (linked cursors). Eye-relative world space: the eye is the origin.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "render/host_device.h"
#include "techniques/polyvol/volume_grid.h"

namespace viz::polyvol {

struct VolumeCrossing {
    double t = 0.0;  // along the unit eye ray, from the eye
    // +1: the ray leaves the lit volume there (front face, adds +L(0, x)); -1: it enters (back face).
    int sign = 0;
};

// The crossings of the ray t w (t > 0, w unit) with the volume of `grid` (mode kModeSpot or
// kModeDirectional) built from `texels` (mapSize^2 stored values, row 0 = GL row 0), sorted by t. Static
// tessellation (keyStride == mapSize, adaptiveKeys null): the procedural grid. Adaptive (keyStride ==
// mapSize + 1): the triangles AdaptiveTessellation emitted, as their keys read back (3 per triangle).
// Either way plus the closure. Every crossing the rasteriser would count, also beyond the surface (the
// pass clamps them to d) and in front of the near plane (depth clamp). Not mirrored: cookie texels darker
// than cookie_mask (the GPU moves them to the light, closing the volume; here they stay).
std::vector<VolumeCrossing> volumeCrossings(const VolumeGrid& grid, const render::GpuLightCpu& light,
                                            const std::vector<float>& texels, const glm::dvec3& w,
                                            const std::vector<std::uint32_t>* adaptiveKeys = nullptr);

// The same for a cube (point light or VPL, mode kModeCube: six grids, static or their adaptive triangles'
// keys as for a 2D map, and the seams between them): `faces` are the six faces' stored values (+X -X +Y -Y
// +Z -Z, mapSize^2 each, row 0 = GL row 0).
std::vector<VolumeCrossing> cubeVolumeCrossings(const VolumeGrid& grid, const render::GpuLightCpu& light,
                                                const std::array<const std::vector<float>*, 6>& faces,
                                                const glm::dvec3& w,
                                                const std::vector<std::uint32_t>* adaptiveKeys = nullptr);

}  // namespace viz::polyvol
