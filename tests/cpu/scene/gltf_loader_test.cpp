// Loading the hand-written files in tests/data/scene: values are those written in the files (see the
// JSON), transforms worked out by hand.
#include <cmath>

#include <gtest/gtest.h>

#include "scene/gltf_loader.h"
#include "test_util.h"

namespace viz::scene {
namespace {

using test::dataPath;
using test::hasNote;

// Tolerance for values that went through a float buffer or a quaternion (float epsilon scale).
constexpr double kFloatTol = 1e-6;

TEST(GltfLoader, BoxWithCameraSpotMediumAndCookie) {
    const Scene s = loadGltf(dataPath("box.gltf"));
    EXPECT_EQ(s.name, "box");
    ASSERT_EQ(s.meshes.size(), 1u);
    EXPECT_EQ(s.meshes[0].positions.size(), 8u);
    EXPECT_EQ(s.meshes[0].indices.size(), 36u);
    EXPECT_TRUE(s.meshes[0].normals.empty());
    ASSERT_EQ(s.meshes[0].uvs.size(), 8u);
    EXPECT_EQ(s.meshes[0].uvs[7], glm::vec2(1.0f, 1.0f));  // corner (0.5, 0.5, 0.5): uv = (x, y) + 0.5
    EXPECT_EQ(s.meshes[0].material, 0);

    ASSERT_EQ(s.materials.size(), 1u);
    EXPECT_EQ(s.materials[0].baseColorFactor, glm::vec4(0.8f, 0.5f, 0.25f, 1.0f));
    EXPECT_EQ(s.materials[0].baseColorTexture, 0);
    EXPECT_FALSE(s.materials[0].isEmissive());

    // 2x2 PNG: red, green / blue, white with alpha 128.
    ASSERT_EQ(s.textures.size(), 1u);
    EXPECT_EQ(s.textures[0].width, 2);
    EXPECT_EQ(s.textures[0].height, 2);
    const std::vector<std::uint8_t> expected = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 128};
    EXPECT_EQ(s.textures[0].rgba8, expected);

    // Camera at (0, 1, 5) with identity rotation: looks down -Z, +Y up; zfar absent -> 1000.
    EXPECT_EQ(s.camera.name, "main");
    EXPECT_EQ(s.camera.position, glm::dvec3(0, 1, 5));
    EXPECT_EQ(s.camera.forward, glm::dvec3(0, 0, -1));
    EXPECT_EQ(s.camera.up, glm::dvec3(0, 1, 0));
    EXPECT_DOUBLE_EQ(s.camera.yfov, 0.7);
    EXPECT_DOUBLE_EQ(s.camera.znear, 0.1);
    EXPECT_DOUBLE_EQ(s.camera.zfar, 1000.0);
    EXPECT_DOUBLE_EQ(s.camera.aspectRatio, 1.5);

    // Spot at (0, 3, 0) rotated -90 degrees about X: -Z turns into -Y (pointing down).
    ASSERT_EQ(s.lights.size(), 1u);
    const Light& l = s.lights[0];
    EXPECT_EQ(l.type, LightType::Spot);
    EXPECT_EQ(l.name, "spot");
    EXPECT_NEAR(glm::length(l.position - glm::dvec3(0, 3, 0)), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(l.direction - glm::dvec3(0, -1, 0)), 0.0, 1e-12);
    EXPECT_EQ(l.colour, glm::dvec3(1.0, 0.5, 0.25));
    EXPECT_DOUBLE_EQ(l.intensity, 30.0);
    EXPECT_DOUBLE_EQ(l.innerConeAngle, 0.2);
    EXPECT_DOUBLE_EQ(l.outerConeAngle, 0.6);
    EXPECT_EQ(l.cookie, 0);

    EXPECT_DOUBLE_EQ(s.medium.sigma_s, 0.1);
    EXPECT_DOUBLE_EQ(s.medium.sigma_a, 0.02);
    EXPECT_DOUBLE_EQ(s.medium.g, 0.3);
    EXPECT_FALSE(hasNote(s, "no camera"));
    EXPECT_FALSE(hasNote(s, "no medium"));
}

TEST(GltfLoader, FlattensNodeTransforms) {
    const Scene s = loadGltf(dataPath("transforms.gltf"));
    // Three instances of the TRIANGLES primitive; the POINTS primitive is skipped with a note.
    ASSERT_EQ(s.meshes.size(), 3u);
    EXPECT_TRUE(hasNote(s, "not TRIANGLES"));

    // child: Rz(90) maps (x, y, z) to (-y, x, z); parent: scale (2, 1, 1) then translate (1, 2, 3).
    const Mesh& m = s.meshes[0];
    const glm::dvec3 expected[3] = {{1, 3, 3}, {-1, 2, 3}, {1, 2, 4}};
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(glm::length(glm::dvec3(m.positions[std::size_t(i)]) - expected[i]), 0.0, kFloatTol) << i;
    }
    // Normal (1, 1, 0)/sqrt2 -> Rz -> (-1, 1, 0)/sqrt2 -> inverse transpose of scale (2,1,1), i.e.
    // scale (0.5, 1, 1) -> (-0.5, 1, 0) -> normalised (-1, 2, 0)/sqrt5.
    const glm::dvec3 n = glm::dvec3(-1, 2, 0) / std::sqrt(5.0);
    for (const glm::vec3& got : m.normals) EXPECT_NEAR(glm::length(glm::dvec3(got) - n), 0.0, kFloatTol);
    // The file's normal is perpendicular to the edge v1 - v0 = (-1, 1, 0); the inverse transpose keeps
    // it perpendicular to the transformed edge (the plain matrix would not).
    const glm::dvec3 e1 = glm::dvec3(m.positions[1]) - glm::dvec3(m.positions[0]);
    EXPECT_NEAR(glm::dot(glm::dvec3(m.normals[0]), glm::normalize(e1)), 0.0, kFloatTol);

    // The root instance is untouched.
    EXPECT_EQ(s.meshes[1].positions[0], glm::vec3(1, 0, 0));
    EXPECT_EQ(s.meshes[1].indices, (std::vector<std::uint32_t>{0, 1, 2}));

    // Mirrored instance: x negated, and the winding swapped so that the geometric normal still agrees
    // with the (transformed) vertex normal: counter-clockwise stays the front face.
    const Mesh& mir = s.meshes[2];
    EXPECT_EQ(mir.positions[0], glm::vec3(-1, 0, 0));
    const glm::dvec3 a(mir.positions[mir.indices[0]]), b(mir.positions[mir.indices[1]]), c(mir.positions[mir.indices[2]]);
    const glm::dvec3 geometric = glm::cross(b - a, c - a);
    EXPECT_GT(glm::dot(geometric, glm::dvec3(mir.normals[0])), 0.0);
    const glm::dvec3 p0(s.meshes[1].positions[0]), p1(s.meshes[1].positions[1]), p2(s.meshes[1].positions[2]);
    EXPECT_GT(glm::dot(glm::cross(p1 - p0, p2 - p0), glm::dvec3(s.meshes[1].normals[0])), 0.0);

    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].type, LightType::Point);
    EXPECT_EQ(s.lights[0].position, glm::dvec3(0, 5, 0));
    EXPECT_DOUBLE_EQ(s.lights[0].intensity, 10.0);
    EXPECT_EQ(s.lights[0].colour, glm::dvec3(1.0));  // KHR default colour
    EXPECT_EQ(s.medium.sigma_s, 0.0);
}

TEST(GltfLoader, GlbEmissiveQuadBecomesAreaLightAndCameraIsFramed) {
    const Scene s = loadGltf(dataPath("quad.glb"));
    ASSERT_EQ(s.meshes.size(), 1u);
    ASSERT_EQ(s.lights.size(), 1u);
    const Light& l = s.lights[0];
    EXPECT_EQ(l.type, LightType::Area);
    EXPECT_EQ(l.mesh, 0);
    EXPECT_EQ(l.position, glm::dvec3(0, 1, 0));
    // Triangles (0,2,1) and (0,3,2) are counter-clockwise seen from +Y.
    EXPECT_EQ(l.direction, glm::dvec3(0, 1, 0));
    // 2 m x 2 m square: half edges of length 1 along x and z, cross(halfU, halfV) along the normal.
    EXPECT_DOUBLE_EQ(glm::length(l.halfU), 1.0);
    EXPECT_DOUBLE_EQ(glm::length(l.halfV), 1.0);
    EXPECT_DOUBLE_EQ(glm::dot(l.halfU, l.halfV), 0.0);
    EXPECT_GT(glm::dot(glm::cross(l.halfU, l.halfV), l.direction), 0.0);
    EXPECT_EQ(l.radiance, glm::dvec3(4.0, 2.0, 1.0));  // emissiveFactor * emissiveStrength 4
    EXPECT_EQ(l.emissionTexture, -1);
    EXPECT_DOUBLE_EQ(s.medium.g, -0.5);

    // No camera: framed so that the whole quad is in front of it and within zfar.
    EXPECT_TRUE(hasNote(s, "no camera: framed the scene"));
    for (const glm::vec3& p : s.meshes[0].positions) {
        const glm::dvec3 v = glm::dvec3(p) - s.camera.position;
        EXPECT_GT(glm::dot(v, s.camera.forward), s.camera.znear);
        EXPECT_LT(glm::length(v), s.camera.zfar);
        // Inside the vertical field of view.
        const double vertical = std::abs(glm::dot(v, s.camera.up)) / glm::dot(v, s.camera.forward);
        EXPECT_LT(vertical, std::tan(0.5 * s.camera.yfov));
    }
}

}  // namespace
}  // namespace viz::scene
