// glTF 2.0 import (.gltf with external or embedded resources, and .glb) into the flattened Scene.
#pragma once

#include <string>

#include "scene/scene.h"

namespace viz::scene {

// Loads the default scene (or scene 0) of a glTF file:
//  - meshes: every TRIANGLES primitive of every node in the scene's tree becomes one Mesh in world
//    space (positions by the node's world matrix, normals by its inverse transpose; winding reversed
//    when the matrix mirrors); other primitive modes are skipped with a note;
//  - materials: baseColorFactor/Texture, emissiveFactor/Texture, KHR_materials_emissive_strength;
//  - textures: one Scene texture per glTF texture (same index), decoded to RGBA8;
//  - camera: the first perspective camera in node order (zfar 1000 when absent); none: the scene is
//    framed and a note added;
//  - lights: KHR_lights_punctual lights in node order (light travels along the node's -Z; a spot's
//    cookie is "extras": {"cookie": texture index}), then one Area light per emissive mesh, in mesh
//    order (see area_light.h);
//  - medium: scenes[i].extras.medium = {"sigma_s", "sigma_a", "g"}; absent: 0.05, 0, 0 and a note.
// Every problem with the file throws viz::InputError with a one-line message naming the file and the
// item. The result has passed validateScene.
Scene loadGltf(const std::string& path);

}  // namespace viz::scene
