// What vsv and ivsv run on each built-in scene, and why: the light kinds each scene has decide which
// shader code is compiled in, whether the epipole rays exist, and which light goes to the inner
// technique (vsv hands area lights to ivsv, ivsv hands every other light to vsv).
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "scene/builtin_scenes.h"
#include "technique_run.h"
#include "techniques/registry.h"

namespace viz {
namespace {

using testing::planOf;

void expectFeatures(const std::string& technique, const std::string& sceneName,
                    const std::map<std::string, bool>& expected, const Settings& given = {}) {
    const Plan plan = planOf(technique, scene::makeBuiltinScene(sceneName), given);
    for (const auto& [name, on] : expected) {
        const FeaturePlan* f = findFeature(plan, name);
        ASSERT_NE(f, nullptr) << technique << " lists no feature " << name;
        EXPECT_EQ(f->enabled, on) << technique << " on " << sceneName << ": " << name << " (" << f->why << ")";
    }
}

TEST(VsvPlan, CompilesOnlyTheLightCodeEachSceneUses) {
    // grate: one spot; stained-glass: a spot with a cookie, looking toward it (an epipole in view);
    // colonnade, forest, terrain: one sun (forest looks toward it); tv-room: only an area light.
    expectFeatures("vsv", "grate",
                   {{"SPOT", true}, {"COOKIE", false}, {"SHADOW_MAPS_2D", true}, {"SHADOW_MAPS_CUBE", false},
                    {"DIRECTIONAL", false}, {"EPIPOLE", false}, {"AREA_LIGHTS_BY_IVSV", false}});
    expectFeatures("vsv", "stained-glass",
                   {{"SPOT", true}, {"COOKIE", true}, {"SHADOW_MAPS_2D", true}, {"SHADOW_MAPS_CUBE", false},
                    {"DIRECTIONAL", false}, {"EPIPOLE", true}, {"AREA_LIGHTS_BY_IVSV", false}});
    for (const char* sun : {"colonnade", "terrain"})
        expectFeatures("vsv", sun,
                       {{"SPOT", false}, {"COOKIE", false}, {"SHADOW_MAPS_2D", true}, {"SHADOW_MAPS_CUBE", false},
                        {"DIRECTIONAL", true}, {"EPIPOLE", false}, {"AREA_LIGHTS_BY_IVSV", false}});
    expectFeatures("vsv", "forest",
                   {{"SPOT", false}, {"SHADOW_MAPS_2D", true}, {"DIRECTIONAL", true}, {"EPIPOLE", true}});
    expectFeatures("vsv", "tv-room",
                   {{"SPOT", false}, {"COOKIE", false}, {"SHADOW_MAPS_2D", false}, {"SHADOW_MAPS_CUBE", false},
                    {"DIRECTIONAL", false}, {"EPIPOLE", false}, {"AREA_LIGHTS_BY_IVSV", true}});
    // Settings choose these, not the scene.
    expectFeatures("vsv", "grate", {{"COMBINE_EXACT", false}, {"INTERP", false}}, {{"combine", 0}, {"interp", 0}});
}

TEST(VsvPlan, SkipsTheGridStagesWithoutAPointSpotOrSun) {
    const Plan room = planOf("vsv", scene::makeBuiltinScene("tv-room"));
    for (const char* id : {"vsv.voxelize", "vsv.scan"}) {
        const StagePlan* s = findStage(room, id);
        ASSERT_NE(s, nullptr);
        EXPECT_FALSE(s->runs) << id;
        EXPECT_NE(s->why.find("no point, spot or directional light"), std::string::npos) << s->why;
    }
    const Plan grate = planOf("vsv", scene::makeBuiltinScene("grate"));
    for (const StagePlan& s : grate.stages) EXPECT_TRUE(s.runs) << s.stage;
    EXPECT_NE(findStage(grate, "vsv.scan")->why.find("7 passes for 128 alpha cells"), std::string::npos);
}

TEST(VsvPlan, ForcingTurnsOnEverySceneChoiceButNoSettingChoice) {
    const scene::Scene room = scene::makeBuiltinScene("tv-room");
    const Plan forced = planOf("vsv", room, {{"force_features", 1}, {"combine", 0}});
    for (const StagePlan& s : forced.stages) EXPECT_TRUE(s.runs) << s.stage;
    for (const char* name : {"SPOT", "COOKIE", "SHADOW_MAPS_2D", "SHADOW_MAPS_CUBE", "EPIPOLE", "AREA_LIGHTS_BY_IVSV"}) {
        const FeaturePlan* f = findFeature(forced, name);
        ASSERT_NE(f, nullptr) << name;
        EXPECT_TRUE(f->enabled) << name;
    }
    EXPECT_NE(findFeature(forced, "SPOT")->why.find("forced on"), std::string::npos);
    EXPECT_FALSE(findFeature(forced, "COMBINE_EXACT")->enabled);  // combine=fraction was asked for
    // epipole=0 is a setting: forcing leaves the epipole rays out.
    EXPECT_FALSE(findFeature(planOf("vsv", room, {{"force_features", 1}, {"epipole", 0}}), "EPIPOLE")->enabled);
}

TEST(VsvPlan, ACulledLightIsListedAndLeftOut) {
    scene::Scene s = scene::makeBuiltinScene("grate");
    scene::Light away = s.lights[0];
    away.name = "behind";
    away.type = scene::LightType::Point;
    away.position = {0.0, 1.0, 9.0};
    s.lights.push_back(away);
    scene::Light spotAway = s.lights[0];
    spotAway.name = "spot-behind";
    spotAway.position = {0.0, 1.0, 9.0};  // behind the camera (at z = 7), shining away from the scene
    spotAway.direction = {0.0, 0.0, 1.0};
    s.lights.push_back(spotAway);
    const Plan p = planOf("vsv", s);
    const FeaturePlan* culled = findFeature(p, "LIGHT spot-behind");
    ASSERT_NE(culled, nullptr);
    EXPECT_FALSE(culled->enabled);
    // The point light fills all space: never culled, and it needs the cube maps.
    EXPECT_EQ(findFeature(p, "LIGHT behind"), nullptr);
    EXPECT_TRUE(findFeature(p, "SHADOW_MAPS_CUBE")->enabled);
}

TEST(IvsvPlan, RunsTheVplPipelineOnlyForAnAreaLight) {
    const Plan room = planOf("ivsv", scene::makeBuiltinScene("tv-room"));
    for (const StagePlan& s : room.stages) EXPECT_TRUE(s.runs) << s.stage;
    EXPECT_TRUE(findFeature(room, "VPL_PIPELINE")->enabled);
    EXPECT_FALSE(findFeature(room, "OTHER_LIGHTS_BY_VSV")->enabled);
    for (const char* sceneName : {"grate", "colonnade", "forest", "terrain", "stained-glass"}) {
        const Plan p = planOf("ivsv", scene::makeBuiltinScene(sceneName));
        EXPECT_FALSE(findFeature(p, "VPL_PIPELINE")->enabled) << sceneName;
        EXPECT_TRUE(findFeature(p, "OTHER_LIGHTS_BY_VSV")->enabled) << sceneName;
        for (const char* id : {"ivsv.vpls", "ivsv.shadow_maps", "ivsv.voxelize", "ivsv.scan"}) {
            const StagePlan* s = findStage(p, id);
            ASSERT_NE(s, nullptr);
            EXPECT_FALSE(s->runs) << sceneName << " " << id;
            EXPECT_NE(s->why.find("no area light"), std::string::npos) << s->why;
        }
    }
    const Plan forced = planOf("ivsv", scene::makeBuiltinScene("tv-room"), {{"force_features", 1}});
    EXPECT_TRUE(findFeature(forced, "OTHER_LIGHTS_BY_VSV")->enabled);
}

// The plan says how the VPLs are laid out: tv-room's 1.6 x 0.9 screen takes 64 VPLs as an 8 x 8 grid
// (cells 0.2 x 0.11) and 128 as 16 x 8 (0.1 x 0.11), each its cell with vpl_kernel=cell; Halton points
// are discs of their area.
TEST(IvsvPlan, SaysHowTheVplsAreLaidOut) {
    const scene::Scene room = scene::makeBuiltinScene("tv-room");
    auto vplsWhy = [&](const Settings& s) { return findStage(planOf("ivsv", room, s), "ivsv.vpls")->why; };
    EXPECT_EQ(vplsWhy({}), "64 VPLs, the centres of 8 x 8 equal cells (vpl_layout=grid; each its cell of the "
                           "emitter, vpl_kernel=cell)");
    EXPECT_NE(vplsWhy({{"vpls", 128}}).find("16 x 8 equal cells"), std::string::npos) << vplsWhy({{"vpls", 128}});
    EXPECT_NE(vplsWhy({{"vpl_layout", 0}}).find("at Halton points (vpl_layout=halton; each a disc"), std::string::npos)
        << vplsWhy({{"vpl_layout", 0}});
    EXPECT_EQ(vplsWhy({{"vpl_kernel", 0}}).find("vpl_kernel"), std::string::npos) << vplsWhy({{"vpl_kernel", 0}});
    EXPECT_NE(findFeature(planOf("ivsv", room), "VPL_PIPELINE")->why.find("8 x 8 equal cells"), std::string::npos);
}

TEST(VsvPlan, QualitySweepAndStiffDeclarations) {
    for (const char* id : {"vsv", "ivsv"}) {
        const auto t = makeTechnique(id);
        for (bool quick : {true, false}) {
            const auto sweep = t->qualitySweep(quick);
            ASSERT_GE(sweep.size(), 2u) << id;
            for (const QualitySetting& q : sweep) EXPECT_NO_THROW(completeSettings(*t, q.settings)) << q.label;
            // Cheapest first: the voxel count never falls along the sweep.
            for (std::size_t i = 1; i < sweep.size(); ++i)
                EXPECT_LE(sweep[i - 1].settings.at("voxels"), sweep[i].settings.at("voxels")) << id;
        }
        EXPECT_NO_THROW(completeSettings(*t, t->stiffSettings())) << id;
        for (const char* cls : {"medium", "intensity", "scale", "singular-ray", "near-light", "epipole", "camera-placement",
                                "geometry", "depth-range", "phase"}) {
            const auto bound = t->stiffBound(cls);
            ASSERT_TRUE(bound.has_value()) << id << " " << cls;
            EXPECT_GT(bound->relativeL2, 0.0);
            EXPECT_FALSE(bound->why.empty());
        }
    }
}

}  // namespace
}  // namespace viz
