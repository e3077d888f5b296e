// What loadGltfFromMemory promises for any input, checked by the fuzz target and by the regression test:
// either a Scene whose every number is finite (and whose indices and references are in range), or a
// viz::InputError whose message is one line of at most kMaxErrorChars characters.
#pragma once

#include <cmath>
#include <cstddef>
#include <string>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace viz::scene::contract {

inline constexpr std::size_t kMaxErrorChars = 600;

// Empty when the message is acceptable, else what is wrong with it.
inline std::string errorMessageProblem(const std::string& message) {
    if (message.empty()) return "the message is empty";
    if (message.find('\n') != std::string::npos) return "the message has more than one line";
    if (message.size() > kMaxErrorChars) {
        return "the message has " + std::to_string(message.size()) + " characters (at most " +
               std::to_string(kMaxErrorChars) + ")";
    }
    return {};
}

namespace detail {

inline bool finite(double v) { return std::isfinite(v); }
template <int N, typename T>
bool finite(const glm::vec<N, T>& v) {
    for (int i = 0; i < N; ++i) {
        if (!std::isfinite(v[i])) return false;
    }
    return true;
}

// The index of the first non-finite element of a list, or -1.
template <typename List>
long firstNonFinite(const List& list) {
    for (std::size_t i = 0; i < list.size(); ++i) {
        if (!finite(list[i])) return long(i);
    }
    return -1;
}

inline bool validIndex(int index, std::size_t size) { return index >= -1 && index < int(size); }

}  // namespace detail

// Empty when the scene keeps the promise, else the first item that breaks it ("meshes[2].normals[7]").
inline std::string sceneProblem(const Scene& scene) {
    using detail::finite;
    using detail::firstNonFinite;
    using detail::validIndex;
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        const Mesh& mesh = scene.meshes[m];
        const std::string who = "meshes[" + std::to_string(m) + "]";
        if (long i = firstNonFinite(mesh.positions); i >= 0) return who + ".positions[" + std::to_string(i) + "]";
        if (long i = firstNonFinite(mesh.normals); i >= 0) return who + ".normals[" + std::to_string(i) + "]";
        if (long i = firstNonFinite(mesh.uvs); i >= 0) return who + ".uvs[" + std::to_string(i) + "]";
        if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size()) return who + ".normals (count)";
        if (!mesh.uvs.empty() && mesh.uvs.size() != mesh.positions.size()) return who + ".uvs (count)";
        if (mesh.indices.size() % 3 != 0) return who + ".indices (not whole triangles)";
        for (std::size_t i = 0; i < mesh.indices.size(); ++i) {
            if (mesh.indices[i] >= mesh.positions.size()) return who + ".indices[" + std::to_string(i) + "]";
        }
        if (!validIndex(mesh.material, scene.materials.size())) return who + ".material";
    }
    for (std::size_t m = 0; m < scene.materials.size(); ++m) {
        const Material& mat = scene.materials[m];
        const std::string who = "materials[" + std::to_string(m) + "]";
        if (!finite(mat.baseColorFactor)) return who + ".baseColorFactor";
        if (!finite(mat.emissiveFactor)) return who + ".emissiveFactor";
        if (!finite(mat.emissiveStrength)) return who + ".emissiveStrength";
        if (!validIndex(mat.baseColorTexture, scene.textures.size())) return who + ".baseColorTexture";
        if (!validIndex(mat.emissiveTexture, scene.textures.size())) return who + ".emissiveTexture";
    }
    for (std::size_t t = 0; t < scene.textures.size(); ++t) {
        const Texture& tex = scene.textures[t];
        if (tex.width <= 0 || tex.height <= 0 ||
            tex.rgba8.size() != std::size_t(tex.width) * std::size_t(tex.height) * 4) {
            return "textures[" + std::to_string(t) + "] (size)";
        }
    }
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
        const Light& light = scene.lights[l];
        const std::string who = "lights[" + std::to_string(l) + "]";
        if (!finite(light.position)) return who + ".position";
        if (!finite(light.direction)) return who + ".direction";
        if (!finite(light.colour)) return who + ".colour";
        if (!finite(light.intensity)) return who + ".intensity";
        if (!finite(light.innerConeAngle) || !finite(light.outerConeAngle)) return who + " (cone angles)";
        if (!finite(light.halfU) || !finite(light.halfV)) return who + " (half edges)";
        if (!finite(light.radiance)) return who + ".radiance";
        if (!validIndex(light.cookie, scene.textures.size())) return who + ".cookie";
        if (!validIndex(light.emissionTexture, scene.textures.size())) return who + ".emissionTexture";
        if (!validIndex(light.mesh, scene.meshes.size())) return who + ".mesh";
    }
    const Camera& cam = scene.camera;
    if (!finite(cam.position) || !finite(cam.forward) || !finite(cam.up)) return "camera (frame)";
    if (!finite(cam.yfov) || !finite(cam.znear) || !finite(cam.zfar) || !finite(cam.aspectRatio)) {
        return "camera (projection)";
    }
    const Medium& med = scene.medium;
    if (!finite(med.sigma_s) || !finite(med.sigma_a) || !finite(med.g)) return "medium";
    return {};
}

}  // namespace viz::scene::contract
