// Built-in scenes: names, determinism, validation and the properties each one promises.
#include <set>

#include <gtest/gtest.h>

#include "scene/builtin_scenes.h"
#include "scene/scene_source.h"
#include "scene/validate.h"
#include "test_util.h"

namespace viz::scene {
namespace {

std::size_t triangleCount(const Scene& s) {
    std::size_t n = 0;
    for (const Mesh& m : s.meshes) n += m.indices.size() / 3;
    return n;
}

TEST(BuiltinScenes, NamesInMenuOrderWithColonnadeDefault) {
    const std::vector<std::string> expected = {"colonnade", "grate", "forest", "terrain", "stained-glass", "tv-room"};
    EXPECT_EQ(builtinSceneNames(), expected);
    EXPECT_EQ(defaultSceneName(), "colonnade");
    for (const auto& n : expected) EXPECT_TRUE(isBuiltinScene(n));
    EXPECT_FALSE(isBuiltinScene("Grate"));
    EXPECT_FALSE(isBuiltinScene("grate.gltf"));
}

TEST(BuiltinScenes, UnknownNameListsKnownOnes) {
    const std::string msg = test::expectInputError([] { makeBuiltinScene("cathedral"); }, "'cathedral'");
    for (const auto& n : builtinSceneNames()) EXPECT_NE(msg.find(n), std::string::npos) << n;
}

TEST(BuiltinScenes, EachBuildsValidatesAndIsDeterministic) {
    for (const std::string& name : builtinSceneNames()) {
        SCOPED_TRACE(name);
        const Scene s = makeBuiltinScene(name);
        EXPECT_EQ(s.name, name);
        EXPECT_NO_THROW(validateScene(s));
        EXPECT_GT(triangleCount(s), 0u);
        EXPECT_FALSE(s.lights.empty());
        EXPECT_GT(s.medium.sigma_s, 0.0);
        EXPECT_TRUE(s.notes.empty());
        // Same content when built again.
        EXPECT_EQ(sceneContentHash(s), sceneContentHash(makeBuiltinScene(name)));
        EXPECT_GT(s.camera.zfar, 10.0 * s.camera.znear);
    }
}

TEST(BuiltinScenes, TestScenesValidateButAreNotListed) {
    EXPECT_NO_THROW(validateScene(makeTestScene()));
    EXPECT_NO_THROW(validateScene(makeTestAreaLightScene()));
    EXPECT_FALSE(isBuiltinScene(makeTestScene().name));
}

TEST(BuiltinScenes, GrateIsSmallWithOneSpotAboveTheGrate) {
    const Scene s = makeBuiltinScene("grate");
    EXPECT_LT(triangleCount(s), 2000u);
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].type, LightType::Spot);
    // The spot points down and sits above every vertex of the grate mesh.
    EXPECT_LT(s.lights[0].direction.y, -0.99);
    for (const Mesh& m : s.meshes) {
        for (const glm::vec3& p : m.positions) EXPECT_LT(double(p.y), s.lights[0].position.y);
    }
}

TEST(BuiltinScenes, ColonnadeForestTerrainUseADirectionalSun) {
    for (const char* name : {"colonnade", "forest", "terrain"}) {
        const Scene s = makeBuiltinScene(name);
        ASSERT_EQ(s.lights.size(), 1u) << name;
        EXPECT_EQ(s.lights[0].type, LightType::Directional) << name;
        EXPECT_LT(s.lights[0].direction.y, 0.0) << name;  // travels downwards
    }
    // Low sun for forest and terrain: less than ~30 degrees above the horizon.
    EXPECT_GT(makeBuiltinScene("forest").lights[0].direction.y, -0.5);
    EXPECT_GT(makeBuiltinScene("terrain").lights[0].direction.y, -0.5);
}

TEST(BuiltinScenes, ForestHasHundredsOfTrunks) {
    const Scene s = makeBuiltinScene("forest");
    // Trunks are boxes of 12 triangles each.
    std::size_t trunkTriangles = 0;
    for (const Mesh& m : s.meshes) {
        if (m.name == "trunks") trunkTriangles = m.indices.size() / 3;
    }
    EXPECT_GE(trunkTriangles / 12, 200u);
    EXPECT_LE(trunkTriangles / 12, 1000u);
}

TEST(BuiltinScenes, TerrainIsA64x64Heightfield) {
    const Scene s = makeBuiltinScene("terrain");
    ASSERT_EQ(s.meshes.size(), 1u);
    EXPECT_EQ(s.meshes[0].positions.size(), 64u * 64u);
    EXPECT_EQ(s.meshes[0].indices.size(), 63u * 63u * 6u);
    // Heights vary (ridges).
    float lo = 1e9f, hi = -1e9f;
    for (const glm::vec3& p : s.meshes[0].positions) {
        lo = std::min(lo, p.y);
        hi = std::max(hi, p.y);
    }
    EXPECT_GT(hi - lo, 2.0f);
}

TEST(BuiltinScenes, StainedGlassSpotHasAColouredCookie) {
    const Scene s = makeBuiltinScene("stained-glass");
    ASSERT_EQ(s.lights.size(), 1u);
    const Light& l = s.lights[0];
    EXPECT_EQ(l.type, LightType::Spot);
    ASSERT_GE(l.cookie, 0);
    const Texture& t = s.textures[std::size_t(l.cookie)];
    EXPECT_GE(t.width, 32);
    // Coloured: some texel has clearly different R, G, B.
    std::set<std::uint32_t> colours;
    for (std::size_t i = 0; i < t.rgba8.size(); i += 4) {
        colours.insert(std::uint32_t(t.rgba8[i]) << 16 | std::uint32_t(t.rgba8[i + 1]) << 8 | t.rgba8[i + 2]);
    }
    EXPECT_GE(colours.size(), 4u);
}

TEST(BuiltinScenes, TvRoomHasATexturedAreaLight) {
    const Scene s = makeBuiltinScene("tv-room");
    ASSERT_EQ(s.lights.size(), 1u);
    const Light& l = s.lights[0];
    EXPECT_EQ(l.type, LightType::Area);
    EXPECT_GE(l.emissionTexture, 0);
    ASSERT_GE(l.mesh, 0);
    EXPECT_TRUE(s.materials[std::size_t(s.meshes[std::size_t(l.mesh)].material)].isEmissive());
    // The screen faces the room (+z) and the camera is on its emitting side.
    EXPECT_GT(l.direction.z, 0.99);
    EXPECT_GT(glm::dot(s.camera.position - l.position, l.direction), 0.0);
    // uv (0,0) is the top-left corner seen from the front: halfU points right (+x), halfV down (-y).
    EXPECT_GT(l.halfU.x, 0.0);
    EXPECT_LT(l.halfV.y, 0.0);
}

}  // namespace
// The detail parameter of `airlight bench`'s triangles axis: detail 1 is the listed scene exactly, and
// detail k multiplies the triangles of the part that grows (counted, not taken from the generator).
TEST(BuiltinScenes, DetailOneIsTheListedSceneAndDetailKScalesTheTriangles) {
    for (const std::string& name : viz::scene::detailedSceneNames()) {
        const viz::scene::Scene listed = viz::scene::makeBuiltinScene(name);
        const viz::scene::Scene one = viz::scene::makeDetailedScene(name, 1.0);
        ASSERT_EQ(one.meshes.size(), listed.meshes.size()) << name;
        for (std::size_t i = 0; i < one.meshes.size(); ++i) {
            EXPECT_EQ(one.meshes[i].positions, listed.meshes[i].positions) << name;
            EXPECT_EQ(one.meshes[i].indices, listed.meshes[i].indices) << name;
        }
        const std::size_t base = triangleCount(one);
        for (double k : {3.0, 10.0, 100.0}) {
            const viz::scene::Scene more = viz::scene::makeDetailedScene(name, k);
            const double ratio = double(triangleCount(more)) / double(base);
            // The floor, cube, cross bars and ground do not grow, so the ratio is under k (grate: 7.8 at k = 10); the heightfield's
            // side is rounded to whole samples.
            EXPECT_GT(ratio, 0.7 * k) << name << " detail " << k;
            EXPECT_LT(ratio, 1.1 * k) << name << " detail " << k;
            // The lights, medium and camera do not change with the detail.
            EXPECT_EQ(more.lights.size(), one.lights.size());
            EXPECT_EQ(more.camera.position, one.camera.position);
        }
    }
    EXPECT_THROW(viz::scene::makeDetailedScene("colonnade", 2.0), viz::InputError);
    EXPECT_THROW(viz::scene::makeDetailedScene("nowhere", 2.0), viz::InputError);
    EXPECT_THROW(viz::scene::makeDetailedScene("grate", 0.0), viz::InputError);
    EXPECT_THROW(viz::scene::makeDetailedScene("grate", 1e6), viz::InputError);
}

}  // namespace viz::scene
