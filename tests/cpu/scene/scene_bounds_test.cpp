// sceneBounds and the geometry stamp: a stamped scene's box is walked once and kept, by key, and must
// still be its own box whichever scenes were asked for in between.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scene/bounds.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_source.h"

namespace viz::scene {
namespace {

// The box by an exhaustive loop over every vertex, in the test.
void expectBoxOfVertices(const Bounds& b, const Scene& s, const std::string& what) {
    bool any = false;
    glm::dvec3 lo(0.0), hi(0.0);
    for (const Mesh& m : s.meshes)
        for (const glm::vec3& p : m.positions) {
            lo = any ? glm::min(lo, glm::dvec3(p)) : glm::dvec3(p);
            hi = any ? glm::max(hi, glm::dvec3(p)) : glm::dvec3(p);
            any = true;
        }
    EXPECT_EQ(b.empty, !any) << what;
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(b.lo[k], lo[k]) << what << " axis " << k;
        EXPECT_EQ(b.hi[k], hi[k]) << what << " axis " << k;
    }
}

// More stamped scenes than the kept boxes (8), asked for twice in turn: every answer is the scene's own.
TEST(SceneBounds, EveryStampedSceneGetsItsOwnBoxWhateverCameBefore) {
    std::vector<Scene> scenes;
    for (const std::string& n : builtinSceneNames()) scenes.push_back(makeBuiltinScene(n));
    for (const std::string& n : detailedSceneNames())
        for (double detail : {0.5, 3.0}) scenes.push_back(makeDetailedScene(n, detail));
    ASSERT_GT(scenes.size(), 8u);
    for (Scene& s : scenes) {
        stampGeometry(s);
        EXPECT_NE(s.geometryKey, 0u) << s.name;
    }
    for (int pass = 0; pass < 2; ++pass)
        for (std::size_t i = 0; i < scenes.size(); ++i) {
            const std::string what = scenes[i].name + " #" + std::to_string(i) + " pass " + std::to_string(pass);
            expectBoxOfVertices(sceneBounds(scenes[i]), scenes[i], what);
        }
    // Scenes of different geometry have different keys.
    for (std::size_t i = 0; i < scenes.size(); ++i)
        for (std::size_t j = i + 1; j < scenes.size(); ++j) EXPECT_NE(scenes[i].geometryKey, scenes[j].geometryKey);
}

TEST(SceneBounds, AnEmptySceneHasAnEmptyBox) {
    Scene s;
    expectBoxOfVertices(sceneBounds(s), s, "unstamped");
    stampGeometry(s);
    expectBoxOfVertices(sceneBounds(s), s, "stamped");
    EXPECT_EQ(sceneBounds(s).diagonal(), 0.0);
}

// The key follows the geometry, not the lights, camera or medium; an unstamped scene's key is its hash.
// A stamped scene's content hash is an unstamped copy's.
TEST(SceneBounds, TheStampFollowsTheGeometryOnly) {
    Scene s = makeBuiltinScene("grate");
    EXPECT_EQ(geometryKeyOf(s), geometryContentHash(s));
    const std::string unstampedHash = sceneContentHash(s);
    stampGeometry(s);
    const std::uint64_t key = s.geometryKey;
    // The reference's cache is keyed by sceneContentHash: stamped or not, one scene has one key.
    EXPECT_EQ(sceneContentHash(s), unstampedHash);
    Scene moved = s;
    moved.camera.position += glm::dvec3(1.0);
    moved.lights[0].position += glm::dvec3(0.5);
    moved.medium.sigma_s *= 2.0;
    stampGeometry(moved);
    EXPECT_EQ(moved.geometryKey, key);
    Scene edited = s;  // a copy keeps the stamp until its owner stamps it again
    EXPECT_EQ(edited.geometryKey, key);
    edited.meshes[0].positions[0].y += 100.0f;
    stampGeometry(edited);
    EXPECT_NE(edited.geometryKey, key);
    expectBoxOfVertices(sceneBounds(edited), edited, "edited, stamped again");
    expectBoxOfVertices(sceneBounds(s), s, "the original");
}

}  // namespace
}  // namespace viz::scene
