// Which of a glTF's textures and images Airlight draws: a material's base colour and emission, and a
// spot light's cookie (extras.cookie). Everything else (normal, occlusion and metallic-roughness maps,
// images reached only through an extension such as MSFT_texture_dds or KHR_texture_basisu) is neither
// decoded nor required to exist, so a model that ships such maps, or lacks one of them, still loads.
// Internal to viz_scene: both halves of the loader read it (gltf_input to decode only the images in
// use, gltf_loader to keep only the textures in use).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace viz::scene::gltf {

struct TextureUse {
    std::vector<bool> textures;  // per glTF texture: drawn by some material or light
    std::vector<bool> images;    // per glTF image: the core `source` of a drawn texture
    // One note saying what is not loaded and why; empty when everything is used.
    std::string note() const;
};

// From the document before tinygltf parses it. Indices that are out of range or of the wrong type are
// left to the loader's own checks (they name the field); here they mark nothing.
TextureUse textureUse(const nlohmann::json& doc);

}  // namespace viz::scene::gltf
