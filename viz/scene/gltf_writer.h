// glTF 2.0 export of a Scene: .gltf (one file, buffer and PNG images embedded as base64 data URIs) or
// .glb, chosen by the extension. Loading the file back with loadGltf gives the same scene: every value
// is written exactly (floats in binary buffers, doubles in shortest round-trip JSON form).
#pragma once

#include <string>

#include "scene/scene.h"

namespace viz::scene {

// Layout: one node per mesh (identity transform; geometry already in world space), then one node per
// punctual light, then the camera node; area lights are written only as their emissive mesh (the
// material is the source of their radiance). Lights load back punctual first, then area lights in
// mesh order, so a scene that keeps that order round-trips exactly.
// The file is written to a temporary name in the same folder and renamed, so a failure never leaves
// a partial file. Throws viz::InputError when the folder does not exist or cannot be written, or when
// the extension is neither .gltf nor .glb.
void writeGltf(const Scene& scene, const std::string& path);

}  // namespace viz::scene
