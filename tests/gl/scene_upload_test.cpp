// A technique instance keeps its GPU upload of the scene while the geometry stays the same (the window
// moves the camera and lights every frame). The upload is keyed by the geometry, never by the scene's
// address: a stamped scene by its stamp (stampGeometry), an unstamped one by its content hash.
#include <gtest/gtest.h>

#include <string>

#include "scene/builtin_scenes.h"
#include "scene/scene_source.h"
#include "technique_test_util.h"

namespace {

class SceneUploadTest : public viz::testing::TechniqueTest {
protected:
    // One instance renders `first` and then `second` in the same variable; the second image must be a
    // fresh instance's image of `second`, which differs from the first (or the check means nothing).
    static void expectSecondDrawnAfresh(const std::string& technique, const viz::scene::Scene& first,
                                        const viz::scene::Scene& second, const std::string& what) {
        auto t = viz::makeTechnique(technique);
        viz::scene::Scene held = first;
        const viz::FrameOutput a = viz::testing::runTechnique(*t, held, {}, 64, 48);
        held = second;
        const viz::FrameOutput b = viz::testing::runTechnique(*t, held, {}, 64, 48);
        const viz::FrameOutput fresh = render(second, technique, {}, 64, 48);
        EXPECT_GT(viz::testing::relativeL2(a.airlight, fresh.airlight), 0.01) << what;
        // Within polyvol's run-to-run spread (its volumes' fragments add up in varying order: two fresh
        // instances differ by about 1e-8); the old upload would be 1e-2 or more off.
        EXPECT_LT(viz::testing::relativeL2(b.airlight, fresh.airlight), 1e-6) << what << ": " << technique
                                                                              << " kept the old upload";
    }
};

// grate with more bars: the same camera and lights, other geometry.
TEST_F(SceneUploadTest, AStampedSceneIsUploadedAgainWhenItsStampChanges) {
    viz::scene::Scene grate = viz::scene::makeBuiltinScene("grate");
    viz::scene::Scene finer = viz::scene::makeDetailedScene("grate", 3.0);
    viz::scene::stampGeometry(grate);
    viz::scene::stampGeometry(finer);
    for (const std::string technique : {"raymarch", "polyvol", "vsv"})
        expectSecondDrawnAfresh(technique, grate, finer, "stamped");
}

// Unstamped, a rescale that keeps every count is caught by the content hash.
TEST_F(SceneUploadTest, AnUnstampedEditedSceneIsUploadedAgain) {
    const viz::scene::Scene grate = viz::scene::makeBuiltinScene("grate");
    viz::scene::Scene raised = grate;
    for (viz::scene::Mesh& m : raised.meshes)
        for (glm::vec3& p : m.positions) p.y += 0.5f;
    for (const std::string technique : {"raymarch", "polyvol", "vsv"})
        expectSecondDrawnAfresh(technique, grate, raised, "unstamped");
}

}  // namespace
