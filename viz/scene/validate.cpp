#include "scene/validate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/error.h"
#include "scene/limits.h"

namespace viz::scene {
namespace {

bool finite3(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Within the coordinate limit (GPU floats square distances: 1e15^2 still fits).
bool placeable(const glm::dvec3& v) {
    const double m = LoadLimits::kMaxCoordinate;
    return std::abs(v.x) <= m && std::abs(v.y) <= m && std::abs(v.z) <= m;
}

std::string num(double v) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.6g", v);
    return text;
}

std::string meshLabel(const Mesh& mesh, std::size_t i) {
    return "mesh " + std::to_string(i) + (mesh.name.empty() ? "" : " '" + mesh.name + "'");
}

std::string lightLabel(const Light& light, std::size_t i) {
    return "light " + std::to_string(i) + (light.name.empty() ? "" : " '" + light.name + "'");
}

void checkTextureIndex(const Scene& scene, int index, const std::string& who, const char* what) {
    if (index < -1 || index >= int(scene.textures.size())) {
        throw InputError(who + ": " + what + " texture " + std::to_string(index) + " does not exist");
    }
}

}  // namespace

void validateScene(const Scene& scene) {
    const std::string where = "scene '" + scene.name + "': ";

    for (std::size_t t = 0; t < scene.textures.size(); ++t) {
        const Texture& tex = scene.textures[t];
        if (tex.width <= 0 || tex.height <= 0 ||
            tex.rgba8.size() != std::size_t(tex.width) * std::size_t(tex.height) * 4) {
            throw InputError(where + "texture " + std::to_string(t) + " has no valid RGBA8 pixels");
        }
    }
    for (std::size_t m = 0; m < scene.materials.size(); ++m) {
        const Material& mat = scene.materials[m];
        const std::string who = where + "material " + std::to_string(m);
        checkTextureIndex(scene, mat.baseColorTexture, who, "base colour");
        checkTextureIndex(scene, mat.emissiveTexture, who, "emissive");
        if (!finite3(glm::dvec3(mat.baseColorFactor)) || !finite3(glm::dvec3(mat.emissiveFactor)) ||
            !std::isfinite(mat.emissiveStrength)) {
            throw InputError(who + " has a NaN or Inf factor");
        }
        const glm::dvec4 base(mat.baseColorFactor);
        const glm::dvec3 emit(mat.emissiveFactor);
        if (base.x < 0 || base.y < 0 || base.z < 0 || base.w < 0 || emit.x < 0 || emit.y < 0 || emit.z < 0 ||
            mat.emissiveStrength < 0) {
            throw InputError(who + " has a negative colour factor or emissive strength");
        }
        if (std::max({emit.x, emit.y, emit.z}) * double(mat.emissiveStrength) > LoadLimits::kMaxRadiance) {
            throw InputError(who + ": emissive factor x strength is over the limit of 1e20");
        }
    }

    std::size_t triangles = 0;
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        const Mesh& mesh = scene.meshes[m];
        const std::string who = where + meshLabel(mesh, m);
        for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
            if (!finite3(glm::dvec3(mesh.positions[v]))) {
                throw InputError(who + ": vertex " + std::to_string(v) + " is NaN or Inf");
            }
            if (!placeable(glm::dvec3(mesh.positions[v]))) {
                throw InputError(who + ": vertex " + std::to_string(v) + " lies beyond 1e15 from the origin");
            }
        }
        for (std::size_t v = 0; v < mesh.normals.size(); ++v) {
            if (!finite3(glm::dvec3(mesh.normals[v]))) {
                throw InputError(who + ": normal " + std::to_string(v) + " is NaN or Inf");
            }
        }
        for (std::size_t v = 0; v < mesh.uvs.size(); ++v) {
            if (!std::isfinite(mesh.uvs[v].x) || !std::isfinite(mesh.uvs[v].y)) {
                throw InputError(who + ": uv " + std::to_string(v) + " is NaN or Inf");
            }
        }
        if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size()) {
            throw InputError(who + ": " + std::to_string(mesh.normals.size()) + " normals for " +
                             std::to_string(mesh.positions.size()) + " positions");
        }
        if (!mesh.uvs.empty() && mesh.uvs.size() != mesh.positions.size()) {
            throw InputError(who + ": " + std::to_string(mesh.uvs.size()) + " uvs for " +
                             std::to_string(mesh.positions.size()) + " positions");
        }
        if (mesh.indices.size() % 3 != 0) {
            throw InputError(who + ": index count " + std::to_string(mesh.indices.size()) +
                             " is not a multiple of 3");
        }
        for (std::uint32_t index : mesh.indices) {
            if (index >= mesh.positions.size()) {
                throw InputError(who + ": index " + std::to_string(index) + " is out of range (" +
                                 std::to_string(mesh.positions.size()) + " vertices)");
            }
        }
        if (mesh.material < -1 || mesh.material >= int(scene.materials.size())) {
            throw InputError(who + ": material " + std::to_string(mesh.material) + " does not exist");
        }
        triangles += mesh.indices.size() / 3;
    }
    if (triangles == 0) throw InputError(where + "no triangles: the scene has no triangle geometry");

    if (scene.lights.empty()) {
        throw InputError(where +
                         "no light: the scene has neither a punctual light (KHR_lights_punctual) nor an "
                         "emissive mesh");
    }
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
        const Light& light = scene.lights[l];
        const std::string who = where + lightLabel(light, l);
        if (!finite3(light.position) || !finite3(light.direction) || !finite3(light.colour) ||
            !std::isfinite(light.intensity) || !finite3(light.halfU) || !finite3(light.halfV) ||
            !finite3(light.radiance)) {
            throw InputError(who + " has a NaN or Inf value");
        }
        if (std::abs(glm::length(light.direction) - 1.0) > 1e-6) {
            throw InputError(who + ": direction is not a unit vector");
        }
        if (light.intensity < 0.0 || light.colour.x < 0.0 || light.colour.y < 0.0 || light.colour.z < 0.0) {
            throw InputError(who + ": negative intensity or colour");
        }
        if (!placeable(light.position)) throw InputError(who + ": position lies beyond 1e15 from the origin");
        const double peak = light.intensity * std::max({light.colour.x, light.colour.y, light.colour.z});
        if (peak > LoadLimits::kMaxRadiance) {
            throw InputError(who + ": intensity x colour = " + num(peak) + " is over the limit of 1e20 (GPU floats overflow)");
        }
        if (light.type == LightType::Area && glm::length(light.radiance) > LoadLimits::kMaxRadiance) {
            throw InputError(who + ": emitted radiance is over the limit of 1e20");
        }
        if (light.type == LightType::Spot) {
            if (!(light.innerConeAngle >= 0.0 && light.innerConeAngle <= light.outerConeAngle &&
                  light.outerConeAngle > 0.0 && light.outerConeAngle <= 0.5 * 3.14159265358979323846 + 1e-12)) {
                throw InputError(who + ": spot cone angles must satisfy 0 <= inner <= outer <= pi/2, outer > 0");
            }
        }
        if (light.cookie != -1) {
            if (light.type != LightType::Spot) throw InputError(who + ": only spot lights can have a cookie");
            checkTextureIndex(scene, light.cookie, who, "cookie");
        }
        if (light.type == LightType::Area) {
            if (light.mesh < 0 || light.mesh >= int(scene.meshes.size())) {
                throw InputError(who + ": area light without its emitter mesh");
            }
            checkTextureIndex(scene, light.emissionTexture, who, "emission");
            if (glm::length(light.halfU) == 0.0 || glm::length(light.halfV) == 0.0) {
                throw InputError(who + ": area light with a zero-size rectangle");
            }
        }
    }

    const Medium& medium = scene.medium;
    if (!std::isfinite(medium.sigma_s) || medium.sigma_s < 0.0) {
        throw InputError(where + "medium sigma_s must be finite and >= 0 (got " + std::to_string(medium.sigma_s) + ")");
    }
    if (!std::isfinite(medium.sigma_a) || medium.sigma_a < 0.0) {
        throw InputError(where + "medium sigma_a must be finite and >= 0 (got " + std::to_string(medium.sigma_a) + ")");
    }
    if (medium.sigma_s > LoadLimits::kMaxSigma || medium.sigma_a > LoadLimits::kMaxSigma) {
        throw InputError(where + "medium sigma_s and sigma_a must be at most 1e12 per scene unit (got " + num(medium.sigma_s) +
                         ", " + num(medium.sigma_a) + ")");
    }
    if (!(std::abs(medium.g) < 1.0)) {
        throw InputError(where + "medium g must satisfy |g| < 1 (got " + std::to_string(medium.g) + ")");
    }

    const Camera& cam = scene.camera;
    if (!finite3(cam.position) || !finite3(cam.forward) || !finite3(cam.up) || !std::isfinite(cam.yfov) ||
        !std::isfinite(cam.znear) || !std::isfinite(cam.zfar) || !std::isfinite(cam.aspectRatio)) {
        throw InputError(where + "camera has a NaN or Inf value");
    }
    if (!placeable(cam.position)) throw InputError(where + "camera position lies beyond 1e15 from the origin");
    if (!(cam.yfov > 0.0 && cam.yfov < 3.14159265358979323846)) {
        throw InputError(where + "camera yfov must be in (0, pi)");
    }
    if (!(cam.znear > 0.0 && cam.zfar > cam.znear)) {
        throw InputError(where + "camera needs 0 < znear < zfar");
    }
    if (cam.aspectRatio < 0.0) throw InputError(where + "camera aspectRatio must be >= 0");
    if (std::abs(glm::length(cam.forward) - 1.0) > 1e-6 || std::abs(glm::length(cam.up) - 1.0) > 1e-6 ||
        std::abs(glm::dot(cam.forward, cam.up)) > 1e-6) {
        throw InputError(where + "camera forward and up must be orthogonal unit vectors");
    }
}

}  // namespace viz::scene
