// Pieces of glTF import that fix up or fill in what a file gives (internal to viz_scene): images to
// RGBA8, a camera for files without one, normals for vertices whose normal is zero.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace tinygltf {
struct Image;
}

namespace viz::scene::gltf {

// Decoded image (1-4 channels of 8 or 16 bits) to RGBA8: grey replicates into R, G, B; missing alpha is
// opaque; 16-bit values are rounded to 8 bits. The caller checked that image.image holds
// width * height * component * bits/8 bytes.
std::vector<std::uint8_t> toRgba8(const tinygltf::Image& image);

// A camera that sees the whole bounding box, looking at its centre from above and to the side.
Camera frameScene(const Scene& scene);

// Replaces zero-length (or non-finite) normals by the area-weighted normal of the triangles that use
// the vertex, or +Y when those are degenerate too; returns how many were replaced.
std::size_t repairNormals(Mesh& mesh);

}  // namespace viz::scene::gltf
