// Topology of a polygonal light volume (Billeter et al. 2010, section 4), pure CPU, mirrored by
// shaders/polyvol/volume.vert. The mesh has no vertex buffer: a vertex is a 32-bit key that the vertex
// shader turns into a position by reading the shadow map.
//
//   grid vertex (face f, texel i, j):  key = f N^2 + j N + i        (f = 0 for 2D maps, 0..5 for cubes)
//   cap vertex under texel (i, j):     key = 6 N^2 + j N + i        (directional: the texel's column moved
//                                                                    back to the cap plane behind the scene)
//   apex:                              key = kApexKey               (spot, point: the light; directional:
//                                                                    the centre of the cap)
//
// Grid triangles are generated from gl_VertexID (two per quad of four neighbouring texel centres, split
// along the (i, j) -> (i + 1, j + 1) diagonal); every other triangle (the closure of a 2D map's grid, the
// seams between the six faces of a cube) is an explicit list of keys. Orientation: every triangle is
// counter-clockwise seen from inside the lit volume (from the light), so a camera that sees a triangle
// as front-facing is inside that triangle's half-space and its ray leaves the volume there.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace viz::polyvol {

inline constexpr std::uint32_t kApexKey = 0xFFFFFFFFu;

inline std::uint32_t gridKey(int size, int face, int i, int j) {
    return std::uint32_t(face) * std::uint32_t(size) * std::uint32_t(size) + std::uint32_t(j) * std::uint32_t(size) +
           std::uint32_t(i);
}
inline std::uint32_t capKey(int size, int i, int j) { return gridKey(size, 6, i, j); }

// Triangles drawn from gl_VertexID for `faces` grids of size x size texels.
inline std::int64_t gridTriangleCount(int size, int faces) {
    return std::int64_t(faces) * 2 * std::int64_t(size - 1) * std::int64_t(size - 1);
}

// The closure of one 2D grid: for each of the 4 (N - 1) border edges a -> b (walked counter-clockwise
// seen from the light: bottom row left to right, right column up, top row right to left, left column
// down), the wall (b, a, a'), (b, a', b') and the cap triangle (b', a', apex), a' = cap vertex under a.
// For a spot light cap vertices and apex are all the light position, so walls become the fan from the
// border to the light and cap triangles are degenerate (zero area, they rasterise nothing).
std::vector<std::uint32_t> gridClosure(int size);

// The seams of a cube's six grids: for each of the 12 cube edges a strip of 2 (N - 1) triangles joining
// the border texels of the two faces, and for each of the 8 corners one triangle joining the three corner
// texels. Each triangle is oriented counter-clockwise seen from the light (checked with the texel
// directions). Together with the grids this is a closed, T-junction-free surface around the light; so it
// is with adaptively refined faces, whose border texels all stay vertices. Keys with `keyStride` texels
// per row (N static, N + 1 adaptive; 0 means N).
std::vector<std::uint32_t> cubeSeams(int size, int keyStride = 0);

// Unit direction from the light through texel (i, j) of cube face `face` (0..5 = +X, -X, +Y, -Y, +Z,
// -Z; the basis of render::ShadowMaps::cubeFaceBasis and shaders/common/shadow_map.glsl).
glm::dvec3 cubeTexelDirection(int size, int face, double i, double j);

// The face and texel that shaders/common/shadow_map.glsl cubeLookup reads for direction d.
struct CubeTexel {
    int face = 0, i = 0, j = 0;
};
CubeTexel cubeTexelOf(int size, const glm::dvec3& d);

}  // namespace viz::polyvol
