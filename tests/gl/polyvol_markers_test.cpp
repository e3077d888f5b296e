// polyvol's linked-cursor marks: the crossings of a pixel's eye ray with the light volume, computed on the
// CPU (techniques/polyvol/volume_crossings.h), against what the GPU's volume pass counted for that pixel
// (polyvol.crossings: r = faces crossed, g = signed sum).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "gl/readback.h"
#include "scene/builtin_scenes.h"
#include "technique_test_util.h"

namespace {

using viz::ViewMarker;

struct Counted {
    int crossings = 0, signedSum = 0;
};

// What the segment's label of a polyvol view says: "eye ray t=a..b: N crossings, signed S" (all of the
// ray's crossings, also those a directional volume's skirt has outside the map), and the crossing points
// drawn ("+1 ..." / "-1 ...").
Counted countCrossings(const std::vector<ViewMarker>& marks, Counted* drawn = nullptr) {
    Counted c;
    for (const ViewMarker& m : marks) {
        if (m.from != m.to) {
            const std::size_t at = m.label.find(": ");
            if (at != std::string::npos) std::sscanf(m.label.c_str() + at, ": %d crossings, signed %d", &c.crossings, &c.signedSum);
            continue;
        }
        if (!drawn) continue;
        ++drawn->crossings;
        drawn->signedSum += m.label.rfind("+1", 0) == 0 ? 1 : (m.label.rfind("-1", 0) == 0 ? -1 : 0);
    }
    return c;
}

// grate's spot, a second spot beside it and two point lights.
struct FourLights {
    viz::scene::Light spot, spot2, point, point2;
};
FourLights fourLights(const viz::scene::Light& spot) {
    FourLights l{spot, spot, spot, spot};
    l.spot2.position += glm::dvec3(0.6, 0.0, -0.4);
    l.point.type = l.point2.type = viz::scene::LightType::Point;
    l.point.position += glm::dvec3(-0.5, 0.2, 0.3);
    l.point2.position += glm::dvec3(0.5, -0.1, 0.3);
    return l;
}

class PolyvolMarkersTest : public viz::testing::TechniqueTest {
protected:
    // Every `step`-th pixel: the marks in polyvol.shadow_map count the faces and the signed sum that the
    // GPU's volume pass drew for that pixel. The signed sum must agree everywhere. The count may differ by
    // a pair (+1 and -1 at the same t) where the ray grazes the fold between two faces (the top of a
    // shadow wall, a wall meeting the map's border): the CPU intersects in double, the rasteriser samples
    // the pixel centre in float. Returns the pixels compared, the crossings marked and the pixels whose
    // count differs by such a pair.
    static void expectCrossingsMatchTheGpu(const viz::scene::Scene& scene, const viz::Settings& settings, int w,
                                           int h, int step, int& pixels, int& crossings, int& grazing) {
        bool allDrawn = true;  // no directional light: every crossing lies inside a map
        for (const viz::scene::Light& light : scene.lights) allDrawn = allDrawn && light.type != viz::scene::LightType::Directional;
        auto polyvol = viz::makeTechnique("polyvol");
        const viz::FrameOutput out = viz::testing::runTechnique(*polyvol, scene, settings, w, h);
        const viz::Intermediate* counts = find(out, "polyvol.crossings");
        ASSERT_NE(counts, nullptr);
        const viz::Image gpu = viz::gl::readTexture(counts->glTexture);
        pixels = crossings = grazing = 0;
        for (int y = step / 2; y < h; y += step) {
            for (int x = step / 2; x < w; x += step) {
                // Every light's marks (polyvol.shadow_map, polyvol.shadow_map.1, ...); the GPU adds them up.
                Counted drawn, c;
                for (std::size_t light = 0; light < scene.lights.size(); ++light) {
                    const std::string id = "polyvol.shadow_map" + (light ? "." + std::to_string(light) : std::string());
                    const std::vector<ViewMarker> marks = polyvol->markersFor({x, y}, id);
                    Counted lightDrawn;
                    Counted one = countCrossings(marks, &lightDrawn);
                    // A ray whose part up to d misses this light's map has no segment there to carry the
                    // count; the crossings beyond d are still marked, each on its own.
                    if (std::none_of(marks.begin(), marks.end(), [](const ViewMarker& m) { return m.from != m.to; }))
                        one = lightDrawn;
                    drawn.crossings += lightDrawn.crossings;
                    drawn.signedSum += lightDrawn.signedSum;
                    c.crossings += one.crossings;
                    c.signedSum += one.signedSum;
                    const bool cube = scene.lights[light].type == viz::scene::LightType::Point;
                    for (const ViewMarker& m : marks) {
                        if (cube) {
                            EXPECT_GE(m.layer, 0);  // a cube face
                            EXPECT_LT(m.layer, 6);
                        } else {
                            EXPECT_EQ(m.layer, -1);
                        }
                    }
                }
                // In a spot's map and a cube every crossing is drawn; a directional volume's skirt is outside.
                if (allDrawn) {
                    EXPECT_EQ(drawn.crossings, c.crossings) << "pixel (" << x << ", " << y << ")";
                }
                EXPECT_LE(drawn.crossings, c.crossings);
                const int gpuCount = int(std::lround(gpu.at(x, y, 0)));
                const int gpuSigned = int(std::lround(gpu.at(x, y, 1)));
                ++pixels;
                crossings += c.crossings;
                EXPECT_EQ(c.signedSum, gpuSigned) << "pixel (" << x << ", " << y << ")";
                if (c.crossings != gpuCount) {
                    ++grazing;
                    EXPECT_EQ(std::abs(c.crossings - gpuCount), 2) << "pixel (" << x << ", " << y << ")";
                    std::printf("pixel (%d, %d): %d crossings marked, the GPU drew %d\n", x, y, c.crossings, gpuCount);
                }
            }
        }
    }
};

TEST_F(PolyvolMarkersTest, SpotCrossingsAddUpToTheGpusCrossingCounts) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    int pixels = 0, crossings = 0, grazing = 0;
    expectCrossingsMatchTheGpu(scene, {{"shadow_map", 128}}, 64, 48, 3, pixels, crossings, grazing);
    std::printf("grate spot 128^2: %d pixels, %d crossings marked, %d grazing pairs\n", pixels, crossings, grazing);
    EXPECT_LE(grazing, 1);  // measured: 1 of 336 pixels
    EXPECT_GT(crossings, 2 * pixels);  // rays do cross the bars' shadow walls
}

// The adaptive mesh (coarse quads where the map is flat, its keys read back) counts as the GPU drew it.
TEST_F(PolyvolMarkersTest, AdaptiveMeshCrossingsAddUpToTheGpusCrossingCounts) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    int pixels = 0, crossings = 0, grazing = 0;
    expectCrossingsMatchTheGpu(scene, {{"shadow_map", 128}, {"tessellation", 1}, {"force_features", 1}}, 64, 48, 3,
                               pixels, crossings, grazing);
    std::printf("grate spot 128^2 adaptive: %d pixels, %d crossings marked, %d grazing pairs\n", pixels, crossings,
                grazing);
    EXPECT_GT(crossings, 2 * pixels);
    EXPECT_LE(grazing, 1);
}

// A point light: six grids and the seams between them; every mark on the face its direction selects.
TEST_F(PolyvolMarkersTest, CubeCrossingsAddUpToTheGpusCrossingCounts) {
    viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    scene.lights[0].type = viz::scene::LightType::Point;
    int pixels = 0, crossings = 0, grazing = 0;
    expectCrossingsMatchTheGpu(scene, {{"shadow_map", 64}}, 64, 48, 3, pixels, crossings, grazing);
    std::printf("omni grate 64^2 cube: %d pixels, %d crossings marked, %d grazing pairs\n", pixels, crossings, grazing);
    EXPECT_GT(crossings, 2 * pixels);
    EXPECT_LE(grazing, 0);
}

// An adaptive cube: its six faces' emitted triangles (keys read back) and the seams between them.
TEST_F(PolyvolMarkersTest, AdaptiveCubeCrossingsAddUpToTheGpusCrossingCounts) {
    viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    scene.lights[0].type = viz::scene::LightType::Point;
    int pixels = 0, crossings = 0, grazing = 0;
    expectCrossingsMatchTheGpu(scene, {{"shadow_map", 64}, {"tessellation", 1}, {"force_features", 1}}, 64, 48, 3, pixels,
                               crossings, grazing);
    std::printf("omni grate 64^2 adaptive cube: %d pixels, %d crossings marked, %d grazing pairs\n", pixels, crossings,
                grazing);
    EXPECT_GT(crossings, 2 * pixels);
    EXPECT_LE(grazing, 1);
}

// Two adaptive spots and two adaptive point lights: every light's marks, summed, add up to what the GPU
// drew. (Only the last light of each kind keeps its keys in the run's buffers; the test below checks that
// the others' marks are built from the same triangles.)
TEST_F(PolyvolMarkersTest, EveryAdaptiveLightsCrossingsAddUpToTheGpusCrossingCounts) {
    viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    const FourLights l = fourLights(scene.lights[0]);
    scene.lights = {l.spot, l.spot2, l.point, l.point2};
    int pixels = 0, crossings = 0, grazing = 0;
    expectCrossingsMatchTheGpu(scene, {{"shadow_map", 64}, {"tessellation", 1}, {"force_features", 1}}, 64, 48, 3, pixels,
                               crossings, grazing);
    std::printf("grate, 2 spots and 2 point lights, 64^2 adaptive: %d pixels, %d crossings marked, %d grazing pairs\n",
                pixels, crossings, grazing);
    EXPECT_GT(crossings, 4 * pixels);
    EXPECT_LE(grazing, 3);
}

// An earlier adaptive light's marks (its keys built again for them) are those it gets as the last light
// of its kind (its keys read back from the run's own buffers): the same lights in the other order.
TEST_F(PolyvolMarkersTest, AnEarlierAdaptiveLightIsMarkedAsWhenItIsTheLast) {
    viz::scene::Scene first = viz::scene::makeBuiltinScene("grate");
    const FourLights l = fourLights(first.lights[0]);
    first.lights = {l.spot, l.point, l.spot2, l.point2};
    viz::scene::Scene last = first;
    last.lights = {first.lights[2], first.lights[3], first.lights[0], first.lights[1]};  // light i of first: (i + 2) % 4
    const viz::Settings settings{{"shadow_map", 64}, {"tessellation", 1}, {"force_features", 1}};
    auto a = viz::makeTechnique("polyvol"), b = viz::makeTechnique("polyvol");
    viz::testing::runTechnique(*a, first, settings, 64, 48);
    viz::testing::runTechnique(*b, last, settings, 64, 48);
    const auto mapOf = [](int light) { return "polyvol.shadow_map" + (light ? "." + std::to_string(light) : std::string()); };
    int compared = 0;
    for (const int light : {0, 1}) {  // the first spot and the first point light of `first`: rebuilt there
        for (int y = 1; y < 48; y += 3)
            for (int x = 1; x < 64; x += 3) {
                const std::vector<ViewMarker> rebuilt = a->markersFor({x, y}, mapOf(light));
                const std::vector<ViewMarker> read = b->markersFor({x, y}, mapOf(light + 2));
                ASSERT_EQ(rebuilt.size(), read.size()) << "light " << light << ", pixel (" << x << ", " << y << ")";
                for (std::size_t i = 0; i < rebuilt.size(); ++i) {
                    EXPECT_EQ(rebuilt[i].label, read[i].label) << "light " << light << ", pixel (" << x << ", " << y << ")";
                    EXPECT_EQ(rebuilt[i].from, read[i].from) << "light " << light << ", pixel (" << x << ", " << y << ")";
                    EXPECT_EQ(rebuilt[i].layer, read[i].layer);
                    compared += rebuilt[i].from == rebuilt[i].to ? 1 : 0;
                }
            }
    }
    std::printf("%d crossing marks compared\n", compared);
    EXPECT_GT(compared, 2 * 2 * 336);
}

TEST_F(PolyvolMarkersTest, DirectionalCrossingsAddUpToTheGpusCrossingCounts) {
    viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    scene.lights[0].type = viz::scene::LightType::Directional;
    scene.lights[0].direction = glm::normalize(glm::dvec3(0.15, -1.0, 0.05));
    int pixels = 0, crossings = 0, grazing = 0;
    expectCrossingsMatchTheGpu(scene, {{"shadow_map", 128}}, 64, 48, 3, pixels, crossings, grazing);
    std::printf("grate sun 128^2: %d pixels, %d crossings marked, %d grazing pairs\n", pixels, crossings, grazing);
    EXPECT_LE(grazing, 3);  // measured: 3 of 336 pixels
    EXPECT_GT(crossings, pixels);
}

TEST_F(PolyvolMarkersTest, EdgeMapAndLevelsShowTheSameRayAndCrossingsAsTheShadowMap) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    auto adaptive = viz::makeTechnique("polyvol");
    viz::testing::runTechnique(*adaptive, scene, {{"shadow_map", 64}, {"tessellation", 1}, {"force_features", 1}},
                               64, 48);
    const glm::ivec2 px{40, 40};
    const std::vector<ViewMarker> map = adaptive->markersFor(px, "polyvol.shadow_map");
    ASSERT_GE(map.size(), 2u);
    for (const std::string id : {"polyvol.edge_map", "polyvol.tess_levels"}) {
        const std::vector<ViewMarker> marks = adaptive->markersFor(px, id);
        ASSERT_EQ(marks.size(), map.size()) << id;
        for (std::size_t i = 0; i < marks.size(); ++i) {
            EXPECT_EQ(marks[i].from, map[i].from) << id;
            EXPECT_EQ(marks[i].label, map[i].label) << id;
        }
    }
    // Static tessellation publishes no edge map: nothing to mark; other views and pixels outside the frame
    // have no marks either.
    auto flat = viz::makeTechnique("polyvol");
    viz::testing::runTechnique(*flat, scene, {{"shadow_map", 64}, {"tessellation", 0}}, 64, 48);
    EXPECT_TRUE(flat->markersFor(px, "polyvol.edge_map").empty());
    EXPECT_TRUE(flat->markersFor(px, "polyvol.crossings").empty());
    EXPECT_TRUE(flat->markersFor({64, 0}, "polyvol.shadow_map").empty());
    EXPECT_TRUE(flat->markersFor({0, -1}, "polyvol.shadow_map").empty());
}

}  // namespace
