#include "scene/area_light.h"

#include <array>
#include <cmath>
#include <string>

#include "core/error.h"

namespace viz::scene {
namespace {

std::string meshLabel(const Scene& scene, int meshIndex) {
    const Mesh& mesh = scene.meshes[std::size_t(meshIndex)];
    return "emissive mesh " + std::to_string(meshIndex) + (mesh.name.empty() ? "" : " '" + mesh.name + "'");
}

[[noreturn]] void notRectangle(const Scene& scene, int meshIndex, const std::string& why) {
    throw InputError(meshLabel(scene, meshIndex) + " is not a planar rectangle (area lights must be): " + why);
}

}  // namespace

Light areaLightFromMesh(const Scene& scene, int meshIndex) {
    VIZ_CHECK(meshIndex >= 0 && std::size_t(meshIndex) < scene.meshes.size(), "mesh index out of range");
    const Mesh& mesh = scene.meshes[std::size_t(meshIndex)];
    VIZ_CHECK(mesh.material >= 0 && std::size_t(mesh.material) < scene.materials.size(),
              "area light mesh without material");
    const Material& material = scene.materials[std::size_t(mesh.material)];

    if (mesh.indices.size() != 6) {
        notRectangle(scene, meshIndex, std::to_string(mesh.indices.size() / 3) + " triangles instead of 2");
    }
    // Distinct positions, in order of first use by the index list; slot[k] maps index k to its corner.
    std::array<glm::dvec3, 4> corner{};
    std::array<int, 4> cornerVertex{};
    std::array<int, 6> slot{};
    int distinct = 0;
    for (std::size_t k = 0; k < 6; ++k) {
        const std::uint32_t vi = mesh.indices[k];
        if (vi >= mesh.positions.size()) notRectangle(scene, meshIndex, "index out of range");
        const glm::dvec3 p(mesh.positions[vi]);
        int found = -1;
        for (int c = 0; c < distinct; ++c) {
            if (corner[std::size_t(c)] == p) found = c;
        }
        if (found < 0) {
            if (distinct == 4) notRectangle(scene, meshIndex, "more than 4 distinct vertices");
            corner[std::size_t(distinct)] = p;
            cornerVertex[std::size_t(distinct)] = int(vi);
            found = distinct++;
        }
        slot[k] = found;
    }
    if (distinct != 4) notRectangle(scene, meshIndex, std::to_string(distinct) + " distinct vertices instead of 4");

    // Winding normals of both triangles (counter-clockwise = front, glTF's convention).
    auto triNormal = [&](int t) {
        const glm::dvec3 a = corner[std::size_t(slot[std::size_t(3 * t)])];
        const glm::dvec3 b = corner[std::size_t(slot[std::size_t(3 * t + 1)])];
        const glm::dvec3 c = corner[std::size_t(slot[std::size_t(3 * t + 2)])];
        return glm::cross(b - a, c - a);
    };
    const glm::dvec3 n0 = triNormal(0), n1 = triNormal(1);
    if (glm::length(n0) == 0.0 || glm::length(n1) == 0.0) notRectangle(scene, meshIndex, "degenerate triangle");
    const glm::dvec3 normal = glm::normalize(n0 + n1);
    if (glm::dot(glm::normalize(n0), glm::normalize(n1)) < 0.9999) {
        notRectangle(scene, meshIndex, "its triangles are not coplanar or not wound the same way");
    }

    // The diagonal is the pair of corners shared by both triangles; the other two are opposite corners.
    int shared[2], sharedCount = 0;
    for (int c = 0; c < 4; ++c) {
        bool inFirst = false, inSecond = false;
        for (int k = 0; k < 3; ++k) inFirst |= slot[std::size_t(k)] == c;
        for (int k = 3; k < 6; ++k) inSecond |= slot[std::size_t(k)] == c;
        if (inFirst && inSecond && sharedCount < 2) shared[sharedCount++] = c;
    }
    if (sharedCount != 2) notRectangle(scene, meshIndex, "its triangles do not share a diagonal");
    int others[2], otherCount = 0;
    for (int c = 0; c < 4; ++c) {
        if (c != shared[0] && c != shared[1]) others[otherCount++] = c;
    }
    const glm::dvec3 a = corner[std::size_t(shared[0])], c = corner[std::size_t(shared[1])];
    const glm::dvec3 b = corner[std::size_t(others[0])], d = corner[std::size_t(others[1])];
    const double size = glm::length(c - a);
    const double tol = 1e-4 * size;
    // A parallelogram has diagonals bisecting each other; a rectangle also has equal diagonals.
    if (glm::length((a + c) - (b + d)) > 2.0 * tol || std::abs(glm::length(c - a) - glm::length(d - b)) > tol) {
        notRectangle(scene, meshIndex, "its corners do not form a rectangle");
    }

    Light light;
    light.name = mesh.name;
    light.type = LightType::Area;
    light.mesh = meshIndex;
    light.direction = normal;
    light.position = 0.5 * (a + c);
    light.radiance = glm::dvec3(material.emissiveFactor) * double(material.emissiveStrength);
    light.emissionTexture = material.emissiveTexture;

    // uv-driven edges when the uvs put the corners on the unit square's corners.
    bool uvLayout = false;
    if (mesh.uvs.size() == mesh.positions.size()) {
        int at[2][2] = {{-1, -1}, {-1, -1}};
        bool ok = true;
        for (int k = 0; k < 4 && ok; ++k) {
            const glm::dvec2 uv(mesh.uvs[std::size_t(cornerVertex[std::size_t(k)])]);
            const int iu = std::abs(uv.x) < 1e-6 ? 0 : (std::abs(uv.x - 1.0) < 1e-6 ? 1 : -1);
            const int iv = std::abs(uv.y) < 1e-6 ? 0 : (std::abs(uv.y - 1.0) < 1e-6 ? 1 : -1);
            if (iu < 0 || iv < 0 || at[iu][iv] >= 0) {
                ok = false;
            } else {
                at[iu][iv] = k;
            }
        }
        if (ok) {
            const glm::dvec3 p00 = corner[std::size_t(at[0][0])];
            light.halfU = 0.5 * (corner[std::size_t(at[1][0])] - p00);
            light.halfV = 0.5 * (corner[std::size_t(at[0][1])] - p00);
            uvLayout = true;
        }
    }
    if (!uvLayout) {
        if (light.emissionTexture >= 0) {
            throw InputError(meshLabel(scene, meshIndex) +
                             " has an emission texture but its uvs do not map the corners to (0,0), (1,0), "
                             "(0,1), (1,1)");
        }
        light.halfU = 0.5 * (b - a);
        light.halfV = 0.5 * (d - a);
        if (glm::dot(glm::cross(light.halfU, light.halfV), normal) < 0.0) std::swap(light.halfU, light.halfV);
    }
    const double lu = glm::length(light.halfU), lv = glm::length(light.halfV);
    if (lu == 0.0 || lv == 0.0 || std::abs(glm::dot(light.halfU, light.halfV)) > 1e-4 * lu * lv) {
        notRectangle(scene, meshIndex, "its edges are not perpendicular");
    }
    return light;
}

}  // namespace viz::scene
