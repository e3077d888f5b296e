// vsv: the GLSL bit helpers against the CPU ones, voxelization against ray casting, the alpha scan
// against a CPU prefix OR, accuracy against the reference, stage stepping and the plan.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "core/error.h"
#include "gl/buffer.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_building.h"
#include "scene/stiff_scenes.h"
#include "technique_test_util.h"
#include "techniques/reference/ray_tracer.h"
#include "techniques/vsv/bits128.h"
#include "techniques/vsv/epipolar_setup.h"

namespace {

class VsvTest : public viz::testing::TechniqueTest {};

using viz::testing::allFinite;
using viz::testing::relativeL2;
using viz::vsv::Bits128;

// The grate with its spot turned into a point light at the same place (cube-map voxelization).
viz::scene::Scene pointGrate() {
    viz::scene::Scene s = viz::scene::makeBuiltinScene("grate");
    s.name = "grate-point";
    s.lights[0].type = viz::scene::LightType::Point;
    s.lights[0].intensity = 60.0;
    return s;
}

// The point-light grate seen from below the grate, looking up past the light: the epipole is in the image.
viz::scene::Scene grateLookingAtLight() {
    viz::scene::Scene s = pointGrate();
    s.name = "grate-epipole";
    s.camera.position = {0.3, 1.0, 4.5};
    const glm::dvec3 target = s.lights[0].position + glm::dvec3(0.4, -0.3, 0.0);
    s.camera.forward = glm::normalize(target - s.camera.position);
    s.camera.up = glm::normalize(glm::cross(glm::cross(s.camera.forward, glm::dvec3(0, 1, 0)), s.camera.forward));
    return s;
}

// grateLookingAtLight with a plank across the line of sight just in front of the light (at 90 % of the way
// from the eye): it hides the light and the lower half of the light's neighbourhood, its edge 0.02 above
// the sight line. Rays within an alpha cell of the epipole then split into ones that end on the plank
// (in its shadow) and ones that pass it and are lit up to the light: one grid texel cannot hold both.
viz::scene::Scene plankBeforeTheLight(double at = 0.9) {
    viz::scene::Scene s = grateLookingAtLight();
    s.name = "grate-epipole-plank";
    const glm::dvec3 eye = s.camera.position, light = s.lights[0].position;
    const glm::dvec3 dir = glm::normalize(light - eye);
    const glm::dvec3 right = glm::normalize(glm::cross(dir, glm::dvec3(0, 1, 0)));
    const glm::dvec3 up = glm::cross(right, dir);
    const glm::dvec3 c = eye + at * (light - eye);
    const glm::dvec3 a = c - 0.8 * right - 0.6 * up, b = c + 0.8 * right - 0.6 * up;
    const glm::dvec3 e = c + 0.8 * right + 0.02 * up, f = c - 0.8 * right + 0.02 * up;
    viz::scene::MeshBuilder plank("plank", s.meshes.front().material);
    plank.quad(a, b, e, f);  // both faces: the plank is opaque either way
    plank.quad(b, a, f, e);
    s.meshes.push_back(plank.take());
    return s;
}

Bits128 toBits(const glm::uvec4& v) { return {{v.x, v.y, v.z, v.w}}; }

}  // namespace

// The GLSL mirror of bits128.h gives the CPU results for every bit position (bit 127 included).
TEST_F(VsvTest, GlslBitHelpersEqualTheCpuOnes) {
    std::mt19937 rng(17);
    const int cases = 64;
    std::vector<glm::uvec4> columns;
    std::vector<glm::vec4> weights;
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int c = 0; c < cases; ++c) {
        for (int i = 0; i < 2; ++i) columns.emplace_back(rng(), rng(), rng(), rng());
        weights.emplace_back(unit(rng), unit(rng), 0.0f, 0.0f);
    }
    columns[0] = glm::uvec4(0u, 0u, 0u, 0x80000000u);  // only bit 127
    columns[2] = glm::uvec4(~0u);
    auto in = viz::gl::Buffer::create({.bytes = columns.size() * sizeof(glm::uvec4), .data = columns.data(),
                                       .label = "test.vsv_columns"});
    auto w = viz::gl::Buffer::create(
        {.bytes = weights.size() * sizeof(glm::vec4), .data = weights.data(), .label = "test.vsv_weights"});
    auto out = viz::gl::Buffer::create({.bytes = size_t(cases) * 128 * sizeof(glm::uvec4), .label = "test.vsv_out"});
    auto fr = viz::gl::Buffer::create({.bytes = size_t(cases) * 128 * sizeof(float), .label = "test.vsv_fractions"});
    auto program = viz::gl::Program::compile(
        {.stages = {std::string(VIZ_TEST_DATA_DIR) + "/vsv/bits128_test.comp"}, .label = "test.vsv_bits"});
    program.use();
    in.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
    w.bindBase(GL_SHADER_STORAGE_BUFFER, 1);
    out.bindBase(GL_SHADER_STORAGE_BUFFER, 2);
    fr.bindBase(GL_SHADER_STORAGE_BUFFER, 3);
    glDispatchCompute(GLuint(cases), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    const std::vector<glm::uvec4> results = out.download<glm::uvec4>();
    const std::vector<float> fractions = fr.download<float>();
    for (int c = 0; c < cases; ++c) {
        const Bits128 a = toBits(columns[std::size_t(2 * c)]), b = toBits(columns[std::size_t(2 * c + 1)]);
        for (int k = 0; k < 128; ++k) {
            const glm::uvec4 r = results[std::size_t(c * 128 + k)];
            ASSERT_EQ(r.x, viz::vsv::testBitPlain(a, k) ? 1u : 0u) << c << " " << k;
            ASSERT_EQ(r.y, viz::vsv::testBitFast(a, k) ? 1u : 0u) << c << " " << k;
            ASSERT_EQ(int(r.z), viz::vsv::countBits(a, 0, k)) << c << " " << k;
            ASSERT_EQ(int(r.w), viz::vsv::countBits(a, k, 128)) << c << " " << k;
            const glm::vec4 wt = weights[std::size_t(c)];
            ASSERT_NEAR(fractions[std::size_t(c * 128 + k)], viz::vsv::litFractionFast(a, b, k, wt.x, wt.y), 1e-6f)
                << c << " " << k;
        }
    }
    EXPECT_EQ(results[127].x, 1u);  // bit 127 of the first column is addressable
}

// One pass after another, shaders/vsv/scan.comp on random columns equals a CPU Hillis-Steele prefix OR,
// and after all passes every bit column (fixed theta and phi bit) along alpha is a single run of ones
// starting at its first set bit, with single occluder bits as input.
TEST_F(VsvTest, ScanShaderEqualsCpuPrefixOrOnRandomColumns) {
    const int nAlpha = 64, nTheta = 8, layers = 2;
    std::mt19937 rng(23);
    std::vector<Bits128> grid(std::size_t(nAlpha * nTheta * layers));
    // One occluder per (theta, phi bit) at a random alpha, or none (as voxelization produces).
    std::uniform_int_distribution<int> cell(-16, nAlpha - 1);
    for (int l = 0; l < layers; ++l)
        for (int j = 0; j < nTheta; ++j)
            for (int k = 0; k < 128; ++k) {
                const int a = cell(rng);
                if (a >= 0) viz::vsv::setBit(grid[std::size_t((l * nTheta + j) * nAlpha + a)], k);
            }
    auto makeGrid = [&](const char* label) {
        return viz::gl::Texture::create({.target = GL_TEXTURE_2D_ARRAY, .format = GL_RGBA32UI,
                                         .size = {nAlpha, nTheta, layers}, .levels = 1, .label = label});
    };
    viz::gl::Texture a = makeGrid("test.scan_a"), b = makeGrid("test.scan_b");
    a.upload(GL_RGBA_INTEGER, GL_UNSIGNED_INT, grid.data());
    auto program = viz::gl::Program::compile({.stages = {"vsv/scan.comp"}, .label = "test.vsv_scan"});
    program.use();
    program.set("uSize", glm::ivec3(nAlpha, nTheta, layers));
    program.set("uSegment", 0);
    std::vector<Bits128> cpu = grid;
    viz::gl::Texture* src = &a;
    viz::gl::Texture* dst = &b;
    for (int pass = 0; (1 << pass) < nAlpha; ++pass) {
        const int offset = 1 << pass;
        program.set("uOffset", offset);
        src->bindImage(0, GL_READ_ONLY);
        dst->bindImage(1, GL_WRITE_ONLY);
        glDispatchCompute(GLuint(nAlpha / 8), GLuint(nTheta / 8), GLuint(layers));
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
        std::swap(src, dst);
        std::vector<Bits128> next = cpu;
        for (int l = 0; l < layers; ++l)
            for (int j = 0; j < nTheta; ++j)
                for (int x = offset; x < nAlpha; ++x) {
                    const std::size_t row = std::size_t((l * nTheta + j) * nAlpha);
                    next[row + std::size_t(x)] = viz::vsv::bitOr(cpu[row + std::size_t(x)], cpu[row + std::size_t(x - offset)]);
                }
        cpu = next;
        std::vector<Bits128> gpu(cpu.size());
        glGetTextureImage(src->id(), 0, GL_RGBA_INTEGER, GL_UNSIGNED_INT, GLsizei(gpu.size() * sizeof(Bits128)),
                          gpu.data());
        ASSERT_TRUE(gpu == cpu) << "pass " << pass;
    }
    // Single runs starting at the input occluder.
    for (int l = 0; l < layers; ++l)
        for (int j = 0; j < nTheta; ++j)
            for (int k = 0; k < 128; ++k) {
                const std::size_t row = std::size_t((l * nTheta + j) * nAlpha);
                int first = nAlpha;
                for (int x = 0; x < nAlpha; ++x)
                    if (viz::vsv::testBitPlain(grid[row + std::size_t(x)], k)) first = std::min(first, x);
                for (int x = 0; x < nAlpha; ++x)
                    ASSERT_EQ(viz::vsv::testBitPlain(cpu[row + std::size_t(x)], k), x >= first) << j << " " << k;
            }
}

// The voxelized occluder of random light rays is the first hit of a ray cast from the light against the
// scene's triangles (Embree), to within one alpha cell. Biases off, so both sample the same ray. Rays that
// hit nothing must have no occluder (a negative cell), and are counted apart: they cannot pass by being
// within one cell of cell 0.
TEST_F(VsvTest, VoxelizationMatchesRayCastingWithinOneVoxel) {
    for (const viz::scene::Scene& scene :
         {viz::scene::makeBuiltinScene("grate"), pointGrate(), viz::scene::makeBuiltinScene("colonnade")}) {
        const viz::Settings settings{{"voxels", 128}, {"alpha_bias", 0}, {"phi_bias", 0}, {"shadow_map", 2048}};
        const viz::FrameOutput out = render(scene, "vsv", settings, 160, 120, 2, {"vsv.occluder_alpha"});
        const viz::Intermediate* occ = find(out, "vsv.occluder_alpha");
        ASSERT_NE(occ, nullptr);
        ASSERT_TRUE(occ->image);
        const viz::Image& image = *occ->image;  // row 0 at the top = the last theta cell
        const viz::scene::Light& light = scene.lights[0];
        const viz::vsv::EpipolarFrame f = viz::vsv::frameForLight(scene, light);
        const viz::vsv::EpipolarGrid g = viz::vsv::gridForLight(scene, light, 160, 120, 128, 128, 128, true);
        ASSERT_EQ(image.width, g.nPhi);
        ASSERT_EQ(image.height, g.nTheta);
        const viz::reference::RayTracer tracer(scene);
        std::mt19937 rng(29);
        std::uniform_int_distribution<int> phiCell(0, g.nPhi - 1), thetaCell(0, g.nTheta - 1);
        int tested = 0, hits = 0, within = 0, misses = 0, missesEmpty = 0;
        for (int trial = 0; trial < 2000; ++trial) {
            const int k = phiCell(rng), j = thetaCell(rng);
            const double theta = viz::vsv::thetaAtCell(g, j + 0.5);
            const double phi = g.phi0 + (k + 0.5) * g.dPhi();
            double expected = -1.0;
            bool found = false;
            if (f.directional) {
                // The light line at offset y = phi: from far toward the light along the travel direction.
                const glm::dvec3 e = std::cos(theta) * f.u + std::sin(theta) * f.v;
                const double far = 1000.0;
                const viz::reference::Hit hit = tracer.intersect(scene.camera.position + phi * e + far * f.b, -f.b, 2e3);
                found = hit.found;
                if (hit.found) expected = viz::vsv::alphaCoord(g, std::atan2(phi, far - hit.t));
            } else {
                const glm::dvec3 dir = viz::vsv::lightRay(f, theta, phi);
                // Only rays inside the spot's cone (the shadow map covers the cone).
                if (light.type == viz::scene::LightType::Spot &&
                    glm::dot(dir, light.direction) < std::cos(light.outerConeAngle) + 1e-3)
                    continue;
                const viz::reference::Hit hit = tracer.intersect(light.position, dir, 1e6);
                found = hit.found;
                if (hit.found) expected = viz::vsv::alphaCoord(g, viz::vsv::alphaOnLightRay(f, phi, hit.t));
            }
            const float gpu = image.at(k, g.nTheta - 1 - j);
            if (!found) {
                // Nothing on the light ray: no occluder in the column.
                ++misses;
                missesEmpty += gpu < 0.0f ? 1 : 0;
                continue;
            }
            ++tested;
            if (expected >= g.nAlpha) {
                // Nothing inside the grid: no bit (the GPU may still see an occluder beyond the last cell).
                within += gpu < 0.0f || gpu >= float(g.nAlpha) - 1.0f ? 1 : 0;
                continue;
            }
            ++hits;
            // An occluder before the grid's alpha range shadows the whole column (cell 0).
            within += std::abs(double(gpu) - std::max(expected, 0.0)) <= 1.0 ? 1 : 0;
        }
        std::printf("%s: %d light rays hitting the scene (%d inside the grid), %d within one alpha cell (%.2f %%); "
                    "%d hitting nothing, %d of them empty (%.2f %%)\n",
                    scene.name.c_str(), tested, hits, within, 100.0 * within / tested, misses, missesEmpty,
                    misses ? 100.0 * missesEmpty / misses : 100.0);
        EXPECT_GT(hits, 200);
        EXPECT_GE(double(within) / tested, 0.99) << scene.name;
        if (misses > 0) {
            EXPECT_GE(double(missesEmpty) / misses, 0.99) << scene.name;
        }
    }
}

// After the scan, every (theta, phi) column of the slice is one run of ones from the occluder cell of
// the voxelization to the end of alpha; stopping after pass p gives the CPU's p-pass prefix OR.
TEST_F(VsvTest, ScannedSliceIsOneRunFromTheOccluderAndStepsPassByPass) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    const viz::Settings base{{"voxels", 64}, {"pick_theta", 40}};
    const viz::FrameOutput before = render(scene, "vsv", base, 80, 60, 2);
    const viz::Image& voxels = *find(before, "vsv.voxels")->image;
    ASSERT_EQ(voxels.width, 64);
    ASSERT_EQ(voxels.height, 64);
    int occupied = 0;
    for (int k = 0; k < 64; ++k) {
        int count = 0;
        for (int a = 0; a < 64; ++a) count += voxels.at(a, k) > 0.5f ? 1 : 0;
        EXPECT_LE(count, 1) << "phi " << k;  // one occluder per light ray
        occupied += count;
    }
    EXPECT_GT(occupied, 10);
    for (int passes : {1, 3, 6}) {
        viz::Settings s = base;
        s["scan_passes"] = passes;
        const viz::FrameOutput after = render(scene, "vsv", s, 80, 60, 3);
        const viz::Image& scanned = *find(after, "vsv.scanned")->image;
        for (int k = 0; k < 64; ++k) {
            std::vector<bool> cpu(64);
            for (int a = 0; a < 64; ++a) cpu[std::size_t(a)] = voxels.at(a, k) > 0.5f;
            for (int p = 0; p < passes; ++p) {
                std::vector<bool> next = cpu;
                for (int a = 1 << p; a < 64; ++a) next[std::size_t(a)] = cpu[std::size_t(a)] || cpu[std::size_t(a - (1 << p))];
                cpu = next;
            }
            for (int a = 0; a < 64; ++a)
                ASSERT_EQ(scanned.at(a, k) > 0.5f, cpu[std::size_t(a)]) << passes << " " << k << " " << a;
            if (passes == 6) {
                int first = 64;
                for (int a = 0; a < 64; ++a)
                    if (voxels.at(a, k) > 0.5f) first = std::min(first, a);
                for (int a = 0; a < 64; ++a) ASSERT_EQ(scanned.at(a, k) > 0.5f, a >= first) << k << " " << a;
            }
        }
    }
}

// The picked pixel's column (the ray inspector's view) shows its phi bits as voxelized and after the
// scan: up to the pixel's fragment, the first row is one column of the voxels slice at the pixel's theta
// (published separately, read back by another path) and the second is the prefix OR of that slice's
// columns up to the same alpha; beyond the fragment both rows read 0.5.
TEST_F(VsvTest, ThePickedColumnShowsItsBitsBeforeAndAfterTheScan) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    for (const glm::ivec2 pick : {glm::ivec2(40, 40), glm::ivec2(30, 45), glm::ivec2(52, 20)}) {
        const viz::Settings s{{"voxels", 64}, {"pick_x", pick.x}, {"pick_y", pick.y}};
        const viz::FrameOutput out = render(scene, "vsv", s, 80, 60);
        // The pixel's alpha cell from the camera's ray for that pixel and the light's frame.
        const viz::vsv::EpipolarFrame f = viz::vsv::frameForLight(scene, scene.lights[0]);
        const viz::vsv::EpipolarGrid g = viz::vsv::gridForLight(scene, scene.lights[0], 80, 60, 64, 64, 64, true);
        const double alpha = viz::vsv::alphaCoord(g, viz::vsv::alphaOf(f, viz::scene::pixelRay(scene.camera, 80, 60, pick.x, pick.y)));
        int before = 0, after = 0;
        const int read = viz::testing::expectColumnIsAVoxelColumnAndItsPrefixOr(
            *find(out, "vsv.voxels")->image, *find(out, "vsv.column")->image, alpha, before, after);
        EXPECT_GT(read, 8) << "pixel " << pick.x << ", " << pick.y << ": the fragment is beyond the first few phi bits";
        std::printf("pixel (%d, %d): %d bits read, %d occluder bits, %d shadowed after the scan\n", pick.x, pick.y,
                    read, before, after);
    }
}

// The acceptance figure: exact combination at 256^3 voxels within 5 % of the reference on grate
// at 160x120; the factorisation's error is reported next to it. No NaN or Inf anywhere.
TEST_F(VsvTest, MatchesTheReferenceOnGrate) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    const viz::FrameOutput reference = render(scene, "reference", {}, 160, 120);
    ASSERT_FALSE(reference.airlight.empty());
    const viz::FrameOutput exact = render(scene, "vsv", {{"voxels", 256}, {"combine", 1}, {"shadow_map", 2048}}, 160, 120);
    const viz::FrameOutput fraction =
        render(scene, "vsv", {{"voxels", 256}, {"combine", 0}, {"shadow_map", 2048}}, 160, 120);
    for (const viz::FrameOutput* o : {&exact, &fraction}) {
        EXPECT_TRUE(allFinite(o->airlight));
        EXPECT_TRUE(allFinite(o->final));
    }
    const double eExact = relativeL2(exact.airlight, reference.airlight);
    const double eFraction = relativeL2(fraction.airlight, reference.airlight);
    const double eFinal = relativeL2(exact.final, reference.final);
    std::printf("vsv grate 160x120 voxels=256: relative L2 exact %.4f, fraction %.4f, final (exact) %.4f\n", eExact,
                eFraction, eFinal);
    EXPECT_LT(eExact, 0.05);
    EXPECT_LT(eExact, eFraction);
}

TEST_F(VsvTest, PointLightMatchesTheReference) {
    const viz::scene::Scene scene = pointGrate();
    expectNearReference(scene, "vsv", {{"voxels", 256}, {"shadow_map", 1024}}, 160, 120, 0.05,
                        "vsv grate with a point light 160x120 voxels=256");
}

// Dynamic range selection spends the cells on the visible part of epipolar space: at equal resolution
// the error is lower than with the grid over all of it.
TEST_F(VsvTest, DynamicRangeBeatsTheFullRangeAtEqualResolution) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    const viz::FrameOutput reference = render(scene, "reference", {}, 160, 120);
    const double eDynamic =
        relativeL2(render(scene, "vsv", {{"voxels", 64}, {"dynamic_range", 1}}, 160, 120).airlight, reference.airlight);
    const double eFull =
        relativeL2(render(scene, "vsv", {{"voxels", 64}, {"dynamic_range", 0}}, 160, 120).airlight, reference.airlight);
    std::printf("vsv grate voxels=64: relative L2 dynamic range %.4f, full range %.4f\n", eDynamic, eFull);
    EXPECT_LT(eDynamic, eFull);
}

// With the light in the image, the plan compiles the epipole case in, and the image stays finite and
// close to the reference.
TEST_F(VsvTest, EpipoleInViewUsesTheSpecialCase) {
    const viz::scene::Scene scene = grateLookingAtLight();
    auto technique = viz::makeTechnique("vsv");
    const viz::Settings settings = viz::completeSettings(*technique, {{"voxels", 128}});
    const viz::Plan plan = technique->plan(scene, settings);
    const auto it = std::find_if(plan.features.begin(), plan.features.end(),
                                 [](const viz::FeaturePlan& f) { return f.feature == "EPIPOLE"; });
    ASSERT_NE(it, plan.features.end());
    EXPECT_TRUE(it->enabled);
    EXPECT_NE(it->why.find("compiled in: EPIPOLE"), std::string::npos);
    const viz::FrameOutput reference = render(scene, "reference", {}, 160, 120);
    const viz::FrameOutput on = render(scene, "vsv", {{"voxels", 64}, {"epipole", 1}}, 160, 120, -1, {"vsv.visibility"});
    const viz::FrameOutput off = render(scene, "vsv", {{"voxels", 64}, {"epipole", 0}}, 160, 120);
    EXPECT_TRUE(allFinite(on.airlight));
    EXPECT_TRUE(allFinite(off.airlight));
    const double eOn = relativeL2(on.airlight, reference.airlight);
    const double eOff = relativeL2(off.airlight, reference.airlight);
    std::printf("vsv point-light grate looking at the light voxels=64: relative L2 epipole case %.4f, grid only %.4f\n",
                eOn, eOff);
    // Direct rays (visibility.a = -1) are those within one alpha cell of the epipole and those crossing
    // fewer than `direct_bins` phi bins: pixels around the light. Here the grid gives them the same
    // visibility (nothing lies between the eye and the light), so the two errors agree.
    const viz::Image& vis = *find(on, "vsv.visibility")->image;
    int replaced = 0;
    for (int y = 0; y < vis.height; ++y)
        for (int x = 0; x < vis.width; ++x) replaced += vis.at(x, y, 3) < 0.0f ? 1 : 0;
    std::printf("  direct rays: %d\n", replaced);
    EXPECT_GT(replaced, 0);
    EXPECT_LT(replaced, vis.width * vis.height / 20);
    EXPECT_LT(eOn, 0.1);
}

// The epipole rules on and off against the reference, over the rays they replace (vsv.visibility.a = -1
// with direct_bins=0: exactly the rays within one alpha cell of the epipole; 28 pixels here). With the
// plank halfway to the light both rules beat the grid (measured: grid 0.017, march 0.0062, paper 0.0043);
// with it next to the light the paper's rule fails as its text says (fragment on the plank: dark, yet
// the stretch past the plank's edge is lit; 0.9: grid 0.018, march 0.0037, paper 0.028; 0.97: 0.011,
// 0.0039, 0.11), which is why march is the default.
TEST_F(VsvTest, EpipoleRulesAgainstTheReferenceOnAndOff) {
    const int w = 160, h = 120;
    for (double at : {0.5, 0.9, 0.97}) {
        const viz::scene::Scene scene = plankBeforeTheLight(at);
        const viz::FrameOutput reference = render(scene, "reference", {}, w, h);
        viz::Settings settings = {{"voxels", 32}, {"direct_bins", 0}, {"epipole", 1}};
        const viz::FrameOutput march = render(scene, "vsv", settings, w, h, -1, {"vsv.visibility"});
        const viz::Image& vis = *find(march, "vsv.visibility")->image;
        int cell = 0;
        auto errorInCell = [&](const viz::Image& a) {
            double num = 0.0, den = 0.0;
            cell = 0;
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    if (vis.at(x, y, 3) >= 0.0f) continue;
                    ++cell;
                    for (int c = 0; c < 3; ++c) {
                        const double r = reference.airlight.at(x, y, c), d = double(a.at(x, y, c)) - r;
                        num += d * d;
                        den += r * r;
                    }
                }
            return std::sqrt(num / den);
        };
        settings["epipole"] = 0;
        const viz::FrameOutput off = render(scene, "vsv", settings, w, h);
        settings["epipole"] = 2;
        const viz::FrameOutput paper = render(scene, "vsv", settings, w, h);
        for (const viz::FrameOutput* o : {&march, &off, &paper}) EXPECT_TRUE(allFinite(o->airlight));
        const double eOff = errorInCell(off.airlight), eMarch = errorInCell(march.airlight),
                     ePaper = errorInCell(paper.airlight);
        std::printf("vsv plank at %.2f, voxels=32, %d px in the epipole cell: relative L2 there grid %.4f, march %.4f, "
                    "paper %.4f\n", at, cell, eOff, eMarch, ePaper);
        ASSERT_GT(cell, 8);
        ASSERT_LT(cell, w * h / 50);
        EXPECT_LT(eMarch, 0.5 * eOff) << at;
        if (at == 0.5) EXPECT_LT(ePaper, 0.5 * eOff);
        else EXPECT_GT(ePaper, eMarch) << at;  // an occluder next to the light: the rule's known failure
    }
}

TEST_F(VsvTest, StoppingAfterEachStagePublishesOnlyWhatExists) {
    expectEachStageStopsCleanly("vsv", viz::scene::makeBuiltinScene("grate"), {{"voxels", 32}}, 4, 5);
}

TEST_F(VsvTest, PlanAndInputErrors) {
    auto technique = viz::makeTechnique("vsv");
    const viz::Settings settings = viz::completeSettings(*technique, {});
    const viz::Plan grate = technique->plan(viz::scene::makeBuiltinScene("grate"), settings);
    EXPECT_FALSE(feature(grate, "EPIPOLE").enabled);
    EXPECT_TRUE(feature(grate, "COMBINE_EXACT").enabled);
    EXPECT_NE(feature(grate, "SHADOW_MAPS_CUBE").why.find("SHADOW_NO_CUBE"), std::string::npos);
    const viz::Plan point = technique->plan(pointGrate(), settings);
    EXPECT_TRUE(feature(point, "SHADOW_MAPS_CUBE").enabled);
    EXPECT_FALSE(feature(point, "SPOT").enabled);
    viz::Settings fraction = settings;
    fraction["combine"] = 0;
    EXPECT_FALSE(feature(technique->plan(viz::scene::makeBuiltinScene("grate"), fraction), "COMBINE_EXACT").enabled);
    EXPECT_TRUE(feature(technique->plan(viz::scene::makeBuiltinScene("colonnade"), settings), "DIRECTIONAL").enabled);
    EXPECT_TRUE(feature(technique->plan(viz::scene::makeBuiltinScene("tv-room"), settings), "AREA_LIGHTS_BY_IVSV").enabled);
    EXPECT_FALSE(feature(grate, "AREA_LIGHTS_BY_IVSV").enabled);
    // phi is rounded up to whole 32-bit words and the plan says so (48 and voxels_phi=100 once threw, and
    // the window's sliders land on such values 31 times in 32).
    viz::Settings odd = settings;
    odd["voxels_phi"] = 100;
    EXPECT_EQ(technique->plan(viz::scene::makeBuiltinScene("grate"), odd).stages[2].why,
              "phi 100 rounded up to 128 bits (whole 32-bit words)");
    viz::Settings between = settings;
    between["voxels"] = 48;
    const viz::Plan rounded = technique->plan(viz::scene::makeBuiltinScene("grate"), between);
    EXPECT_EQ(rounded.stages[2].stage, "vsv.voxelize");
    EXPECT_EQ(rounded.stages[2].why, "phi 48 rounded up to 64 bits (whole 32-bit words)");
    EXPECT_EQ(technique->plan(viz::scene::makeBuiltinScene("grate"), settings).stages[2].why, "");
}

// Every `voxels` in vsv's range runs, and refines with the count: 48 lies between 32 and 64 in error
// against the reference (its phi rounded up to 64).
TEST_F(VsvTest, AVoxelCountBetweenWholeWordsRunsBetweenItsNeighbours) {
    const viz::scene::Scene grate = viz::scene::makeBuiltinScene("grate");
    const viz::Image ref = render(grate, "reference", {}, 64, 48).airlight;
    std::map<int, double> error;
    for (int voxels : {32, 48, 64}) {
        viz::FrameOutput out;
        ASSERT_NO_THROW(out = render(grate, "vsv", {{"voxels", voxels}}, 64, 48)) << voxels;
        ASSERT_TRUE(viz::testing::allFinite(out.airlight));
        error[voxels] = viz::testing::relativeL2(out.airlight, ref);
    }
    std::printf("vsv grate 64x48: relative L2 %.4f (32), %.4f (48), %.4f (64)\n", error[32], error[48], error[64]);
    // An explicit phi is rounded the same way: 100 bits give the frame 128 gives.
    const viz::FrameOutput a = render(grate, "vsv", {{"voxels_phi", 100}}, 64, 48);
    const viz::FrameOutput b = render(grate, "vsv", {{"voxels_phi", 128}}, 64, 48);
    EXPECT_EQ(a.airlight.pixels, b.airlight.pixels);
    EXPECT_LT(error[48], error[32]);
    EXPECT_GT(error[48], error[64]);
}


// Round-2 stiff cases: a sun whose orthographic map spans 1e6 (500-unit texels) and a plate whose face
// passes through the spot. Before: relative L2 0.915 and 0.688 (the voxelizer ignored the shared
// lookup's bias, so each huge texel shadowed its own receivers; the middle image column blended two
// theta cells across the plate's face). The bounds are the stiff suite's for their classes.
TEST_F(VsvTest, StiffCasesHugeTexelsAndAnOccluderThroughTheLight) {
    const std::vector<std::pair<std::string, double>> cases = {{"depth-range-1e6", 0.025},
                                                               {"occluder-touching-light", 0.05}};
    for (const auto& [id, bound] : cases) {
        const viz::scene::StiffCase* c = viz::scene::findStiffCase(id);
        ASSERT_NE(c, nullptr) << id;
        const viz::scene::Scene scene = viz::scene::buildStiffScene(*c);
        const viz::FrameOutput reference = render(scene, "reference", {}, 33, 25);
        const viz::FrameOutput out = render(scene, "vsv", {}, 33, 25);
        ASSERT_FALSE(out.airlight.empty());
        EXPECT_TRUE(allFinite(out.airlight)) << id;
        const double e = relativeL2(out.airlight, reference.airlight);
        std::printf("vsv %s 33x25 voxels=128: relative L2 %.4f (bound %.3f)\n", id.c_str(), e, bound);
        EXPECT_LT(e, bound) << id;
    }
}

// force_features=1 compiles in every light kind, the epipole rays and the inner ivsv: only dead code
// (or zero work) is added, so the image is the same.
TEST_F(VsvTest, ForcingSceneFeaturesLeavesTheImageUnchanged) {
    const std::vector<std::pair<std::string, std::string>> runs = {
        {"vsv", "grate"}, {"vsv", "colonnade"}, {"vsv", "stained-glass"}, {"vsv", "tv-room"},
        {"ivsv", "grate"}, {"ivsv", "tv-room"}};
    for (const auto& [technique, name] : runs) {
        const viz::scene::Scene s = viz::scene::makeBuiltinScene(name);
        viz::Settings plain = {{"voxels", 64}};
        if (technique == "ivsv") plain["vpls"] = 16;
        else plain["shadow_map"] = 256;
        viz::Settings forced = plain;
        forced["force_features"] = 1;
        const auto t = viz::makeTechnique(technique);
        const viz::Plan a = t->plan(s, viz::completeSettings(*t, plain));
        const viz::Plan b = t->plan(s, viz::completeSettings(*t, forced));
        // The forced plan really runs more (features compiled in, or stages the scene skips).
        int onA = 0, onB = 0;
        for (const auto& f : a.features) onA += f.enabled;
        for (const auto& f : b.features) onB += f.enabled;
        for (const auto& st : a.stages) onA += st.runs;
        for (const auto& st : b.stages) onB += st.runs;
        EXPECT_GT(onB, onA) << technique << " " << name;
        const viz::FrameOutput x = render(s, technique, plain, 40, 30);
        const viz::FrameOutput y = render(s, technique, forced, 40, 30);
        ASSERT_FALSE(x.airlight.empty());
        ASSERT_EQ(x.airlight.pixels.size(), y.airlight.pixels.size());
        EXPECT_TRUE(allFinite(y.airlight));
        double maxDiff = 0.0, maxValue = 0.0;
        for (std::size_t i = 0; i < x.airlight.pixels.size(); ++i) {
            maxDiff = std::max(maxDiff, double(std::abs(x.airlight.pixels[i] - y.airlight.pixels[i])));
            maxValue = std::max(maxValue, double(std::abs(x.airlight.pixels[i])));
        }
        EXPECT_GT(maxValue, 0.0) << technique << " " << name;
        EXPECT_LE(maxDiff, 1e-5 * maxValue) << technique << " " << name;
    }
}

// A spot behind the camera shining away lights nothing visible: it is culled (no GPU light, no grid)
// and the image is that of the scene without it.
TEST_F(VsvTest, ACulledLightIsDroppedWithoutChangingTheImage) {
    const viz::scene::Scene plain = viz::scene::makeBuiltinScene("grate");
    viz::scene::Scene extra = plain;
    viz::scene::Light away = plain.lights[0];
    away.name = "behind";
    away.position = {0.0, 1.0, 9.0};
    away.direction = {0.0, 0.0, 1.0};
    extra.lights.push_back(away);
    const viz::Settings fast = {{"voxels", 64}, {"shadow_map", 256}};
    const viz::FrameOutput a = render(plain, "vsv", fast, 40, 30);
    const viz::FrameOutput b = render(extra, "vsv", fast, 40, 30);
    ASSERT_FALSE(b.airlight.empty());
    double maxDiff = 0.0, maxValue = 0.0;
    for (std::size_t i = 0; i < a.airlight.pixels.size(); ++i) {
        maxDiff = std::max(maxDiff, double(std::abs(a.airlight.pixels[i] - b.airlight.pixels[i])));
        maxValue = std::max(maxValue, double(std::abs(a.airlight.pixels[i])));
    }
    EXPECT_LE(maxDiff, 1e-5 * maxValue);
}
