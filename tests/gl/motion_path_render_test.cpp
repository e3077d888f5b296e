// Frames along a motion path are deterministic for every GPU technique: a frame rendered twice, or after
// the frames before it on the same instance (as `airlight animate` renders them), or alone on a fresh
// instance gives the same pixels, bit for bit. That is what lets reference frames be cached by frame.
#include <cstring>
#include <string>

#include "gl/technique_test_util.h"
#include "scene/builtin_scenes.h"
#include "scene/motion_path.h"

namespace viz::testing {
namespace {

class MotionPathRender : public TechniqueTest {};

bool samePixels(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.channels == b.channels &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

TEST_F(MotionPathRender, AFrameGivesTheSamePixelsHoweverItIsReached) {
    constexpr int kW = 48, kH = 36, kFrames = 8, kFrame = 3;
    const scene::Scene base = scene::makeTestScene();
    const scene::MotionPath path = scene::parseMotionPath("camera-orbit:30deg,light-sweep:20deg");
    for (const std::string& id : techniqueIds()) {
        if (!makeTechnique(id)->needsGl()) continue;
        SCOPED_TRACE(id);
        // Small shadow maps keep polyvol (a vertex per texel) quick; the path is what is under test.
        Settings settings;
        auto walker = makeTechnique(id);
        for (const ParamInfo& p : walker->params())
            if (p.name == "shadow_map") settings["shadow_map"] = 256;
        // One instance walks the path from frame 0 and renders frame kFrame twice.
        scene::Scene moving = base;
        FrameOutput first, walked, again;
        for (int i = 0; i <= kFrame; ++i) {
            scene::applyPose(scene::poseAt(path, base, i, kFrames), moving);
            FrameOutput out = runTechnique(*walker, moving, settings, kW, kH);
            if (i == 0) first = out;
            if (i == kFrame) walked = out;
        }
        again = runTechnique(*walker, moving, settings, kW, kH);
        // A fresh instance renders frame kFrame alone, from its own copy of the scene.
        auto fresh = makeTechnique(id);
        scene::Scene alone = base;
        scene::applyPose(scene::poseAt(path, base, kFrame, kFrames), alone);
        const FrameOutput single = runTechnique(*fresh, alone, settings, kW, kH);

        ASSERT_FALSE(walked.airlight.empty());
        EXPECT_TRUE(samePixels(walked.airlight, again.airlight)) << "the second render of the frame differs";
        EXPECT_TRUE(samePixels(walked.final, again.final));
        EXPECT_TRUE(samePixels(walked.airlight, single.airlight)) << "the frame depends on the frames before it";
        EXPECT_TRUE(samePixels(walked.final, single.final));
        EXPECT_FALSE(samePixels(walked.final, first.final)) << "the path moved nothing";
    }
}

}  // namespace
}  // namespace viz::testing
