// What plans leave out must not change the image: force_features=1 runs everything a plan would skip,
// and a light whose lit volume misses the view is dropped entirely.
#include <gtest/gtest.h>

#include "gl/technique_test_util.h"
#include "scene/builtin_scenes.h"

namespace viz::testing {
namespace {

class ForcedPlan : public TechniqueTest {};

TEST_F(ForcedPlan, ForcingSkippedFeaturesLeavesEveryImageUnchanged) {
    for (const char* technique : {"raymarch", "slices"})
        for (const char* name : {"grate", "colonnade", "stained-glass", "tv-room"}) {
            const scene::Scene s = scene::makeBuiltinScene(name);
            const Settings fast = {{"samples", 32}, {"planes", 32}, {"area_samples", 2}, {"shadow_map", 256}};
            Settings plain, forced;
            const auto t = makeTechnique(technique);
            for (const auto& [k, v] : fast)
                for (const ParamInfo& p : t->params())
                    if (p.name == k) plain[k] = v;
            forced = plain;
            forced["force_features"] = 1;
            // The forced plan really turns something on (every scene here lacks some light kind).
            const Plan a = t->plan(s, completeSettings(*t, plain)), b = t->plan(s, completeSettings(*t, forced));
            int enabledA = 0, enabledB = 0;
            for (const auto& f : a.features) enabledA += f.enabled;
            for (const auto& f : b.features) enabledB += f.enabled;
            EXPECT_GT(enabledB, enabledA) << technique << " " << name;

            const FrameOutput x = render(s, technique, plain, 40, 30);
            const FrameOutput y = render(s, technique, forced, 40, 30);
            ASSERT_FALSE(x.airlight.empty());
            double maxDiff = 0.0, maxValue = 0.0;
            for (std::size_t i = 0; i < x.airlight.pixels.size(); ++i) {
                maxDiff = std::max(maxDiff, double(std::abs(x.airlight.pixels[i] - y.airlight.pixels[i])));
                maxValue = std::max(maxValue, double(std::abs(x.airlight.pixels[i])));
            }
            // Same arithmetic on the same data; only dead code differs. Allow float reassociation.
            EXPECT_LE(maxDiff, 1e-5 * maxValue) << technique << " " << name;
        }
}

TEST_F(ForcedPlan, ALightThatLightsNothingVisibleIsDroppedWithoutChangingTheImage) {
    const scene::Scene plain = scene::makeBuiltinScene("grate");
    scene::Scene extra = plain;
    scene::Light away = plain.lights[0];
    away.name = "behind";
    away.position = {0.0, 1.0, 9.0};  // behind the camera (at z = 7), shining away from the scene
    away.direction = {0.0, 0.0, 1.0};
    extra.lights.push_back(away);
    for (const char* technique : {"raymarch", "slices"}) {
        const auto t = makeTechnique(technique);
        const Plan p = t->plan(extra, completeSettings(*t, {}));
        bool listed = false;
        for (const FeaturePlan& f : p.features) listed |= f.feature == "LIGHT behind" && !f.enabled;
        EXPECT_TRUE(listed) << technique;
        const Settings fast = {{"shadow_map", 256}};
        const FrameOutput a = render(plain, technique, fast, 40, 30);
        const FrameOutput b = render(extra, technique, fast, 40, 30);
        EXPECT_EQ(a.airlight.pixels, b.airlight.pixels) << technique;
        EXPECT_EQ(a.final.pixels, b.final.pixels) << technique;
        // One shadow map, not two.
        EXPECT_NE(find(b, std::string(technique) + ".shadow_map"), nullptr);
        EXPECT_EQ(find(b, std::string(technique) + ".shadow_map.1"), nullptr);
    }
}

}  // namespace
}  // namespace viz::testing
