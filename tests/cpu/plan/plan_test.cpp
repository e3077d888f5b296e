// What each technique leaves out for each built-in scene: the plan is asserted scene by scene, and
// every technique's plan is checked for the general contract (every stage listed once in order, every
// skipped stage and disabled feature with a reason).
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>
#include <vector>

#include "scene/builtin_scenes.h"
#include "technique_run.h"
#include "techniques/registry.h"

namespace viz {
namespace {

const FeaturePlan* feature(const Plan& plan, const std::string& name) { return findFeature(plan, name); }

Plan planFor(const std::string& technique, const std::string& sceneName, const Settings& given = {}) {
    return testing::planOf(technique, scene::makeBuiltinScene(sceneName), given);
}

TEST(Plan, EveryTechniqueListsItsStagesInOrderAndExplainsEverySkip) {
    for (const std::string& id : techniqueIds())
        for (const std::string& sceneName : scene::builtinSceneNames()) {
            const auto t = makeTechnique(id);
            const Plan plan = t->plan(scene::makeBuiltinScene(sceneName), completeSettings(*t, {}));
            ASSERT_EQ(plan.stages.size(), t->stages().size()) << id << " " << sceneName;
            for (std::size_t i = 0; i < plan.stages.size(); ++i) {
                EXPECT_EQ(plan.stages[i].stage, t->stages()[i].id) << id << " " << sceneName;
                if (!plan.stages[i].runs) {
                    EXPECT_FALSE(plan.stages[i].why.empty()) << id << " " << plan.stages[i].stage;
                }
            }
            for (const FeaturePlan& f : plan.features)
                if (!f.enabled) {
                    EXPECT_FALSE(f.why.empty()) << id << " " << sceneName << " " << f.feature;
                }
        }
}

// Expected on/off per scene for the features a scene decides (settings at their defaults).
using FeatureTable = std::map<std::string, std::map<std::string, bool>>;

void expectFeatures(const std::string& technique, const FeatureTable& table) {
    for (const auto& [sceneName, expected] : table) {
        const Plan plan = planFor(technique, sceneName);
        for (const auto& [name, on] : expected) {
            const FeaturePlan* f = feature(plan, name);
            ASSERT_NE(f, nullptr) << technique << " lists no feature " << name;
            EXPECT_EQ(f->enabled, on) << technique << " on " << sceneName << ": " << name << " (" << f->why << ")";
        }
    }
}

TEST(Plan, RaymarchCompilesOnlyTheLightAndShadowCodeEachSceneUses) {
    // grate and stained-glass: one spot (stained-glass's with a cookie); colonnade, forest, terrain: one
    // sun; tv-room: one area light (VPLs with cube maps).
    const std::map<std::string, bool> sun = {{"SPOT", false}, {"COOKIE", false}, {"AREA_VPLS", false},
                                             {"SHADOW_MAPS_CUBE", false}, {"SHADOW_MAPS_2D", true}};
    expectFeatures("raymarch",
                   {{"grate", {{"SPOT", true}, {"COOKIE", false}, {"AREA_VPLS", false}, {"SHADOW_MAPS_CUBE", false},
                               {"SHADOW_MAPS_2D", true}}},
                    {"stained-glass", {{"SPOT", true}, {"COOKIE", true}, {"SHADOW_MAPS_CUBE", false}}},
                    {"colonnade", sun},
                    {"forest", sun},
                    {"terrain", sun},
                    {"tv-room", {{"SPOT", false}, {"COOKIE", false}, {"AREA_VPLS", true}, {"SHADOW_MAPS_CUBE", true},
                                 {"SHADOW_MAPS_2D", false}}}});
}

TEST(Plan, SlicesClipsOnlyWhereALightFrustumExists) {
    const std::map<std::string, bool> sun = {{"SPOT_FALLOFF", false}, {"COOKIE", false}, {"CLIP", false},
                                             {"UNBOUNDED_PLANES", true}, {"SHADOW_MAPS_CUBE", false}};
    expectFeatures("slices", {{"grate", {{"SPOT_FALLOFF", true}, {"COOKIE", false}, {"CLIP", true},
                                         {"UNBOUNDED_PLANES", false}, {"SHADOW_MAPS_CUBE", false}}},
                              {"stained-glass", {{"SPOT_FALLOFF", true}, {"COOKIE", true}, {"CLIP", true}}},
                              {"colonnade", sun},
                              {"forest", sun},
                              {"terrain", sun},
                              {"tv-room", {{"CLIP", false}, {"UNBOUNDED_PLANES", true}, {"SHADOW_MAPS_CUBE", true}}}});
    // A directional light boxed into its shadow map's volume is clipped to that box.
    EXPECT_TRUE(feature(planFor("slices", "colonnade", {{"directional_box", 1}}), "CLIP")->enabled);
}

TEST(Plan, NothingScattersWithoutScattering) {
    scene::Scene s = scene::makeBuiltinScene("grate");
    s.medium.sigma_s = 0.0;
    const auto t = makeTechnique("raymarch");
    const Plan plan = t->plan(s, completeSettings(*t, {}));
    bool skipped = false;
    for (const StagePlan& st : plan.stages) skipped |= st.stage == "raymarch.march" && !st.runs;
    EXPECT_TRUE(skipped);
}

// The picked pixel is one declaration: every technique that follows it has pick_x and pick_y with the
// same range, and each one's run maps -1 to the centre and clamps past the edge, checked against the
// image's own centre and corner here (not against pickParam's numbers).
TEST(Params, EveryTechniqueWithAPickedPixelDeclaresTheSameRange) {
    int withPick = 0;
    std::vector<std::pair<double, double>> ranges;
    for (const std::string& id : techniqueIds()) {
        const auto t = makeTechnique(id);
        const ParamInfo* x = nullptr;
        const ParamInfo* y = nullptr;
        for (const ParamInfo& p : t->params()) {
            if (p.name == "pick_x") x = &p;
            if (p.name == "pick_y") y = &p;
        }
        ASSERT_EQ(x == nullptr, y == nullptr) << id << " declares only one of pick_x / pick_y";
        if (!x) continue;
        ++withPick;
        EXPECT_EQ(x->defaultValue, -1.0) << id;
        EXPECT_EQ(y->defaultValue, -1.0) << id;
        EXPECT_TRUE(x->integer && y->integer) << id;
        ranges.push_back({x->minValue, x->maxValue});
        ranges.push_back({y->minValue, y->maxValue});
        // The largest image a user can ask for (--size up to 8192) can be picked to its last pixel.
        EXPECT_GE(x->maxValue, 8191.0) << id;
        EXPECT_GE(y->maxValue, 8191.0) << id;
    }
    EXPECT_GE(withPick, 4);  // slices, minmax, vsv, ivsv
    for (const auto& r : ranges) EXPECT_EQ(r, ranges.front());
}

// The controls reach a run as typed fields, never as settings: setRunSettings moves every control name a
// user can write (--set, a lesson) out of the settings and into FrameInput::controls, and the defaults
// there are the declared parameters' defaults.
TEST(Params, ControlsLeaveTheSettingsForTypedFields) {
    for (const std::string& id : techniqueIds()) {
        const auto t = makeTechnique(id);
        const Controls c = t->controls();
        Settings given;
        if (c.pickedPixel) given = {{kPickX, 60}, {kPickY, 7}};
        if (c.orbitCamera) given.insert({{kOrbitYaw, 120}, {kOrbitPitch, -10}, {kOrbitZoom, 2.5}});
        if (c.animationTime) given[kAnimationTime] = 3.25;
        FrameInput in;
        setRunSettings(in, completeSettings(*t, given));
        for (const char* name : {kPickX, kPickY, kOrbitYaw, kOrbitPitch, kOrbitZoom, kAnimationTime})
            EXPECT_EQ(in.settings.count(name), 0u) << id << " " << name;
        EXPECT_EQ(in.controls.pickX, c.pickedPixel ? 60 : -1) << id;
        EXPECT_EQ(in.controls.pickY, c.pickedPixel ? 7 : -1) << id;
        EXPECT_EQ(in.controls.orbitYaw, c.orbitCamera ? 120.0 : 35.0) << id;
        EXPECT_EQ(in.controls.orbitPitch, c.orbitCamera ? -10.0 : 25.0) << id;
        EXPECT_EQ(in.controls.orbitZoom, c.orbitCamera ? 2.5 : 1.0) << id;
        EXPECT_EQ(in.controls.time, c.animationTime ? 3.25 : 0.0) << id;
        // Every other complete setting is still there.
        std::size_t named = 0;
        for (const auto& [name, value] : controlSettings({})) named += findParam(*t, name) != nullptr;
        EXPECT_EQ(in.settings.size() + named, completeSettings(*t, {}).size()) << id;
    }
    // The defaults a run gets without any control named are the declared ones.
    const FrameControls none;
    for (const ParamInfo& p : orbitParams(""))
        EXPECT_EQ(controlSettings(none).at(p.name), p.defaultValue) << p.name;
    EXPECT_EQ(controlSettings(none).at(kPickX), pickParam('x', "").defaultValue);
    EXPECT_EQ(controlSettings(none).at(kAnimationTime), animationTimeParam("").defaultValue);
}

TEST(Params, ThePickedPixelIsTheCentreByDefaultAndClampsAtTheEdge) {
    FrameInput input;
    input.width = 33;
    input.height = 20;
    input.controls.pickX = input.controls.pickY = -1;
    EXPECT_EQ(pickedPixel(input), glm::ivec2(16, 10));
    input.controls.pickX = 1000;
    input.controls.pickY = 7;
    EXPECT_EQ(pickedPixel(input), glm::ivec2(32, 7));
    input.controls.pickX = 0;
    input.controls.pickY = 5000;
    EXPECT_EQ(pickedPixel(input), glm::ivec2(0, 19));
}

// A view's stage: the one that declares it, or for a numbered sibling (`x.shadow_map.3`) the one that
// declares the first; anything else, a stage's own id among them, has none.
TEST(StageOfIntermediate, ExactIdsAndNumberedSiblingsOnly) {
    std::vector<StageInfo> stages(3);
    stages[0].id = "t.shadow_maps";
    stages[0].intermediates = {"t.shadow_map", "t.cookies"};
    stages[1].id = "t.march";
    stages[1].intermediates = {"t.airlight", "t.map.2d"};
    stages[2].id = "t.compose";
    EXPECT_EQ(stageOfIntermediate(stages, "t.shadow_map"), 0);
    EXPECT_EQ(stageOfIntermediate(stages, "t.shadow_map.1"), 0);
    EXPECT_EQ(stageOfIntermediate(stages, "t.shadow_map.17"), 0);
    EXPECT_EQ(stageOfIntermediate(stages, "t.airlight"), 1);
    EXPECT_EQ(stageOfIntermediate(stages, "t.map.2d"), 1);
    EXPECT_EQ(stageOfIntermediate(stages, "t.shadow_map.x"), -1);
    EXPECT_EQ(stageOfIntermediate(stages, "t.shadow_map."), -1);
    EXPECT_EQ(stageOfIntermediate(stages, "t.shadow_maps"), -1);
    EXPECT_EQ(stageOfIntermediate(stages, "t.cookies2"), -1);
    EXPECT_EQ(stageOfIntermediate(stages, "t.march"), -1);
}

// The report measures each technique as a user runs it: both of its sweeps, the quick one too, hold the
// technique's default settings (the sweep may set what the report must not time, such as slices'
// recording of one pixel's planes, to a value that changes no image).
TEST(QualitySweep, EverySweepHoldsTheTechniquesDefaults) {
    for (const std::string& id : techniqueIds()) {
        const auto t = makeTechnique(id);
        Settings defaults = completeSettings(*t, {});
        defaults.erase("ray_planes");
        for (bool quick : {true, false}) {
            int found = 0;
            for (const QualitySetting& q : t->qualitySweep(quick)) {
                Settings complete = completeSettings(*t, q.settings);
                complete.erase("ray_planes");
                found += complete == defaults ? 1 : 0;
            }
            EXPECT_GE(found, 1) << id << (quick ? " quick" : " full") << " sweep never runs the defaults";
        }
    }
}

// On a scene with an area light the report adds more VPLs (Technique::areaLightSweep): each added point
// is the defaults with a larger VPL count (area_samples for the techniques on the shared VPLs, ivsv's own
// vpls), so that it extends the technique's own front; where another knob sets how finely each VPL's ray
// is integrated (raymarch's samples, minmax's vpl_samples, slices' planes) each count comes twice, at that
// knob's default and at one other value, so that the front can trade the two; vsv, which hands an area
// light to an inner ivsv at its defaults, adds none.
TEST(QualitySweep, AreaLightPointsAreTheDefaultsWithMoreVpls) {
    const std::map<std::string, std::string> count = {{"raymarch", "area_samples"}, {"slices", "area_samples"},
                                                      {"polyvol", "area_samples"}, {"minmax", "area_samples"},
                                                      {"ivsv", "vpls"}};
    const std::map<std::string, std::string> march = {{"raymarch", "samples"}, {"minmax", "vpl_samples"},
                                                      {"slices", "planes"}};
    for (const std::string& id : techniqueIds()) {
        const auto t = makeTechnique(id);
        const Settings defaults = completeSettings(*t, {});
        for (bool quick : {true, false}) {
            const std::vector<QualitySetting> points = t->areaLightSweep(quick);
            const auto it = count.find(id);
            if (it == count.end()) {
                EXPECT_TRUE(points.empty()) << id;
                continue;
            }
            // polyvol's quick sweep leaves them out (each VPL is a cube volume: 8^2 would double the
            // quick report's time on tv-room); ivsv's full sweep has its 256 VPLs already.
            EXPECT_EQ(points.empty(), (quick && id == "polyvol") || (!quick && id == "ivsv"))
                << id << (quick ? " quick" : " full");
            const std::string& param = it->second;
            const auto marched = march.find(id);
            std::map<double, std::set<double>> marchesPerCount;  // VPL count -> the march's sample counts
            for (const QualitySetting& q : points) {
                Settings complete = completeSettings(*t, q.settings);
                const double n = complete.at(param);
                EXPECT_GT(n, defaults.at(param)) << id << " " << q.label << ": not more VPLs than the default";
                EXPECT_EQ(q.label.rfind(param + "=" + std::to_string(int(n)), 0), 0u) << q.label;
                complete[param] = defaults.at(param);
                if (marched != march.end()) {
                    const double m = complete.at(marched->second);
                    if (m != defaults.at(marched->second)) {
                        EXPECT_NE(q.label.find(marched->second + "=" + std::to_string(int(m))), std::string::npos)
                            << q.label;
                    }
                    marchesPerCount[n].insert(m);
                    complete[marched->second] = defaults.at(marched->second);
                }
                EXPECT_EQ(complete, defaults) << id << " " << q.label << " changes more than the VPLs and their march";
            }
            for (const auto& [n, marches] : marchesPerCount)
                EXPECT_EQ(marches.size(), 2u) << id << " at " << n << " VPLs per axis: the default march and a shorter one";
        }
    }
}

}  // namespace
}  // namespace viz
