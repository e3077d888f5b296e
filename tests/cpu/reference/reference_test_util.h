// Small scenes and helpers shared by the reference tests.
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace viz::reference_test {

// Adds an axis-aligned box as 12 triangles (outward winding not needed: Embree sees both sides).
inline void addBox(scene::Scene& s, glm::vec3 lo, glm::vec3 hi, int material) {
    scene::Mesh m;
    m.name = "box";
    m.material = material;
    for (int i = 0; i < 8; ++i)
        m.positions.emplace_back((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
    const std::uint32_t faces[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                                       {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    for (const auto& f : faces) {
        m.indices.insert(m.indices.end(), {f[0], f[1], f[2], f[0], f[2], f[3]});
    }
    s.meshes.push_back(std::move(m));
}

// A floor, a slab of bars 2 units above it (a grate: light shafts between the bars) and a spot light
// above the slab, looked at obliquely so that pixel rays cross several shadow boundaries.
inline scene::Scene makeSlabScene() {
    scene::Scene s;
    s.name = "slab";
    scene::Material white;
    white.name = "white";
    white.baseColorFactor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
    s.materials.push_back(white);
    // Floor: one quad, 10 x 10, with normals and uvs.
    scene::Mesh floor;
    floor.name = "floor";
    floor.material = 0;
    floor.positions = {{-5, 0, -5}, {5, 0, -5}, {5, 0, 5}, {-5, 0, 5}};
    floor.normals.assign(4, glm::vec3(0, 1, 0));
    floor.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    floor.indices = {0, 2, 1, 0, 3, 2};
    s.meshes.push_back(floor);
    // Bars along z, 0.3 wide with 0.4 gaps, at y in [2, 2.1].
    for (int i = -4; i <= 4; ++i) {
        const float x = 0.7f * float(i);
        addBox(s, {x - 0.15f, 2.0f, -3.0f}, {x + 0.15f, 2.1f, 3.0f}, 0);
    }
    scene::Light spot{.name = "spot",
                      .type = scene::LightType::Spot,
                      .position = {0.2, 4.0, 0.3},
                      .direction = glm::normalize(glm::dvec3(0.1, -1.0, 0.05)),
                      .colour = {1.0, 0.9, 0.7},
                      .intensity = 40.0,
                      .innerConeAngle = 0.35,
                      .outerConeAngle = 0.6};
    s.lights.push_back(spot);
    s.camera.position = {0.3, 1.2, 6.0};
    s.camera.forward = glm::normalize(glm::dvec3(-0.05, 0.05, -1.0));
    s.camera.up = glm::normalize(glm::cross(glm::cross(s.camera.forward, glm::dvec3(0, 1, 0)), s.camera.forward));
    s.camera.yfov = 0.9;
    s.camera.zfar = 30.0;
    s.medium.sigma_s = 0.08;
    s.medium.sigma_a = 0.03;
    s.medium.g = 0.4;
    return s;
}

// Henyey-Greenstein written straight from its definition.
inline double hg(double cosTheta, double g) {
    return (1.0 - g * g) / (4.0 * std::numbers::pi * std::pow(1.0 + g * g - 2.0 * g * cosTheta, 1.5));
}

// KHR_lights_punctual angular attenuation, from the definition.
inline double spotA(const scene::Light& l, const glm::dvec3& dirFromLight) {
    const double cd = glm::dot(glm::normalize(l.direction), dirFromLight);
    const double scale = 1.0 / std::max(0.001, std::cos(l.innerConeAngle) - std::cos(l.outerConeAngle));
    const double offset = -std::cos(l.outerConeAngle) * scale;
    const double a = std::clamp(cd * scale + offset, 0.0, 1.0);
    return a * a;
}

// Relative difference, per channel maximum.
inline double relDiff(const glm::dvec3& a, const glm::dvec3& b) {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c) {
        const double scale = std::max(std::abs(a[c]), std::abs(b[c]));
        if (scale > 0.0) worst = std::max(worst, std::abs(a[c] - b[c]) / scale);
    }
    return worst;
}

}  // namespace viz::reference_test
