// polyvol's adaptive tessellation of cube faces (point lights, area-light VPLs): each face refined on its
// own with its border ring at texel resolution, so the seams close the volume. Checked against the static
// mesh (same image, fewer triangles), with the crack detector from outside, inside and at a cube corner,
// and by the plan's choice.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "polyvol_test_util.h"
#include "scene/builtin_scenes.h"
#include "techniques/registry.h"

namespace {

using viz::testing::allFinite;
using viz::testing::crackPixels;
using viz::testing::lookAtCamera;
using viz::testing::omniGrate;
using viz::testing::PolyvolTest;
using viz::testing::relativeL2;
using viz::testing::trianglesDrawn;
using viz::testing::volumeMs;

}  // namespace

// The image of the static cube mesh with a fraction of its triangles: a point light (the omni grate) and
// an area light's VPL cubes (tv-room, 2x2 VPLs).
TEST_F(PolyvolTest, AdaptiveCubeFacesMatchStaticWithFewerTriangles) {
    const std::pair<std::string, viz::scene::Scene> cases[] = {{"omni grate", omniGrate()},
                                                               {"tv-room", viz::scene::makeBuiltinScene("tv-room")}};
    for (const auto& [name, scene] : cases) {
        const viz::Settings base = {{"shadow_map", 128}, {"area_samples", 2}, {"tessellation", 0}};
        viz::Settings adaptiveSettings = base;
        adaptiveSettings["tessellation"] = 1;
        const viz::FrameOutput fixed = render(scene, "polyvol", base, 160, 120);
        const viz::FrameOutput adaptive = render(scene, "polyvol", adaptiveSettings, 160, 120);
        ASSERT_TRUE(allFinite(adaptive.airlight)) << name;
        const double e = relativeL2(adaptive.airlight, fixed.airlight);
        const std::int64_t nStatic = trianglesDrawn(fixed), nAdaptive = trianglesDrawn(adaptive);
        std::printf("%s 128^2 cube faces: static %lld triangles, adaptive %lld; relative L2 adaptive vs static %.2e\n",
                    name.c_str(), (long long)nStatic, (long long)nAdaptive, e);
        EXPECT_LT(e, 1e-3) << name;
        EXPECT_LT(nAdaptive, nStatic / 2) << name;
    }
}

// Watertight at every threshold: from the scene's camera, from inside the cube volume and looking at a
// cube corner (three faces and three seam strips meet), and on tv-room's VPL cubes.
TEST_F(PolyvolTest, CrackDetectorFindsNoHoleWithAdaptiveCubeFaces) {
    const viz::scene::Scene omni = omniGrate();
    viz::scene::Scene inside = omni, corner = omni;
    inside.camera = lookAtCamera(omni.camera, {0.3, 4.0, 0.5}, {1.0, 5.0, -1.0});
    corner.camera = lookAtCamera(omni.camera, {0.0, 6.2, 0.0}, {1.0, 7.2, 1.0});
    const std::pair<const char*, const viz::scene::Scene*> views[] = {
        {"omni grate", &omni}, {"inside", &inside}, {"corner", &corner}};
    for (const auto& [name, scene] : views) {
        for (double threshold : {1e-4, 1e-2}) {
            const viz::FrameOutput out = render(*scene, "polyvol",
                                                {{"shadow_map", 64}, {"tessellation", 1}, {"force_features", 1},
                                                 {"threshold", threshold}, {"crack_check", 1}},
                                                160, 120, 2, {"polyvol.crossings"});
            EXPECT_EQ(crackPixels(out), 0) << name << " threshold " << threshold;
        }
    }
    const viz::scene::Scene room = viz::scene::makeBuiltinScene("tv-room");
    const viz::FrameOutput out = render(room, "polyvol",
                                        {{"shadow_map", 64}, {"area_samples", 2}, {"tessellation", 1},
                                         {"force_features", 1}, {"threshold", 1e-2}, {"crack_check", 1}},
                                        160, 120, 2, {"polyvol.crossings"});
    EXPECT_EQ(crackPixels(out), 0) << "tv-room";
}

// A spot and a point light in one scene: each kind keeps its own buffers; both volumes adaptive, the
// image as static, and watertight. (Their marks: polyvol_markers_test.cpp.)
TEST_F(PolyvolTest, ASpotAndAPointLightAreBothTessellatedAdaptively) {
    viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    viz::scene::Light point = omniGrate().lights.front();
    point.name = "point";
    point.position += glm::dvec3(1.5, 0.0, 0.5);
    point.intensity *= 0.5;
    scene.lights.push_back(point);
    const viz::Settings adaptiveSettings = {{"shadow_map", 128}, {"tessellation", 1}, {"force_features", 1}};
    viz::Settings staticSettings = adaptiveSettings;
    staticSettings["tessellation"] = 0;
    const viz::FrameOutput fixed = render(scene, "polyvol", staticSettings, 160, 120);
    const viz::FrameOutput adaptive = render(scene, "polyvol", adaptiveSettings, 160, 120);
    ASSERT_TRUE(allFinite(adaptive.airlight));
    const double e = relativeL2(adaptive.airlight, fixed.airlight);
    std::printf("grate + point light 128^2: static %lld triangles, adaptive %lld; relative L2 %.2e\n",
                (long long)trianglesDrawn(fixed), (long long)trianglesDrawn(adaptive), e);
    EXPECT_LT(e, 1e-3);
    EXPECT_LT(trianglesDrawn(adaptive), trianglesDrawn(fixed) / 2);
    viz::Settings cracks = adaptiveSettings;
    cracks["crack_check"] = 1;
    EXPECT_EQ(crackPixels(render(scene, "polyvol", cracks, 160, 120, 2, {"polyvol.crossings"})), 0);
}

// The edge and level maps of a cube light have one layer per face.
TEST_F(PolyvolTest, AdaptiveCubeFacesPublishOneEdgeAndLevelLayerPerFace) {
    const viz::FrameOutput out =
        render(omniGrate(), "polyvol", {{"shadow_map", 64}, {"tessellation", 1}, {"force_features", 1}}, 80, 60, -1,
               {"polyvol.edge_map", "polyvol.tess_levels"});
    for (const char* id : {"polyvol.edge_map", "polyvol.tess_levels"}) {
        const viz::Intermediate* view = find(out, id);
        ASSERT_NE(view, nullptr) << id;
        EXPECT_EQ(view->extent.z, 6) << id;
    }
}

// Benchmark (not run by CTest: DISABLED_; run with --gtest_also_run_disabled_tests): static against
// adaptive cube faces on tv-room (its 4x4 VPL cubes, 256^2 faces) and the omni grate (64^2 .. 1024^2),
// and grate's spot map for comparison, 160x120 and 640x480: volume stage time, triangles drawn, relative
// L2 of L_air against static. POLYVOL_BENCH_SCENE=NAME runs one of them.
TEST_F(PolyvolTest, DISABLED_BenchmarkStaticVsAdaptiveCubeFaces) {
    const std::pair<std::string, viz::scene::Scene> cases[] = {{"tv-room", viz::scene::makeBuiltinScene("tv-room")},
                                                               {"omni grate", omniGrate()},
                                                               {"grate", viz::scene::makeBuiltinScene("grate")}};
    const char* only = std::getenv("POLYVOL_BENCH_SCENE");
    for (const auto& [name, scene] : cases) {
        if (only && name != only) continue;
        for (int n : {64, 128, 256, 512, 1024}) {
            if (name == "tv-room" && n > 256) continue;  // VPL faces stop at 256^2
            for (const auto& [w, h] : {std::pair<int, int>{160, 120}, std::pair<int, int>{640, 480}}) {
                const viz::FrameOutput fixed = render(scene, "polyvol", {{"shadow_map", n}, {"tessellation", 0}}, w, h);
                const viz::FrameOutput adaptive = render(scene, "polyvol", {{"shadow_map", n}, {"tessellation", 1}}, w, h);
                std::printf("%-10s %4d^2 %dx%d  static %9.1f ms %9lld triangles  adaptive %9.1f ms %9lld triangles  "
                            "rel L2 %.2e\n",
                            name.c_str(), n, w, h, volumeMs(fixed), (long long)trianglesDrawn(fixed), volumeMs(adaptive),
                            (long long)trianglesDrawn(adaptive), relativeL2(adaptive.airlight, fixed.airlight));
            }
        }
    }
}
