// FrameInput::readBack: a caller that reads no CPU images (vsv's and ivsv's inner runs for each other's
// lights) gets none, the same intermediates, and leaves the technique as it was for the next run.
#include <gtest/gtest.h>

#include "gl/technique_test_util.h"
#include "scene/builtin_scenes.h"

namespace viz::testing {
namespace {

class ReadBackTest : public TechniqueTest {};

std::vector<std::string> idsOf(const FrameOutput& out) {
    std::vector<std::string> ids;
    for (const Intermediate& i : out.intermediates) ids.push_back(i.id);
    return ids;
}

// tv-room has an area light next to its other lights, so vsv and ivsv each run the other inside, and the
// shared passes publish numbered shadow maps (one per light or area sample). Every view a run publishes
// belongs to a declared stage the run reached (the window's titles and "not made" notes name it).
TEST_F(ReadBackTest, ARunWithoutReadBackReturnsNoImagesAndPublishesTheSameDeclaredViews) {
    const scene::Scene scene = scene::makeBuiltinScene("tv-room");
    int gpu = 0;
    for (const std::string& id : techniqueIds()) {
        const auto t = makeTechnique(id);
        if (!t->needsGl()) continue;
        ++gpu;
        // polyvol's volume has a vertex per shadow-map texel on each of 16 VPLs' six cube faces: at 64^2
        // it runs in a few seconds here instead of twenty at 256^2 (read-back does not depend on it).
        const Settings given = id == "polyvol" ? Settings{{"shadow_map", 64}} : Settings{};
        FrameInput in = frameInput(&scene, 48, 36, completeSettings(*t, given));
        const FrameOutput full = t->run(in);
        ASSERT_EQ(full.airlight.pixels.size(), 48u * 36u * 3u) << id;
        ASSERT_EQ(full.final.pixels.size(), 48u * 36u * 3u) << id;
        const std::vector<std::string> shown = idsOf(full);
        int numbered = 0;
        for (const std::string& view : shown) {
            const int stage = stageOfIntermediate(t->stages(), view);
            EXPECT_GE(stage, 0) << id << ": " << view << " is declared by no stage";
            EXPECT_LE(stage, full.lastStageRun) << id << ": " << view;
            numbered += view.find("shadow_map.") != std::string::npos ? 1 : 0;
        }
        EXPECT_GT(numbered, 0) << id << ": tv-room's lights give numbered shadow maps";

        in.readBack = false;
        const FrameOutput bare = t->run(in);
        EXPECT_TRUE(bare.airlight.pixels.empty()) << id;
        EXPECT_TRUE(bare.final.pixels.empty()) << id;
        EXPECT_EQ(idsOf(bare), shown) << id;
        EXPECT_EQ(bare.lastStageRun, full.lastStageRun) << id;

        in.readBack = true;
        const FrameOutput again = t->run(in);
        EXPECT_EQ(again.airlight.pixels, full.airlight.pixels) << id;
        EXPECT_EQ(again.final.pixels, full.final.pixels) << id;
    }
    EXPECT_EQ(gpu, 6);
}

}  // namespace
}  // namespace viz::testing
