// glTF 2.0 import (.gltf with external or embedded resources, and .glb) into the flattened Scene.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene/limits.h"
#include "scene/scene.h"

namespace viz::scene {

// What the loader may decide on its own when a file lacks something a render needs.
struct LoadOptions {
    // A file with no light (no KHR_lights_punctual light used by a node, no emissive mesh) gets a default
    // spot light aimed at the model from above (with a note); false: such a file is an error.
    bool defaultLight = true;
};


// Loads the default scene (or scene 0) of a glTF file:
//  - meshes: every TRIANGLES primitive of every node in the scene's tree becomes one Mesh in world
//    space (positions by the node's world matrix, normals by its inverse transpose; winding reversed
//    when the matrix mirrors); other primitive modes are skipped with a note; zero-length normals are
//    replaced by their triangle's normal with a note;
//  - materials: baseColorFactor/Texture, emissiveFactor/Texture, KHR_materials_emissive_strength;
//  - textures: one Scene texture per glTF texture (same index), decoded to RGBA8;
//  - camera: the first perspective camera in node order (zfar 1000 when absent); none: the scene is
//    framed and a note added;
//  - lights: KHR_lights_punctual lights in node order (light travels along the node's -Z; a spot's
//    cookie is "extras": {"cookie": texture index}), then one Area light per emissive mesh that is a
//    planar rectangle, in mesh order (see area_light.h; other emissive meshes shade as emissive
//    surfaces, with a note); none at all: a default light (LoadOptions);
//  - medium: scenes[i].extras.medium = {"sigma_s", "sigma_a", "g"}; absent: sigma_s chosen so that the
//    optical depth across the bounding box is 0.5, with a note; unknown keys and non-numbers are notes.
// The file is checked before it is read: JSON depth, the node graph (a forest), every accessor's and
// bufferView's range with overflow-safe arithmetic, URIs (inside the file's folder, regular files), sizes
// (LoadLimits), finite and non-negative values where glTF requires them. Every problem throws
// viz::InputError with a one-line message naming the file and the item (values quoted to at most 120
// characters). The result has passed validateScene.
Scene loadGltf(const std::string& path, const LoadOptions& options = {});

// The same from bytes in memory (binary: GLB, else glTF JSON). fileName names the file in messages;
// baseDir resolves relative URIs, and an empty baseDir refuses every external file (data: URIs only).
Scene loadGltfFromMemory(const std::vector<unsigned char>& bytes, const std::string& fileName,
                         const std::string& baseDir, bool binary, const LoadOptions& options = {});

}  // namespace viz::scene
