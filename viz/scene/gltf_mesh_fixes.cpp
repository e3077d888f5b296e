#include "scene/gltf_mesh_fixes.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <tiny_gltf.h>

#include "scene/bounds.h"

namespace viz::scene::gltf {

std::vector<std::uint8_t> toRgba8(const tinygltf::Image& image) {
    const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
    const std::size_t channels = std::size_t(image.component);
    const bool wide = image.bits == 16;
    auto channel = [&](std::size_t p, std::size_t c) -> std::uint8_t {
        const std::size_t at = p * channels + c;
        if (!wide) return image.image[at];
        std::uint16_t w;
        std::memcpy(&w, &image.image[2 * at], 2);
        return std::uint8_t((unsigned(w) + 128u) / 257u);
    };
    std::vector<std::uint8_t> out(pixels * 4);
    for (std::size_t p = 0; p < pixels; ++p) {
        std::uint8_t* o = &out[p * 4];
        if (channels <= 2) {
            o[0] = o[1] = o[2] = channel(p, 0);
            o[3] = channels == 2 ? channel(p, 1) : 255;
        } else {
            for (std::size_t c = 0; c < 3; ++c) o[c] = channel(p, c);
            o[3] = channels == 4 ? channel(p, 3) : 255;
        }
    }
    return out;
}

Camera frameScene(const Scene& scene) {
    const Bounds b = sceneBounds(scene);
    const glm::dvec3 centre = b.centre();
    // Scale-free: a model a tenth of a millimetre across is framed as one of ten metres is. Only a scene
    // with no extent (every vertex in one point) gets a unit radius.
    const double extent = 0.5 * b.diagonal();
    const double radius = extent > 0.0 && std::isfinite(extent) ? extent : 1.0;
    Camera cam;
    cam.name = "framed";
    cam.yfov = 0.8;
    const glm::dvec3 fromCentre = glm::normalize(glm::dvec3(0.6, 0.45, 1.0));
    // Distance at which a sphere of the given radius fits in the vertical field of view.
    const double distance = 1.1 * radius / std::sin(0.5 * cam.yfov);
    cam.position = centre + distance * fromCentre;
    cam.forward = -fromCentre;
    cam.up = glm::normalize(glm::dvec3(0, 1, 0) - glm::dot(glm::dvec3(0, 1, 0), cam.forward) * cam.forward);
    cam.znear = 0.01 * radius;
    cam.zfar = distance + 2.0 * radius;
    return cam;
}

std::size_t repairNormals(Mesh& mesh) {
    std::vector<bool> bad(mesh.normals.size());
    std::size_t count = 0;
    for (std::size_t v = 0; v < mesh.normals.size(); ++v) {
        const glm::vec3& n = mesh.normals[v];
        bad[v] = !(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z)) || glm::dot(n, n) < 1e-24f;
        count += bad[v];
    }
    if (count == 0) return 0;
    std::vector<glm::dvec3> sum(mesh.normals.size(), glm::dvec3(0.0));
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        const glm::dvec3 face = glm::cross(glm::dvec3(mesh.positions[b]) - glm::dvec3(mesh.positions[a]),
                                           glm::dvec3(mesh.positions[c]) - glm::dvec3(mesh.positions[a]));
        for (std::uint32_t v : {a, b, c}) {
            if (bad[v]) sum[v] += face;
        }
    }
    for (std::size_t v = 0; v < mesh.normals.size(); ++v) {
        if (!bad[v]) continue;
        const double len = glm::length(sum[v]);
        mesh.normals[v] = len > 0.0 && std::isfinite(len) ? glm::vec3(sum[v] / len) : glm::vec3(0, 1, 0);
    }
    return count;
}

}  // namespace viz::scene::gltf
