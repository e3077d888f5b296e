// What polyvol's test files share: the fixture, two readings of a frame's intermediates (the crack
// detector's count over the crossings image, the triangle count in the mesh view's note), the omni grate
// and a look-at camera.
#pragma once

#include <cstdint>
#include <string>

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "scene/builtin_scenes.h"
#include "technique_test_util.h"
#include "techniques/polyvol/crack_check.h"

namespace viz::testing {

class PolyvolTest : public TechniqueTest {};

// Pixels whose crossing count differs from the common count of their neighbourhood (crack_check=1).
inline int crackPixels(const viz::FrameOutput& out) {
    for (const auto& i : out.intermediates)
        if (i.id == "polyvol.crossings" && i.image) return viz::polyvol::countCrackPixels(*i.image, 1).badPixels;
    ADD_FAILURE() << "no polyvol.crossings image";
    return -1;
}

// The triangles the volume stage drew, from the polyvol.mesh intermediate's note.
inline std::int64_t trianglesDrawn(const viz::FrameOutput& out) {
    const viz::Intermediate* mesh = nullptr;
    for (const auto& i : out.intermediates)
        if (i.id == "polyvol.mesh") mesh = &i;
    EXPECT_NE(mesh, nullptr);
    return mesh ? std::stoll(mesh->note) : -1;
}

// The volume stage's time in a run (benchmarks only).
inline double volumeMs(const viz::FrameOutput& out) {
    for (const auto& st : out.timing.stages)
        if (st.stage == "polyvol.volume") return st.milliseconds;
    return 0.0;
}

// grate with its spot replaced by a point light at the same place (an omni test scene).
inline viz::scene::Scene omniGrate() {
    viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    for (auto& light : scene.lights)
        if (light.type == viz::scene::LightType::Spot) light.type = viz::scene::LightType::Point;
    return scene;
}

inline viz::scene::Camera lookAtCamera(const viz::scene::Camera& base, glm::dvec3 eye, glm::dvec3 target) {
    viz::scene::Camera c = base;
    c.position = eye;
    c.forward = glm::normalize(target - eye);
    const glm::dvec3 right = glm::normalize(glm::cross(c.forward, glm::dvec3(0, 1, 0)));
    c.up = glm::cross(right, c.forward);
    return c;
}

}  // namespace viz::testing
