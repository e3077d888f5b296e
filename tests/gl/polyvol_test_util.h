// What polyvol's test files share: the fixture, and two readings of a frame's intermediates (the crack
// detector's count over the crossings image, the triangle count in the mesh view's note).
#pragma once

#include <cstdint>
#include <string>

#include <gtest/gtest.h>

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

}  // namespace viz::testing
