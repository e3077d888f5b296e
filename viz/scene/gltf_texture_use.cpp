#include "scene/gltf_texture_use.h"

#include <algorithm>

#include <nlohmann/json.hpp>

namespace viz::scene::gltf {
namespace {

using Json = nlohmann::json;

// doc[key] when it is an array, else null.
const Json* array(const Json& doc, const char* key) {
    if (!doc.is_object()) return nullptr;
    const auto it = doc.find(key);
    return it != doc.end() && it->is_array() ? &*it : nullptr;
}

// obj[key] when obj is an object that has it, else null.
const Json* member(const Json* obj, const char* key) {
    if (!obj || !obj->is_object()) return nullptr;
    const auto it = obj->find(key);
    return it != obj->end() ? &*it : nullptr;
}

void mark(std::vector<bool>& used, const Json* index) {
    if (!index || !index->is_number_integer()) return;
    const auto i = index->get<long long>();
    if (i >= 0 && std::size_t(i) < used.size()) used[std::size_t(i)] = true;
}

std::size_t unused(const std::vector<bool>& used) { return std::size_t(std::count(used.begin(), used.end(), false)); }

std::string count(std::size_t n, const char* what) { return std::to_string(n) + " " + what + (n == 1 ? "" : "s"); }

}  // namespace

std::string TextureUse::note() const {
    const std::size_t t = unused(textures), i = unused(images);
    if (t == 0 && i == 0) return {};
    std::string what;
    if (t > 0) what = count(t, "texture") + " of " + std::to_string(textures.size());
    if (i > 0) what += (what.empty() ? "" : " and ") + count(i, "image") + " of " + std::to_string(images.size());
    return what + " not loaded: Airlight draws only base colour, emission and spot-light cookies "
                  "(normal, metallic-roughness and extension-only maps are left out)";
}

TextureUse textureUse(const Json& doc) {
    TextureUse use;
    const Json* textures = array(doc, "textures");
    const Json* images = array(doc, "images");
    use.textures.assign(textures ? textures->size() : 0, false);
    use.images.assign(images ? images->size() : 0, false);
    if (const Json* materials = array(doc, "materials")) {
        for (const Json& m : *materials) {
            mark(use.textures, member(member(member(&m, "pbrMetallicRoughness"), "baseColorTexture"), "index"));
            mark(use.textures, member(member(&m, "emissiveTexture"), "index"));
        }
    }
    const Json* lights = member(member(member(&doc, "extensions"), "KHR_lights_punctual"), "lights");
    if (lights && lights->is_array()) {
        for (const Json& l : *lights) mark(use.textures, member(member(&l, "extras"), "cookie"));
    }
    for (std::size_t t = 0; t < use.textures.size(); ++t) {
        if (use.textures[t]) mark(use.images, member(&(*textures)[t], "source"));
    }
    return use;
}

}  // namespace viz::scene::gltf
