// minmax's plan scene by scene: which stages and shader permutations each built-in scene runs, and why;
// force_features=1 turns every pruned one on. The expectations follow from the scenes' lights and
// cameras (viz/scene/builtin_scenes.cpp), not from running the plan.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "scene/builtin_scenes.h"
#include "technique_run.h"
#include "techniques/registry.h"

namespace viz {
namespace {

Plan minmaxPlan(const std::string& sceneName, const Settings& given = {}) {
    return testing::planOf("minmax", scene::makeBuiltinScene(sceneName), given);
}

struct Expected {
    bool nearEpipole, spot, cookie, cubes, maps2D, brute, rectify, svd;
};

// grate: a spot seen from the side, its position in the image; stained-glass: a spot with a cookie in
// view; colonnade and terrain: a sun whose epipoles lie far off screen; forest: a sun low in the view
// (its epipole near the screen); tv-room: one area light, marched as VPLs with cube maps.
// integrand=auto takes svd for the spots and analytic for the suns (a closed form, cheaper than the tables'
// lookups; integrand_choice.h) and on tv-room (no light to factorise).
const std::map<std::string, Expected> kExpected = {
    {"grate", {true, true, false, false, true, false, true, true}},
    {"stained-glass", {true, true, true, false, true, false, true, true}},
    {"colonnade", {false, false, false, false, true, false, true, false}},
    {"terrain", {false, false, false, false, true, false, true, false}},
    {"forest", {true, false, false, false, true, false, true, false}},
    {"tv-room", {false, false, false, true, false, true, false, false}},
};

TEST(MinmaxPlan, EachBuiltinSceneRunsWhatItsLightsAndCameraNeed) {
    for (const auto& [sceneName, e] : kExpected) {
        const Plan plan = minmaxPlan(sceneName);
        const std::map<std::string, bool> features = {
            {"NEAR_EPIPOLE", e.nearEpipole}, {"SPOT", e.spot},           {"COOKIE", e.cookie},
            {"SHADOW_MAPS_CUBE", e.cubes},   {"SHADOW_MAPS_2D", e.maps2D}, {"BRUTE_FORCE_LIGHTS", e.brute},
            {"INTEGRAND_SVD", e.svd},        {"TREE_TRAVERSAL", true}};
        for (const auto& [name, on] : features) {
            const FeaturePlan* f = findFeature(plan, name);
            ASSERT_NE(f, nullptr) << sceneName << " lists no feature " << name;
            EXPECT_EQ(f->enabled, on) << sceneName << ": " << name << " (" << f->why << ")";
            EXPECT_FALSE(f->why.empty()) << sceneName << ": " << name;
        }
        for (const char* stage : {"minmax.rectify", "minmax.mipmap"}) {
            const StagePlan* s = findStage(plan, stage);
            ASSERT_NE(s, nullptr) << stage;
            EXPECT_EQ(s->runs, e.rectify) << sceneName << ": " << stage << " (" << s->why << ")";
        }
        const StagePlan* traverse = findStage(plan, "minmax.traverse");
        ASSERT_NE(traverse, nullptr);
        EXPECT_TRUE(traverse->runs) << sceneName << ": every scene scatters";
        // No built-in scene has a light outside the view volume.
        for (const FeaturePlan& f : plan.features) EXPECT_NE(f.feature.rfind("LIGHT ", 0), 0u) << f.feature;
    }
}

TEST(MinmaxPlan, ReasonsNameTheCause) {
    const Plan colonnade = minmaxPlan("colonnade");
    EXPECT_NE(findFeature(colonnade, "NEAR_EPIPOLE")->why.find("far off screen"), std::string::npos);
    EXPECT_NE(findFeature(colonnade, "SPOT")->why.find("LIGHTS_NO_SPOT"), std::string::npos);
    const Plan tv = minmaxPlan("tv-room");
    EXPECT_NE(findStage(tv, "minmax.rectify")->why.find("no spot or directional light"), std::string::npos);
    const Plan grate = minmaxPlan("grate");
    EXPECT_NE(findFeature(grate, "NEAR_EPIPOLE")->why.find("NEAR_EPIPOLE"), std::string::npos);
}

// integrand=auto: suns alone get the closed form without a factorisation; a spot in the same scene brings
// the tables back (checked on the spot's and the sun's fully lit rays), and thickening the medium past
// what rank 4 holds sends it back to analytic for the tables' error, not for the suns.
TEST(MinmaxPlan, SunsAloneTakeTheClosedFormAndASpotBringsTheTablesBack) {
    scene::Scene terrain = scene::makeBuiltinScene("terrain");
    const FeaturePlan suns = *findFeature(testing::planOf("minmax", terrain, {}), "INTEGRAND_SVD");
    EXPECT_FALSE(suns.enabled);
    EXPECT_NE(suns.why.find("suns only"), std::string::npos) << suns.why;
    scene::Light spot = scene::makeBuiltinScene("grate").lights.at(0);
    ASSERT_EQ(spot.type, scene::LightType::Spot);
    spot.position = terrain.camera.position + 40.0 * terrain.camera.forward + glm::dvec3(0.0, 20.0, 0.0);
    spot.direction = glm::dvec3(0.0, -1.0, 0.0);
    terrain.lights.push_back(spot);
    const FeaturePlan mixed = *findFeature(testing::planOf("minmax", terrain, {}), "INTEGRAND_SVD");
    EXPECT_TRUE(mixed.enabled) << mixed.why;
    EXPECT_NE(mixed.why.find("rank-4"), std::string::npos) << mixed.why;
    terrain.medium.sigma_s = terrain.medium.sigma_a = 25.0;
    const FeaturePlan thick = *findFeature(testing::planOf("minmax", terrain, {}), "INTEGRAND_SVD");
    EXPECT_FALSE(thick.enabled) << thick.why;
    EXPECT_NE(thick.why.find("off on the fully lit rays"), std::string::npos) << thick.why;
}

// The report's sweep measures minmax as a user runs it: its grid leaves the integrand to the plan (on
// grate's spot the tables, on terrain's sun the closed form, at every grid point) and both sweeps hold
// the default settings themselves; the forced points of the full sweep say which integrand they force.
TEST(MinmaxPlan, QualitySweepRunsTheDefaultIntegrandAndHoldsTheDefaults) {
    const auto t = makeTechnique("minmax");
    const Settings defaults = completeSettings(*t, {});
    const scene::Scene grate = scene::makeBuiltinScene("grate"), terrain = scene::makeBuiltinScene("terrain");
    for (bool quick : {true, false}) {
        int holdsDefaults = 0;
        for (const QualitySetting& q : t->qualitySweep(quick)) {
            const Settings complete = completeSettings(*t, q.settings);
            holdsDefaults += complete == defaults ? 1 : 0;
            if (q.label.rfind("map=", 0) != 0) {
                EXPECT_FALSE(quick) << q.label << ": the quick sweep forces nothing";
                EXPECT_EQ(q.label.find(complete.at("integrand") == 0.0 ? "analytic" : "svd"), 0u) << q.label;
                continue;
            }
            EXPECT_EQ(q.settings.count("integrand"), 0u) << q.label;
            EXPECT_TRUE(findFeature(t->plan(grate, complete), "INTEGRAND_SVD")->enabled) << q.label;
            EXPECT_FALSE(findFeature(t->plan(terrain, complete), "INTEGRAND_SVD")->enabled) << q.label;
        }
        EXPECT_EQ(holdsDefaults, 1) << (quick ? "quick" : "full");
    }
}

TEST(MinmaxPlan, SettingsChooseTheIntegrandAndTheNearEpipolePass) {
    EXPECT_TRUE(findFeature(minmaxPlan("terrain", {{"integrand", 1.0}}), "INTEGRAND_SVD")->enabled);
    const Plan svdGrate = minmaxPlan("grate", {{"integrand", 1.0}});
    ASSERT_NE(findFeature(svdGrate, "TEXTURED_PREFIX_SUMS"), nullptr);
    EXPECT_TRUE(findFeature(svdGrate, "TEXTURED_PREFIX_SUMS")->enabled);
    const Plan svdTerrain = minmaxPlan("terrain", {{"integrand", 1.0}});
    EXPECT_FALSE(findFeature(svdTerrain, "TEXTURED_PREFIX_SUMS")->enabled);
    EXPECT_FALSE(findFeature(minmaxPlan("grate", {{"epipole_radius", 0.0}}), "NEAR_EPIPOLE")->enabled);
    EXPECT_FALSE(findFeature(minmaxPlan("grate", {{"traversal", 1.0}}), "TREE_TRAVERSAL")->enabled);
}

TEST(MinmaxPlan, ForceFeaturesTurnsEveryScenePrunedPartOn) {
    for (const auto& [sceneName, e] : kExpected) {
        const Plan plan = minmaxPlan(sceneName, {{"force_features", 1.0}});
        for (const StagePlan& s : plan.stages) EXPECT_TRUE(s.runs) << sceneName << " " << s.stage;
        for (const char* name : {"NEAR_EPIPOLE", "SPOT", "COOKIE", "SHADOW_MAPS_CUBE", "SHADOW_MAPS_2D"}) {
            const FeaturePlan* f = findFeature(plan, name);
            ASSERT_NE(f, nullptr) << name;
            EXPECT_TRUE(f->enabled) << sceneName << ": " << name << " (" << f->why << ")";
        }
        // Setting choices are not scene pruning: force leaves them alone.
        EXPECT_EQ(findFeature(plan, "INTEGRAND_SVD")->enabled, e.svd) << sceneName;
    }
    // Forcing a feature the scene uses anyway changes nothing.
    EXPECT_EQ(findFeature(minmaxPlan("grate", {{"force_features", 1.0}}), "SPOT")->why,
              findFeature(minmaxPlan("grate"), "SPOT")->why);
}

}  // namespace
}  // namespace viz
