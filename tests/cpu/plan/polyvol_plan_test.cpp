// polyvol's plan on each built-in scene: which light and shadow paths are compiled in (and by which
// define they are compiled out), the triangle count the volume stage announces, culled lights, and what
// force_features turns on.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "scene/builtin_scenes.h"
#include "techniques/polyvol/light_volume_mesh.h"
#include "techniques/registry.h"

namespace viz {
namespace {

const FeaturePlan& requiredFeature(const Plan& plan, const std::string& name) {
    static const FeaturePlan kNone;
    const FeaturePlan* f = findFeature(plan, name);
    if (!f) ADD_FAILURE() << "polyvol lists no feature " << name;
    return f ? *f : kNone;
}

Plan polyvolPlan(const scene::Scene& scene, const Settings& given = {}) {
    const auto t = makeTechnique("polyvol");
    return t->plan(scene, completeSettings(*t, given));
}

Plan polyvolPlan(const std::string& sceneName, const Settings& given = {}) {
    return polyvolPlan(scene::makeBuiltinScene(sceneName), given);
}

bool mentions(const FeaturePlan& f, const std::string& text) { return f.why.find(text) != std::string::npos; }

// grate: one spot without cookie; stained-glass: a spot with a colour cookie; colonnade, forest, terrain:
// one sun (a 2D orthographic map); tv-room: one area light, 16 VPLs with cube maps. Each scene compiles
// in only the light and shadow-map code it uses, and says which define leaves the rest out.
TEST(PolyvolPlan, CompilesOnlyTheLightAndShadowCodeEachSceneUses) {
    struct Row {
        bool spot, cookie, cube, maps2D, area;
    };
    const std::map<std::string, Row> table = {
        {"grate", {true, false, false, true, false}},
        {"stained-glass", {true, true, false, true, false}},
        {"colonnade", {false, false, false, true, false}},
        {"forest", {false, false, false, true, false}},
        {"terrain", {false, false, false, true, false}},
        {"tv-room", {false, false, true, false, true}},
    };
    for (const auto& [name, row] : table) {
        const Plan p = polyvolPlan(name);
        for (const StagePlan& s : p.stages) EXPECT_TRUE(s.runs) << name << " " << s.stage;
        EXPECT_EQ(requiredFeature(p, "SPOT").enabled, row.spot) << name;
        EXPECT_EQ(requiredFeature(p, "COOKIE").enabled, row.cookie) << name;
        EXPECT_EQ(requiredFeature(p, "SHADOW_MAPS_CUBE").enabled, row.cube) << name;
        EXPECT_EQ(requiredFeature(p, "SHADOW_MAPS_2D").enabled, row.maps2D) << name;
        EXPECT_EQ(requiredFeature(p, "AREA_VPLS").enabled, row.area) << name;
        EXPECT_FALSE(requiredFeature(p, "AIRLIGHT_LUT").enabled) << name << ": analytic by default, no table";
        // Adaptive by default, at the default 1024^2 maps (2D) and 256^2 VPL faces, where it pays off.
        EXPECT_EQ(requiredFeature(p, "ADAPTIVE").enabled, row.maps2D) << name;
        EXPECT_EQ(requiredFeature(p, "ADAPTIVE_CUBES").enabled, row.cube) << name;
        // The define that leaves each unused path out is named.
        if (!row.spot) {
            EXPECT_TRUE(mentions(requiredFeature(p, "SPOT"), "LIGHTS_NO_SPOT")) << name;
        }
        if (!row.cookie) {
            EXPECT_TRUE(mentions(requiredFeature(p, "COOKIE"), "LIGHTS_NO_COOKIE")) << name;
        }
        if (!row.cube) {
            EXPECT_TRUE(mentions(requiredFeature(p, "SHADOW_MAPS_CUBE"), "SHADOW_NO_CUBE")) << name;
        }
        if (!row.maps2D) {
            EXPECT_TRUE(mentions(requiredFeature(p, "SHADOW_MAPS_2D"), "SHADOW_NO_2D")) << name;
        }
        for (const FeaturePlan& f : p.features) EXPECT_NE(f.feature.rfind("LIGHT ", 0), 0u) << name << ": no culled light";
    }
}

// The volume stage announces the triangle count of the mesh it draws: the static grid plus the closure
// of a 2D map (light_volume_mesh.h builds the actual key lists), or per VPL a cube's six grids plus its
// seams (VPL cubes are at most 256^2 per face); with adaptive tessellation that count is the most it draws.
TEST(PolyvolPlan, VolumeStageAnnouncesItsTriangleCount) {
    const Plan grate = polyvolPlan("grate", {{"shadow_map", 256}});
    ASSERT_NE(grate.stages[2].why.find("triangles"), std::string::npos) << grate.stages[2].why;
    EXPECT_EQ(std::stoll(grate.stages[2].why),
              polyvol::gridTriangleCount(256, 1) + std::int64_t(polyvol::gridClosure(256).size() / 3));
    const Plan room = polyvolPlan("tv-room", {{"shadow_map", 1024}});
    const std::int64_t cube = polyvol::gridTriangleCount(256, 6) + std::int64_t(polyvol::cubeSeams(256).size() / 3);
    EXPECT_EQ(std::stoll(room.stages[2].why), 16 * cube);
    EXPECT_TRUE(room.stages[2].why.find("at most") != std::string::npos) << room.stages[2].why;
}

// Choices made by settings: the table and adaptive tessellation (2D maps: ADAPTIVE; cube faces:
// ADAPTIVE_CUBES), and a medium that scatters nothing skips the volume stage.
TEST(PolyvolPlan, SettingsChooseTheTableAndTheTessellation) {
    EXPECT_TRUE(requiredFeature(polyvolPlan("grate", {{"airlight", 1}}), "AIRLIGHT_LUT").enabled);
    EXPECT_TRUE(requiredFeature(polyvolPlan("colonnade", {{"tessellation", 1}}), "ADAPTIVE").enabled);
    EXPECT_TRUE(requiredFeature(polyvolPlan("colonnade", {{"tessellation", 1}, {"shadow_map", 512}}), "ADAPTIVE").enabled);
    const Plan room = polyvolPlan("tv-room", {{"tessellation", 1}});
    EXPECT_FALSE(requiredFeature(room, "ADAPTIVE").enabled);
    EXPECT_TRUE(mentions(requiredFeature(room, "ADAPTIVE"), "no 2D map")) << requiredFeature(room, "ADAPTIVE").why;
    EXPECT_TRUE(requiredFeature(room, "ADAPTIVE_CUBES").enabled) << requiredFeature(room, "ADAPTIVE_CUBES").why;
    for (const std::string name : {"colonnade", "tv-room"}) {
        const Plan fixed = polyvolPlan(name, {{"tessellation", 0}});
        EXPECT_FALSE(requiredFeature(fixed, "ADAPTIVE").enabled) << name;
        EXPECT_FALSE(requiredFeature(fixed, "ADAPTIVE_CUBES").enabled) << name;
        // draw_triangles cuts the static mesh, and the refinement needs a power-of-two map: both leave
        // adaptive tessellation out, saying so.
        const Plan cut = polyvolPlan(name, {{"draw_triangles", 1000}});
        const Plan odd = polyvolPlan(name, {{"shadow_map", 600}});
        for (const char* f : {"ADAPTIVE", "ADAPTIVE_CUBES"}) EXPECT_FALSE(requiredFeature(cut, f).enabled) << name << " " << f;
        const char* used = name == "tv-room" ? "ADAPTIVE_CUBES" : "ADAPTIVE";
        EXPECT_TRUE(mentions(requiredFeature(cut, used), "draw_triangles")) << requiredFeature(cut, used).why;
        if (name == "colonnade") {
            EXPECT_FALSE(requiredFeature(odd, used).enabled);
            EXPECT_TRUE(mentions(requiredFeature(odd, used), "power of two")) << requiredFeature(odd, used).why;
        } else {
            // tv-room's VPL faces stop at 256^2, a power of two, whatever shadow_map is above it.
            EXPECT_TRUE(requiredFeature(odd, used).enabled) << requiredFeature(odd, used).why;
        }
    }
    scene::Scene clear = scene::makeBuiltinScene("grate");
    clear.medium.sigma_s = 0.0;
    const Plan p = polyvolPlan(clear);
    EXPECT_FALSE(p.stages[2].runs);
    EXPECT_TRUE(p.stages[2].why.find("sigma_s = 0") != std::string::npos);
    // The crack detector has a constant integrand: it draws even in a clear medium.
    EXPECT_TRUE(polyvolPlan(clear, {{"crack_check", 1}}).stages[2].runs);
}

// Below 512^2 adaptive tessellation did not pay off (forest, README benchmark): the plan leaves it out
// and says why, unless force_features keeps it.
TEST(PolyvolPlan, AdaptiveTessellationIsLeftOutBelowItsBreakEvenSize) {
    for (const std::string name : {"colonnade", "forest", "grate"}) {
        const FeaturePlan small = requiredFeature(polyvolPlan(name, {{"tessellation", 1}, {"shadow_map", 256}}), "ADAPTIVE");
        EXPECT_FALSE(small.enabled) << name;
        EXPECT_TRUE(mentions(small, "did not pay off")) << small.why;
        const FeaturePlan forced =
            requiredFeature(polyvolPlan(name, {{"tessellation", 1}, {"shadow_map", 256}, {"force_features", 1}}), "ADAPTIVE");
        EXPECT_TRUE(forced.enabled) << name;
        EXPECT_TRUE(mentions(forced, "forced on")) << forced.why;
    }
    // Cube faces below 128^2 (tv-room's VPL faces follow shadow_map up to 256^2).
    const FeaturePlan cubes = requiredFeature(polyvolPlan("tv-room", {{"shadow_map", 64}}), "ADAPTIVE_CUBES");
    EXPECT_FALSE(cubes.enabled);
    EXPECT_TRUE(mentions(cubes, "did not pay off")) << cubes.why;
    EXPECT_TRUE(requiredFeature(polyvolPlan("tv-room", {{"shadow_map", 64}, {"force_features", 1}}), "ADAPTIVE_CUBES").enabled);
    EXPECT_TRUE(requiredFeature(polyvolPlan("tv-room", {{"shadow_map", 128}}), "ADAPTIVE_CUBES").enabled);
    // Static stays static whatever the size, forced or not.
    for (const char* f : {"ADAPTIVE", "ADAPTIVE_CUBES"}) {
        EXPECT_FALSE(requiredFeature(polyvolPlan("forest", {{"shadow_map", 2048}, {"tessellation", 0}, {"force_features", 1}}), f)
                         .enabled);
        EXPECT_FALSE(requiredFeature(polyvolPlan("tv-room", {{"tessellation", 0}, {"force_features", 1}}), f).enabled);
    }
}

// A light whose lit volume misses the view volume is culled (render::planCulledLights): it is listed,
// gets no map and adds no triangles.
TEST(PolyvolPlan, CulledLightsAreListedAndAddNoTriangles) {
    scene::Scene scene = scene::makeBuiltinScene("grate");
    const Plan before = polyvolPlan(scene, {{"shadow_map", 256}});
    scene::Light behind = scene.lights[0];
    behind.name = "behind";
    behind.position = scene.camera.position - 2.0 * scene.camera.forward;
    behind.direction = -scene.camera.forward;  // shines away from everything the camera sees
    scene.lights.push_back(behind);
    const Plan after = polyvolPlan(scene, {{"shadow_map", 256}});
    const FeaturePlan& culled = requiredFeature(after, "LIGHT behind");
    EXPECT_FALSE(culled.enabled);
    EXPECT_FALSE(culled.why.empty());
    EXPECT_EQ(std::stoll(after.stages[2].why), std::stoll(before.stages[2].why));
}

// force_features=1 turns on every scene-pruned path (the light kinds and map kinds) and runs every
// stage, keeping the reason it would have been left out; features chosen by settings stay as set.
TEST(PolyvolPlan, ForceFeaturesTurnsOnEverySceneChoiceOnly) {
    for (const std::string name : {"grate", "colonnade", "tv-room"}) {
        const Plan p = polyvolPlan(name, {{"force_features", 1}});
        for (const char* f : {"SPOT", "COOKIE", "SHADOW_MAPS_CUBE", "SHADOW_MAPS_2D"}) {
            EXPECT_TRUE(requiredFeature(p, f).enabled) << name << " " << f;
            EXPECT_EQ(mentions(requiredFeature(p, f), "forced on"), !requiredFeature(polyvolPlan(name), f).enabled) << name << " " << f;
        }
        EXPECT_FALSE(requiredFeature(p, "AIRLIGHT_LUT").enabled) << name;
        // Tessellation is a setting: as without force_features (the default maps are above its
        // break-even sizes).
        for (const char* f : {"ADAPTIVE", "ADAPTIVE_CUBES"}) {
            EXPECT_EQ(requiredFeature(p, f).enabled, requiredFeature(polyvolPlan(name), f).enabled) << name << " " << f;
        }
    }
    scene::Scene clear = scene::makeBuiltinScene("grate");
    clear.medium.sigma_s = 0.0;
    EXPECT_TRUE(polyvolPlan(clear, {{"force_features", 1}}).stages[2].runs);
}

}  // namespace
}  // namespace viz
