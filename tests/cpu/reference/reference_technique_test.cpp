// The `reference` technique as a whole: stages, determinism, the disk cache, settings and surface shading.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "core/error.h"
#include "reference_test_util.h"
#include "scene/builtin_scenes.h"
#include "scene/camera.h"
#include "scene/texture_sampling.h"
#include "techniques/reference/ray_tracer.h"
#include "techniques/reference/reference.h"
#include "technique_run.h"
#include "temp_dir.h"

namespace viz {
namespace {

const Image* findImage(const FrameOutput& out, const std::string& id) {
    for (const auto& im : out.intermediates)
        if (im.id == id) return im.image.get();
    return nullptr;
}

FrameOutput runReference(const scene::Scene& s, int w, int h, Settings given, int stopAfter = -1) {
    auto tech = makeReferenceTechnique();
    return viz::testing::runTechnique(*tech, s, given, w, h, stopAfter);
}

// A cache folder of its own, removed afterwards; AIRLIGHT_CACHE_DIR points at it meanwhile and is then
// restored, so that later tests of the same process (the whole binary in one run, as under ASan in CI)
// use the cache they were given.
class TempCacheDir {
public:
    TempCacheDir() {
        if (const char* given = std::getenv("AIRLIGHT_CACHE_DIR")) mGiven = given;
        ::setenv("AIRLIGHT_CACHE_DIR", mDir.path().c_str(), 1);
    }
    ~TempCacheDir() {
        if (mGiven) ::setenv("AIRLIGHT_CACHE_DIR", mGiven->c_str(), 1);
        else ::unsetenv("AIRLIGHT_CACHE_DIR");
    }
    std::vector<std::filesystem::path> files() const {
        std::vector<std::filesystem::path> out;
        for (const auto& e : std::filesystem::directory_iterator(mDir.path())) out.push_back(e.path());
        return out;
    }

private:
    viz::testing::TempDir mDir{"reference_cache"};
    std::optional<std::string> mGiven;
};

TEST(ReferenceTechnique, DeclaresStagesAndParams) {
    auto tech = makeReferenceTechnique();
    EXPECT_EQ(tech->id(), "reference");
    EXPECT_FALSE(tech->needsGl());
    const std::vector<std::string> ids = {"reference.trace", "reference.visibility", "reference.airlight",
                                          "reference.surface", "reference.final"};
    ASSERT_EQ(tech->stages().size(), ids.size());
    for (std::size_t i = 0; i < ids.size(); ++i) EXPECT_EQ(tech->stages()[i].id, ids[i]);
    const Settings s = completeSettings(*tech, {});
    EXPECT_EQ(s.at("transition_samples"), 256);
    EXPECT_EQ(s.at("threads"), 0);
    EXPECT_EQ(s.at("cache"), 1);
    EXPECT_TRUE(s.count("area_samples"));
}

TEST(ReferenceTechnique, UnknownParameterIsRejected) {
    auto tech = makeReferenceTechnique();
    EXPECT_THROW(completeSettings(*tech, {{"transition_sample", 64}}), InputError);
    EXPECT_THROW(completeSettings(*tech, {{"transition_samples", 1}}), InputError);
}

TEST(ReferenceTechnique, PlanExplainsWhatIsOff) {
    auto tech = makeReferenceTechnique();
    scene::Scene s = reference_test::makeSlabScene();
    Plan p = tech->plan(s, completeSettings(*tech, {}));
    bool sawEmitter = false;
    for (const auto& f : p.features) {
        if (f.feature == "emitter quadrature") {
            sawEmitter = true;
            EXPECT_FALSE(f.enabled);
            EXPECT_EQ(f.why, "no area light in the scene");
        }
    }
    EXPECT_TRUE(sawEmitter);
    s.medium.sigma_s = 0.0;
    p = tech->plan(s, completeSettings(*tech, {}));
    ASSERT_EQ(p.stages.size(), 5u);
    EXPECT_NE(p.stages[2].why.find("sigma_s = 0"), std::string::npos);
}

TEST(ReferenceTechnique, StopAfterStageLeavesLaterImagesEmpty) {
    const scene::Scene s = reference_test::makeSlabScene();
    const FrameOutput trace = runReference(s, 16, 12, {{"cache", 0}}, 0);
    EXPECT_EQ(trace.lastStageRun, 0);
    EXPECT_TRUE(trace.airlight.empty());
    EXPECT_TRUE(trace.final.empty());
    ASSERT_EQ(trace.intermediates.size(), 1u);
    EXPECT_EQ(trace.intermediates[0].id, "reference.distance");
    EXPECT_EQ(trace.timing.stages.size(), 1u);

    const FrameOutput air = runReference(s, 16, 12, {{"cache", 0}}, 2);
    EXPECT_EQ(air.lastStageRun, 2);
    EXPECT_FALSE(air.airlight.empty());
    EXPECT_TRUE(air.final.empty());
    EXPECT_EQ(findImage(air, "reference.surface"), nullptr);
    EXPECT_NE(findImage(air, "reference.lit_fraction"), nullptr);
}

TEST(ReferenceTechnique, ResultDoesNotDependOnThreadCount) {
    const scene::Scene s = reference_test::makeSlabScene();
    const FrameOutput one = runReference(s, 20, 15, {{"cache", 0}, {"threads", 1}, {"transition_samples", 64}});
    const FrameOutput three = runReference(s, 20, 15, {{"cache", 0}, {"threads", 3}, {"transition_samples", 64}});
    ASSERT_EQ(one.intermediates.size(), three.intermediates.size());
    for (std::size_t i = 0; i < one.intermediates.size(); ++i) {
        EXPECT_EQ(one.intermediates[i].image->pixels, three.intermediates[i].image->pixels) << one.intermediates[i].id;
    }
    // The image is not trivially zero: shafts and shadows are there.
    float maxAir = 0.0f;
    for (float v : one.airlight.pixels) maxAir = std::max(maxAir, v);
    EXPECT_GT(maxAir, 0.0f);
}

TEST(ReferenceTechnique, CacheHitReturnsIdenticalPixelsAndCorruptFilesAreRewritten) {
    TempCacheDir dir;
    const scene::Scene s = reference_test::makeSlabScene();
    const Settings settings{{"transition_samples", 32}};
    const FrameOutput first = runReference(s, 16, 12, settings);
    EXPECT_EQ(first.timing.clock, "steady_clock");
    ASSERT_EQ(dir.files().size(), 1u);
    const std::filesystem::path file = dir.files()[0];

    const FrameOutput second = runReference(s, 16, 12, settings);
    EXPECT_EQ(second.timing.clock, "cache");
    EXPECT_EQ(second.airlight.pixels, first.airlight.pixels);
    EXPECT_EQ(second.final.pixels, first.final.pixels);
    ASSERT_EQ(second.intermediates.size(), first.intermediates.size());
    for (std::size_t i = 0; i < first.intermediates.size(); ++i) {
        EXPECT_EQ(second.intermediates[i].id, first.intermediates[i].id);
        EXPECT_EQ(second.intermediates[i].image->pixels, first.intermediates[i].image->pixels);
    }

    // Another setting is another key, hence a miss.
    const FrameOutput other = runReference(s, 16, 12, {{"transition_samples", 33}});
    EXPECT_EQ(other.timing.clock, "steady_clock");

    // Truncate the file: the next run ignores it, recomputes and rewrites it whole.
    const auto size = std::filesystem::file_size(file);
    std::filesystem::resize_file(file, size / 2);
    const FrameOutput third = runReference(s, 16, 12, settings);
    EXPECT_EQ(third.timing.clock, "steady_clock");
    EXPECT_EQ(third.final.pixels, first.final.pixels);
    EXPECT_EQ(std::filesystem::file_size(file), size);
    // Flip one byte in the middle: same.
    {
        std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(std::streamoff(size / 2));
        f.put('\x5a');
    }
    EXPECT_EQ(runReference(s, 16, 12, settings).timing.clock, "steady_clock");
    EXPECT_EQ(runReference(s, 16, 12, settings).timing.clock, "cache");

    // cache = 0 neither reads nor writes.
    EXPECT_EQ(runReference(s, 16, 12, {{"transition_samples", 32}, {"cache", 0}}).timing.clock, "steady_clock");
}

TEST(ReferenceTechnique, FinalComposesSurfaceAndAirlight) {
    const scene::Scene s = reference_test::makeSlabScene();
    const FrameOutput out = runReference(s, 16, 12, {{"cache", 0}, {"transition_samples", 32}});
    const Image* surface = findImage(out, "reference.surface");
    const Image* distance = findImage(out, "reference.distance");
    ASSERT_NE(surface, nullptr);
    ASSERT_NE(distance, nullptr);
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 16; ++x)
            for (int c = 0; c < 3; ++c) {
                const double expect = surface->at(x, y, c) * std::exp(-s.medium.sigma_t() * double(distance->at(x, y))) +
                                      out.airlight.at(x, y, c);
                EXPECT_NEAR(out.final.at(x, y, c), expect, 1e-6 * expect + 1e-12);
            }
}

TEST(ReferenceTechnique, SurfaceMatchesLambertFromTheDefinition) {
    // Pixels that see the floor: surface = albedo / pi * E * max(0, n.l) * V with E from the definition.
    const scene::Scene s = reference_test::makeSlabScene();
    const int W = 16, H = 12;
    const FrameOutput out = runReference(s, W, H, {{"cache", 0}, {"transition_samples", 16}});
    const Image* surface = findImage(out, "reference.surface");
    ASSERT_NE(surface, nullptr);
    const reference::RayTracer tracer(s);
    const scene::Light& l = s.lights[0];
    int litFloor = 0;
    for (int y = 0; y < H; ++y) {
        for (int x = 0; x < W; ++x) {
            const glm::dvec3 w = scene::pixelRay(s.camera, W, H, x, y);
            const reference::Hit hit = tracer.intersect(s.camera.position, w, s.camera.zfar);
            if (!hit.found || hit.mesh != 0) continue;  // mesh 0 is the floor (normal +y)
            const glm::dvec3 X = s.camera.position + hit.t * w;
            const double r = glm::length(l.position - X);
            const glm::dvec3 toLight = (l.position - X) / r;
            const bool visible = !tracer.occludedSegment(X + 1e-4 * glm::dvec3(0, 1, 0), l.position);
            const double E = l.intensity * reference_test::spotA(l, -toLight) * std::exp(-s.medium.sigma_t() * r) / (r * r);
            const double expect = visible ? 0.8 / 3.14159265358979323846 * E * std::max(0.0, toLight.y) : 0.0;
            for (int c = 0; c < 3; ++c) {
                const double e = expect * l.colour[c];
                EXPECT_NEAR(surface->at(x, y, c), e, 1e-5 * e + 1e-9) << x << "," << y;
            }
            litFloor += expect > 0.0;
        }
    }
    EXPECT_GT(litFloor, 0);
}

TEST(ReferenceTechnique, EmitterPixelsShowTheirEmittedRadiance) {
    // The panel of the test area-light scene is its only light; from its own nodes it receives nothing
    // (they lie in its plane), so a pixel that sees its emitting side has surface = L_e(uv) exactly.
    const scene::Scene s = scene::makeTestAreaLightScene();
    const int W = 24, H = 18;
    const FrameOutput out = runReference(s, W, H, {{"cache", 0}, {"transition_samples", 8}, {"area_samples", 2}});
    const Image* surface = findImage(out, "reference.surface");
    ASSERT_NE(surface, nullptr);
    const scene::Light& l = s.lights[0];
    const scene::Mesh& panel = s.meshes[std::size_t(l.mesh)];
    const scene::Texture& tex = s.textures[std::size_t(l.emissionTexture)];
    const reference::RayTracer tracer(s);
    int seen = 0;
    for (int y = 0; y < H; ++y) {
        for (int x = 0; x < W; ++x) {
            const glm::dvec3 w = scene::pixelRay(s.camera, W, H, x, y);
            const reference::Hit hit = tracer.intersect(s.camera.position, w, s.camera.zfar);
            if (!hit.found || hit.mesh != l.mesh) continue;
            // The emitter's uv from the mesh's own uvs (the scene model makes them match the rectangle).
            ASSERT_FALSE(panel.uvs.empty());
            const std::size_t t = std::size_t(hit.triangle);
            const glm::dvec2 uv = (1.0 - hit.u - hit.v) * glm::dvec2(panel.uvs[panel.indices[3 * t]]) +
                                  hit.u * glm::dvec2(panel.uvs[panel.indices[3 * t + 1]]) +
                                  hit.v * glm::dvec2(panel.uvs[panel.indices[3 * t + 2]]);
            const glm::dvec3 le = l.radiance * glm::dvec3(scene::sampleLinearRgb(tex, uv));
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(surface->at(x, y, c), le[c], 1e-4 * le[c]) << x << "," << y;
            ++seen;
        }
    }
    EXPECT_GT(seen, 0) << "no pixel sees the emitter";
}

}  // namespace
}  // namespace viz
