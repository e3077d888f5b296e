// A technique keeps its GL textures and buffers from one run to the next when their sizes agree (the
// window runs it every frame; allocating them again each time is hundreds of MB at 1920x1080). What a run
// leaves in them must not reach the next one: an instance that ran other frames first gives, bit for bit,
// what a fresh instance gives.
#include <gtest/gtest.h>

#include "gl/technique_test_util.h"
#include "scene/builtin_scenes.h"

namespace viz::testing {
namespace {

class KeptResourcesTest : public TechniqueTest {};

// The camera turned a little about its up axis: the same image size, so the same texture sizes where
// they depend on the image, with different contents.
scene::Scene turned(scene::Scene scene, double radians) {
    const glm::dvec3 f = scene.camera.forward, u = scene.camera.up, side = glm::cross(f, u);
    scene.camera.forward = glm::normalize(std::cos(radians) * f + std::sin(radians) * side);
    scene.camera.position += 0.05 * side;
    return scene;
}

TEST_F(KeptResourcesTest, AnInstanceThatRanOtherFramesFirstGivesWhatAFreshOneGives) {
    const scene::Scene grate = scene::makeBuiltinScene("grate");
    const scene::Scene stained = scene::makeBuiltinScene("stained-glass");
    // grate, grate turned (every size kept, every content changed), then another scene.
    const std::vector<const scene::Scene*> frames = {&grate, nullptr, &stained};
    const scene::Scene grateTurned = turned(grate, 0.04);
    int gpu = 0;
    for (const std::string& id : techniqueIds()) {
        auto kept = makeTechnique(id);
        if (!kept->needsGl()) continue;
        ++gpu;
        // minmax: a fixed slice count keeps its per-slice tables (svd on these spot-lit scenes) the same
        // size across the turn, so they are reused with the first frame's contents in them.
        Settings given;
        if (id == "minmax") given = {{"slices", 96.0}};
        if (id == "polyvol") given = {{"shadow_map", 128.0}};
        for (std::size_t i = 0; i < frames.size(); ++i) {
            const scene::Scene& scene = frames[i] ? *frames[i] : grateTurned;
            const FrameOutput again = runTechnique(*kept, scene, given, 64, 48);
            auto fresh = makeTechnique(id);
            const FrameOutput first = runTechnique(*fresh, scene, given, 64, 48);
            ASSERT_EQ(first.airlight.pixels.size(), 64u * 48u * 3u) << id << ", frame " << i;
            EXPECT_EQ(again.airlight.pixels, first.airlight.pixels) << id << ", frame " << i;
            EXPECT_EQ(again.final.pixels, first.final.pixels) << id << ", frame " << i;
        }
    }
    EXPECT_EQ(gpu, 6);
}

// Programs are kept too: a technique compiles its shaders on first use, inside the stage that uses them
// (whose time then says so: StageTiming::programsCompiled), and never again for the same scene and
// settings, nor for the next frame of a moving camera. A technique that compiled on every run would pay
// a compile per frame in the window and in every timed run of `report` and `bench`.
TEST_F(KeptResourcesTest, OnlyTheFirstRunCompilesShaders) {
    for (const std::string& name : scene::builtinSceneNames()) {
        const scene::Scene scene = scene::makeBuiltinScene(name);
        const scene::Scene next = turned(scene, 0.04);
        for (const std::string& id : techniqueIds()) {
            auto technique = makeTechnique(id);
            if (!technique->needsGl()) continue;
            Settings given;
            if (id == "polyvol") given = {{"shadow_map", 128.0}};
            const FrameOutput first = runTechnique(*technique, scene, given, 32, 24);
            EXPECT_GT(first.timing.programsCompiled(), 0) << name << " " << id << ": the first run compiles its shaders";
            for (const scene::Scene* again : {&scene, &next}) {
                const FrameOutput later = runTechnique(*technique, *again, given, 32, 24);
                for (const StageTiming& st : later.timing.stages)
                    EXPECT_EQ(st.programsCompiled, 0) << name << " " << id << ", " << st.stage
                                                      << (again == &scene ? " (the same frame)" : " (the next frame)");
            }
        }
    }
}

}  // namespace
}  // namespace viz::testing
