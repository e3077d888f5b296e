// Work counters (gl/work_counters.h) against counts known without them: raymarch's shadow-map lookups and
// ray samples are pixels x samples x lights exactly; minmax's tree nodes for one picked pixel equal the CPU
// mirror's walk of that pixel (pixel_mirror.h); the primitives drawn are the scene's triangles once per
// pass and shadow-map face; an ordinary run carries no counts, and counting does not change the image.
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

#include "gl/work_counters.h"
#include "minmax_frame.h"
#include "render/host_device.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_source.h"
#include "technique_test_util.h"

namespace viz::testing {
namespace {

namespace hd = render::hd;

class WorkCountersTest : public TechniqueTest {
protected:
    void TearDown() override {
        gl::WorkCounters::setEnabled(false);
        gl::WorkCounters::countPixel(std::nullopt);
        TechniqueTest::TearDown();
    }
    static const StageTiming* stage(const FrameOutput& out, const std::string& id) {
        for (const StageTiming& s : out.timing.stages)
            if (s.stage == id) return &s;
        return nullptr;
    }
};

TEST_F(WorkCountersTest, RaymarchLooksUpTheShadowMapOncePerPixelSampleAndLight) {
    const scene::Scene scene = scene::makeBuiltinScene("colonnade");
    ASSERT_EQ(scene.lights.size(), 1u);  // the sun: its lit interval is the whole ray, so no ray is skipped
    ASSERT_EQ(scene.lights[0].type, scene::LightType::Directional);
    const int w = 40, h = 30, samples = 16;
    const Settings settings{{"samples", double(samples)}};
    const FrameOutput plain = render(scene, "raymarch", settings, w, h);
    for (const StageTiming& s : plain.timing.stages) EXPECT_TRUE(s.work.empty()) << s.stage;

    gl::WorkCounters::setEnabled(true);
    const FrameOutput counted = render(scene, "raymarch", settings, w, h);
    const StageTiming* march = stage(counted, "raymarch.march");
    ASSERT_NE(march, nullptr);
    ASSERT_EQ(march->work.size(), std::size_t(gl::kWorkCounts));
    const std::uint64_t expected = std::uint64_t(w) * h * samples;
    EXPECT_EQ(march->work[hd::kWorkShadowLookups], expected);
    EXPECT_EQ(march->work[hd::kWorkRaySamples], expected);
    // A 2D map's lookup reads its nearest texel and, where the neighbours are in the map, two per axis.
    EXPECT_GE(march->work[hd::kWorkShadowTexels], expected);
    EXPECT_LE(march->work[hd::kWorkShadowTexels], 5 * expected);
    // The surface pass shades fragments and looks the sun's map up at most once for each (only where the
    // surface faces the sun).
    const StageTiming* surface = stage(counted, "raymarch.surface");
    ASSERT_NE(surface, nullptr);
    EXPECT_GT(surface->work[hd::kWorkFragments], 0u);
    EXPECT_GT(surface->work[hd::kWorkShadowLookups], 0u);
    EXPECT_LE(surface->work[hd::kWorkShadowLookups], surface->work[hd::kWorkFragments]);
    EXPECT_EQ(surface->work[hd::kWorkRaySamples], 0u);
    // Counting changes nothing in the image.
    ASSERT_EQ(counted.airlight.pixels.size(), plain.airlight.pixels.size());
    for (std::size_t i = 0; i < plain.airlight.pixels.size(); ++i)
        ASSERT_EQ(counted.airlight.pixels[i], plain.airlight.pixels[i]) << i;
}

// The primitives counter against the scene's triangles, counted from its meshes: the surface pass draws
// every mesh twice (its depth prepass, then the shading); the shadow pass draws them once into a sun's 2D
// map and once per face into a point light's cube map. The march itself is a compute pass and draws
// nothing.
TEST_F(WorkCountersTest, PrimitivesAreTheScenesTrianglesOncePerPassAndShadowFace) {
    struct PassCase {
        const char* scene;
        scene::LightType light;
        std::uint64_t shadowPasses;
    };
    for (const PassCase c :
         {PassCase{"colonnade", scene::LightType::Directional, 1}, PassCase{"grate", scene::LightType::Point, 6}}) {
        scene::Scene scene = scene::makeBuiltinScene(c.scene);
        ASSERT_EQ(scene.lights.size(), 1u) << c.scene;
        scene.lights[0].type = c.light;
        std::uint64_t triangles = 0;
        for (const scene::Mesh& m : scene.meshes) triangles += m.indices.size() / 3;
        ASSERT_GT(triangles, 0u);
        gl::WorkCounters::setEnabled(true);
        const FrameOutput counted = render(scene, "raymarch", {{"samples", 4.0}}, 40, 30);
        gl::WorkCounters::setEnabled(false);
        const StageTiming* shadow = stage(counted, "raymarch.shadow_maps");
        const StageTiming* surface = stage(counted, "raymarch.surface");
        const StageTiming* march = stage(counted, "raymarch.march");
        ASSERT_TRUE(shadow && surface && march) << c.scene;
        ASSERT_EQ(shadow->work.size(), std::size_t(gl::kWorkCounts));
        EXPECT_EQ(shadow->work[gl::kWorkPrimitives], c.shadowPasses * triangles) << c.scene;
        EXPECT_EQ(surface->work[gl::kWorkPrimitives], 2 * triangles) << c.scene;
        EXPECT_EQ(march->work[gl::kWorkPrimitives], 0u) << c.scene;
    }
}

// The surface pass shades one fragment a pixel whose ray meets a surface within zfar, however many
// triangles cover it (its depth prepass): colonnade's and forest's overlap about two deep at 320x240.
// The covered pixels are counted from the distance it wrote (sky and misses hold zfar).
TEST_F(WorkCountersTest, TheSurfacePassShadesOneFragmentPerCoveredPixel) {
    for (const char* name : {"colonnade", "forest", "stiff/depth-range-1e6"}) {
        const scene::Scene scene = scene::loadScene(name);
        gl::WorkCounters::setEnabled(true);
        const FrameOutput out = render(scene, "raymarch", {{"samples", 4.0}}, 64, 48, -1, {"raymarch.distance"});
        gl::WorkCounters::setEnabled(false);
        const StageTiming* surface = stage(out, "raymarch.surface");
        const Intermediate* distance = find(out, "raymarch.distance");
        ASSERT_TRUE(surface && distance && distance->image) << name;
        std::uint64_t covered = 0;
        for (float d : distance->image->pixels) covered += d < float(scene.camera.zfar);
        EXPECT_GT(covered, 0u) << name;
        EXPECT_EQ(surface->work[hd::kWorkFragments], covered) << name;
    }
}

TEST_F(WorkCountersTest, MinmaxTreeNodesOfAPickedPixelEqualTheCpuMirrorsWalk) {
    for (const char* name : {"grate", "terrain"}) {
        const scene::Scene scene = scene::makeBuiltinScene(name);
        const int w = 80, h = 60, size = 512;
        // The analytic integrand, whose quadrature nodes the counters below bound.
        const Settings settings{{"shadow_map", double(size)}, {"integrand", 0.0}};
        const FrameOutput out = render(scene, "minmax", settings, w, h, -1,
                                       {"minmax.tree", "minmax.ray_coords", "minmax.near_epipole"});
        const Intermediate* tree = find(out, "minmax.tree");
        const Intermediate* coords = find(out, "minmax.ray_coords");
        const Intermediate* near = find(out, "minmax.near_epipole");
        ASSERT_TRUE(tree && coords && near && tree->image && coords->image && near->image);
        render::GpuLightCpu L{};
        const auto f = minmaxFrame(scene, 0, w, h, size, &L);
        int checked = 0;
        for (const glm::ivec2 p : {glm::ivec2(13, 11), glm::ivec2(40, 30), glm::ivec2(61, 47), glm::ivec2(70, 8)}) {
            if (near->image->at(p.x, p.y) != 0.0f) continue;  // marched near the epipole: no walk
            const minmax::MirrorResult mirror = mirrorPixel(scene, out, f, L, w, h, p.x, p.y);

            gl::WorkCounters::setEnabled(true);
            gl::WorkCounters::countPixel(glm::ivec2(p.x, h - 1 - p.y));  // GL rows count from the bottom
            const FrameOutput counted = render(scene, "minmax", settings, w, h);
            gl::WorkCounters::setEnabled(false);
            gl::WorkCounters::countPixel(std::nullopt);
            const StageTiming* traverse = stage(counted, "minmax.traverse");
            ASSERT_NE(traverse, nullptr);
            ASSERT_EQ(traverse->work.size(), std::size_t(gl::kWorkCounts));
            EXPECT_EQ(traverse->work[hd::kWorkTreeNodes], std::uint64_t(mirror.visited))
                << name << " pixel " << p.x << "," << p.y;
            EXPECT_GT(mirror.visited, 0) << name;
            // Each closed-form point or spot segment is 13 Gauss-Legendre panels of 8 nodes at most, and at
            // least one (common/airlight.glsl pointSegment); a sun's segment has none.
            const std::uint64_t segments = traverse->work[hd::kWorkClosedFormSegments];
            const std::uint64_t nodes = traverse->work[hd::kWorkQuadratureNodes];
            if (scene.lights[0].type == scene::LightType::Directional) {
                EXPECT_EQ(nodes, 0u) << name;
            } else {
                EXPECT_GE(nodes, 8 * segments) << name;
                EXPECT_LE(nodes, 13 * 8 * segments) << name;
            }
            ++checked;
        }
        EXPECT_GE(checked, 3) << name;
    }
}

}  // namespace
}  // namespace viz::testing
