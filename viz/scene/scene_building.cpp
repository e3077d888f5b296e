#include "scene/scene_building.h"

#include <cmath>
#include <cstdint>
#include <utility>

namespace viz::scene {

Camera lookAt(const std::string& name, glm::dvec3 eye, glm::dvec3 target, double yfov, double znear, double zfar) {
    Camera cam;
    cam.name = name;
    cam.position = eye;
    cam.forward = glm::normalize(target - eye);
    const glm::dvec3 worldUp = std::abs(cam.forward.y) > 0.999 ? glm::dvec3(0, 0, -1) : glm::dvec3(0, 1, 0);
    cam.up = glm::normalize(worldUp - glm::dot(worldUp, cam.forward) * cam.forward);
    cam.yfov = yfov;
    cam.znear = znear;
    cam.zfar = zfar;
    return cam;
}

MeshBuilder::MeshBuilder(std::string name, int material) {
    mMesh.name = std::move(name);
    mMesh.material = material;
}

void MeshBuilder::quad(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, glm::dvec3 d) {
    const glm::vec3 n(glm::normalize(glm::cross(b - a, c - a)));
    const auto base = std::uint32_t(mMesh.positions.size());
    const glm::dvec3 p[4] = {a, b, c, d};
    const glm::vec2 uv[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int i = 0; i < 4; ++i) {
        mMesh.positions.push_back(glm::vec3(p[i]));
        mMesh.normals.push_back(n);
        mMesh.uvs.push_back(uv[i]);
    }
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mMesh.indices.push_back(base + i);
}

void MeshBuilder::box(glm::dvec3 centre, glm::dvec3 half, double yaw, bool inward) {
    const double c = std::cos(yaw), s = std::sin(yaw);
    auto place = [&](glm::dvec3 q) {  // local -> world: rotate about Y, then translate
        return centre + glm::dvec3(c * q.x + s * q.z, q.y, -s * q.x + c * q.z);
    };
    // For each face: normal n and tangents u, v with cross(u, v) = n.
    const glm::dvec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);
    const glm::dvec3 faces[6][3] = {{X, Y, Z}, {-X, Z, Y}, {Y, Z, X}, {-Y, X, Z}, {Z, X, Y}, {-Z, Y, X}};
    for (const auto& f : faces) {
        const glm::dvec3 n = f[0] * half, u = f[1] * half, v = f[2] * half;
        glm::dvec3 q[4] = {n - u - v, n + u - v, n + u + v, n - u + v};
        if (inward) std::swap(q[1], q[3]);
        quad(place(q[0]), place(q[1]), place(q[2]), place(q[3]));
    }
}

void MeshBuilder::triangle(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
    const glm::dvec3 cross = glm::cross(b - a, c - a);
    const double length = glm::length(cross);
    const glm::vec3 n = length > 0.0 ? glm::vec3(cross / length) : glm::vec3(0, 1, 0);
    const auto base = std::uint32_t(mMesh.positions.size());
    for (const glm::dvec3& p : {a, b, c}) {
        mMesh.positions.push_back(glm::vec3(p));
        mMesh.normals.push_back(n);
        mMesh.uvs.push_back({0.0f, 0.0f});
    }
    for (std::uint32_t i : {0u, 1u, 2u}) mMesh.indices.push_back(base + i);
}

}  // namespace viz::scene
