// loadScene dispatch and sceneContentHash sensitivity and stability.
#include <functional>
#include <set>

#include <gtest/gtest.h>

#include "scene/builtin_scenes.h"
#include "scene/scene_source.h"
#include "test_util.h"

namespace viz::scene {
namespace {

TEST(SceneSource, LoadsBuiltinNamesAndGltfPaths) {
    EXPECT_EQ(loadScene("grate").name, "grate");
    EXPECT_EQ(loadScene(test::dataPath("box.gltf")).name, "box");
    EXPECT_EQ(loadScene(test::dataPath("quad.glb")).lights.size(), 1u);
}

TEST(SceneSource, UnknownSceneMessageListsBuiltinsAndFileTypes) {
    const std::string msg = test::expectInputError([] { loadScene("cathedral.obj"); }, "unknown scene 'cathedral.obj'");
    EXPECT_NE(msg.find("not a built-in scene (colonnade, grate, forest, terrain, stained-glass, tv-room)"), std::string::npos);
    EXPECT_NE(msg.find("not a .gltf/.glb file"), std::string::npos);
}

TEST(SceneSource, MissingGltfPathIsAnInputError) {
    test::expectInputError([] { loadScene("/nonexistent/dir/x.glb"); }, "no such file");
}

TEST(SceneSource, Fnv1aMatchesPublishedTestVectors) {
    // Test vectors from the FNV reference (Fowler, Noll, Vo; IETF draft-eastlake-fnv).
    EXPECT_EQ(fnv1a64("", 0), 0xcbf29ce484222325ULL);
    EXPECT_EQ(fnv1a64("a", 1), 0xaf63dc4c8601ec8cULL);
    EXPECT_EQ(fnv1a64("foobar", 6), 0x85944171f73967e8ULL);
    // Continuing from a previous hash is the same as hashing the concatenation.
    EXPECT_EQ(fnv1a64("bar", 3, fnv1a64("foo", 3)), fnv1a64("foobar", 6));
}

TEST(SceneSource, HashIsHexAndStable) {
    const std::string h = sceneContentHash(makeBuiltinScene("grate"));
    EXPECT_EQ(h.size(), 16u);
    EXPECT_EQ(h.find_first_not_of("0123456789abcdef"), std::string::npos);
    // Independent of where the data lives and of names and notes.
    Scene copy = makeBuiltinScene("grate");
    copy.name = "renamed";
    copy.notes.push_back("a note");
    copy.meshes.reserve(100);
    EXPECT_EQ(sceneContentHash(copy), h);
    // Different scenes differ.
    std::set<std::string> all;
    for (const auto& n : builtinSceneNames()) all.insert(sceneContentHash(makeBuiltinScene(n)));
    EXPECT_EQ(all.size(), builtinSceneNames().size());
}

TEST(SceneSource, HashChangesWithEveryRenderingInput) {
    const Scene base = makeTestAreaLightScene();
    const std::string h0 = sceneContentHash(base);
    std::vector<std::pair<std::string, std::function<void(Scene&)>>> edits = {
        {"vertex", [](Scene& s) { s.meshes[0].positions[0].x += 1e-3f; }},
        {"normal", [](Scene& s) { s.meshes[0].normals[0].y = -1.0f; }},
        {"uv", [](Scene& s) { s.meshes[1].uvs[0].x = 0.5f; }},
        {"index", [](Scene& s) { std::swap(s.meshes[0].indices[0], s.meshes[0].indices[1]); }},
        {"mesh material", [](Scene& s) { s.meshes[0].material = -1; }},
        {"albedo", [](Scene& s) { s.materials[0].baseColorFactor.r = 0.51f; }},
        {"emission strength", [](Scene& s) { s.materials[1].emissiveStrength = 5.5f; }},
        {"texture byte", [](Scene& s) { s.textures[0].rgba8[5] ^= 1; }},
        {"light position", [](Scene& s) { s.lights[0].position.y += 0.01; }},
        {"light radiance", [](Scene& s) { s.lights[0].radiance.x *= 2.0; }},
        {"light half edge", [](Scene& s) { s.lights[0].halfU *= 1.01; }},
        {"camera position", [](Scene& s) { s.camera.position.z += 0.01; }},
        {"camera yfov", [](Scene& s) { s.camera.yfov = 0.91; }},
        {"camera zfar", [](Scene& s) { s.camera.zfar = 21.0; }},
        {"camera aspect", [](Scene& s) { s.camera.aspectRatio = 2.0; }},
        {"sigma_s", [](Scene& s) { s.medium.sigma_s = 0.21; }},
        {"sigma_a", [](Scene& s) { s.medium.sigma_a = 0.01; }},
        {"g", [](Scene& s) { s.medium.g = 0.1; }},
    };
    for (auto& [what, edit] : edits) {
        Scene s = base;
        edit(s);
        EXPECT_NE(sceneContentHash(s), h0) << what;
    }
    const Scene spot = makeTestScene();
    const std::string hs = sceneContentHash(spot);
    std::vector<std::pair<std::string, std::function<void(Scene&)>>> spotEdits = {
        {"intensity", [](Scene& s) { s.lights[0].intensity = 51.0; }},
        {"colour", [](Scene& s) { s.lights[0].colour.z = 0.9; }},
        {"direction", [](Scene& s) { s.lights[0].direction = glm::normalize(glm::dvec3(0.1, -1, 0)); }},
        {"inner cone", [](Scene& s) { s.lights[0].innerConeAngle = 0.2; }},
        {"outer cone", [](Scene& s) { s.lights[0].outerConeAngle = 0.6; }},
        {"type", [](Scene& s) { s.lights[0].type = LightType::Point; }},
        {"added light", [](Scene& s) { s.lights.push_back(s.lights[0]); }},
    };
    for (auto& [what, edit] : spotEdits) {
        Scene s = spot;
        edit(s);
        EXPECT_NE(sceneContentHash(s), hs) << what;
    }
}

}  // namespace
}  // namespace viz::scene
