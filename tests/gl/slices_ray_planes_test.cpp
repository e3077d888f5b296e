// slices.ray_planes: the picked pixel's record of every plane drawn, written by the plane shader and the
// blend replay, against an independent CPU computation (geometry, coverage, the physical weight, each
// accumulation format's rounding) and against the pixel of slices.accumulation, on grate at 160x120.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <memory>
#include <string>
#include <vector>

#include "technique_test_util.h"
#include "scene/builtin_scenes.h"
#include "scene/camera.h"
#include "shared/airlight.h"
#include "techniques/reference/emitters.h"
#include "techniques/reference/ray_probe.h"
#include "techniques/registry.h"
#include "techniques/slices/ray_planes.h"

namespace {

constexpr int kW = 160, kH = 120;
// A pixel below the centre whose ray runs through the light shafts under the grate's gaps and the
// shadows of its bars (checked below against the reference's lit intervals).
constexpr int kPickX = 83, kPickY = 72;
constexpr int kPlanes = 64;

// Columns of the table and the status codes (ray_planes.h, pick_record.glsl).
using namespace viz::slices;
constexpr int kWhere = kColWhere, kTest = kColTest, kValue = kColValue, kAdded = kColAdded, kAfter = kColAfter,
              kSet = kColSet, kColumns = kRayPlaneColumns;
constexpr int kAdded_ = int(PickStatus::Added), kBeyond = int(PickStatus::BeyondSurface),
              kLightFrustum = int(PickStatus::LightFrustum), kUserPlane = int(PickStatus::UserPlane),
              kOutsideQuad = int(PickStatus::OutsideQuad);

struct Row {
    int plane = 0;
    double s = 0, t = 0, dt = 0;
    int status = 0;
    double v = 0;
    int channel = -1;
    double d = 0;
    glm::dvec4 value{0.0}, added{0.0}, after{0.0};
    int light = 0, set = 0;
};

std::vector<Row> rowsOf(const viz::Image& table) {
    std::vector<Row> rows;
    auto at = [&](int column, int row) {
        glm::dvec4 v(0.0);
        for (int c = 0; c < 4; ++c) v[c] = double(table.at(column, row, c));
        return v;
    };
    for (int y = 0; y < table.height; ++y) {
        Row r;
        const glm::dvec4 where = at(kWhere, y), test = at(kTest, y), set = at(kSet, y);
        r.plane = int(where.x), r.s = where.y, r.t = where.z, r.dt = where.w;
        r.status = int(test.x), r.v = test.y, r.channel = int(test.z), r.d = test.w;
        r.value = at(kValue, y), r.added = at(kAdded, y), r.after = at(kAfter, y);
        r.light = int(set.x), r.set = int(set.y);
        rows.push_back(r);
    }
    return rows;
}

// x rounded to a binary16 value by `round` on its 10 fraction bits (normal and subnormal range).
template <typename Round>
double toHalf(double x, Round round) {
    if (x == 0.0) return 0.0;
    const int e = std::max(std::ilogb(x), -14);  // smallest normal 2^-14
    return std::ldexp(round(std::ldexp(x, 10 - e)), e - 10);
}

// grate's spot at distance t along the eye ray w, as the plane shader defines it but without the shadow
// test: sigma_s p(cos theta) E exp(-sigma_t t), E = intensity A_spot exp(-sigma_t r) / r^2, A_spot the
// reference's (KHR's squared falloff; grate's spot has no cookie).
glm::dvec3 spotIntegrand(const viz::scene::Scene& scene, const glm::dvec3& w, double t) {
    const viz::scene::Light& spot = scene.lights.front();
    const glm::dvec3 light = spot.position - scene.camera.position;  // eye-relative world, as the shaders work
    const glm::dvec3 p = t * w;
    const glm::dvec3 fromLight = glm::normalize(p - light);
    const double a = viz::reference::SpotProfile::fromLight(spot, nullptr).attenuation(fromLight);
    const glm::dvec3 toLight = light - p;
    const double r2 = glm::dot(toLight, toLight), sigmaT = scene.medium.sigma_t();
    const glm::dvec3 e = spot.colour * spot.intensity * a * std::exp(-sigmaT * std::sqrt(r2)) / r2;
    const double phase = viz::airlight::phaseHG(glm::dot(fromLight, -w), scene.medium.g);
    return scene.medium.sigma_s * phase * std::exp(-sigmaT * t) * e;
}

class SlicesRayPlanesTest : public viz::testing::TechniqueTest {
protected:
    struct Run {
        viz::FrameOutput out;
        std::vector<Row> rows;
        glm::dvec4 accumulated{0.0};
    };
    static Run renderPick(const viz::scene::Scene& scene, int accum, viz::Settings extra = {}) {
        viz::Settings s{{"planes", kPlanes}, {"accum", accum}, {"pick_x", kPickX}, {"pick_y", kPickY}};
        for (const auto& [k, v] : extra) s[k] = v;
        Run run;
        run.out = render(scene, "slices", s, kW, kH, 2, {"slices.accumulation"});
        const viz::Intermediate* table = find(run.out, "slices.ray_planes");
        const viz::Intermediate* accumulation = find(run.out, "slices.accumulation");
        EXPECT_TRUE(table && table->image && table->rayView);
        EXPECT_TRUE(accumulation && accumulation->image);
        if (!table || !table->image || !accumulation || !accumulation->image) return run;
        EXPECT_EQ(table->image->width, int(kColumns));
        run.rows = rowsOf(*table->image);
        for (int c = 0; c < 4; ++c) run.accumulated[c] = double(accumulation->image->at(kPickX, kPickY, c));
        return run;
    }
};

// The sum of the quantised values along the ray is the pixel's accumulated value: the replayed blend
// quantises exactly as the frame's did (exact equality in all four formats on llvmpipe).
TEST_F(SlicesRayPlanesTest, QuantisedValuesSumToTheAccumulatedPixelInEveryFormat) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    for (int accum = 0; accum < 4; ++accum) {
        SCOPED_TRACE("accum " + std::to_string(accum));
        const Run run = renderPick(scene, accum);
        ASSERT_EQ(run.rows.size(), std::size_t(kPlanes)) << "grate has one spot light: one draw set";
        glm::dvec4 sum(0.0);
        int added = 0;
        for (const Row& r : run.rows) {
            sum += r.added;
            added += r.status == kAdded_ ? 1 : 0;
        }
        EXPECT_GT(added, kPlanes / 4) << "the ray crosses the light volume over many planes";
        EXPECT_GT(sum.r + sum.g + sum.b + sum.a, 0.0) << "a pixel in a shaft gathers light";
        std::printf("accum %d: %d planes added; sum of quantised values %.9g %.9g %.9g %.9g, accumulation "
                    "%.9g %.9g %.9g %.9g\n",
                    accum, added, sum.r, sum.g, sum.b, sum.a, run.accumulated.r, run.accumulated.g,
                    run.accumulated.b, run.accumulated.a);
        // 8-bit and half: exact. Float: each added value is a float difference of two float sums, which
        // rounds when the plane adds more than the accumulation holds; their sum stays within one float
        // ulp of the accumulation (measured: 5e-10 of 0.069, 0.12 ulp, at this pixel).
        for (int c = 0; c < 4; ++c) {
            const double ulp = double(std::nextafter(float(run.accumulated[c]), 1.0f)) - run.accumulated[c];
            if (accum == 3) {
                EXPECT_LE(std::abs(sum[c] - run.accumulated[c]), ulp) << "channel " << c;
            } else {
                EXPECT_EQ(sum[c], run.accumulated[c]) << "channel " << c;
            }
        }
        // And the last replayed value is the accumulation itself (the sum telescopes to it).
        for (int c = 0; c < 4; ++c) EXPECT_EQ(run.rows.back().after[c], run.accumulated[c]) << "channel " << c;
    }
}

// Two draw sets (the spot's planes, then the point light's over the camera frustum): the accumulation runs
// on from one into the next, and so does the replay (over rows of its target, each seeded with the end of
// the one before); the sum over both is the accumulated pixel.
TEST_F(SlicesRayPlanesTest, QuantisedValuesSumAcrossDrawSets) {
    viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    viz::scene::Light point = scene.lights.front();
    point.name = "point";
    point.type = viz::scene::LightType::Point;
    point.position = {1.5, 2.0, 1.0};
    point.intensity = 20.0;
    scene.lights.push_back(point);
    // 2 x 64 records, also more than one row of the replay's target (64 texels): the second row starts
    // from the end of the first. Pass 4: 2 x 150, rows that start inside a draw set.
    for (int accum = 0; accum < 5; ++accum) {
        SCOPED_TRACE("accum " + std::to_string(accum));
        const int planes = accum == 4 ? 150 : kPlanes;
        // Small shadow maps: the point light's cube map would dominate the test's time.
        const Run run = renderPick(scene, accum == 4 ? 2 : accum, {{"planes", planes}, {"shadow_map", 256}});
        ASSERT_EQ(run.rows.size(), std::size_t(2 * planes));
        glm::dvec4 sum(0.0), perSet[2] = {glm::dvec4(0.0), glm::dvec4(0.0)};
        for (const Row& r : run.rows) {
            sum += r.added;
            perSet[r.set] += r.added;
        }
        EXPECT_EQ(run.rows.front().light, 0);
        EXPECT_EQ(run.rows.back().light, -1) << "the point light's set: the unbounded lights";
        EXPECT_GT(perSet[0].r + perSet[0].g + perSet[0].b + perSet[0].a, 0.0);
        EXPECT_GT(perSet[1].r + perSet[1].g + perSet[1].b + perSet[1].a, 0.0);
        for (int c = 0; c < 4; ++c) {
            const double ulp = double(std::nextafter(float(run.accumulated[c]), 1.0f)) - run.accumulated[c];
            EXPECT_EQ(run.rows.back().after[c], run.accumulated[c]) << "channel " << c;
            if (accum == 3) {
                EXPECT_LE(std::abs(sum[c] - run.accumulated[c]), ulp) << "channel " << c;
            } else {
                EXPECT_EQ(sum[c], run.accumulated[c]) << "channel " << c;
            }
        }
    }
}

// Each record against a CPU computation from the scene alone: the plane depths and the ray's t and dt,
// which planes cover the pixel (the surface distance from the reference probe, the spot's cone), the
// physical weight sigma_s p(cos) E V exp(-sigma_t t) dt times the store scale (with the GPU's shadow
// test V, itself checked against the reference's lit intervals), and each format's rounding of the sum.
TEST_F(SlicesRayPlanesTest, RecordsMatchAnIndependentCpuComputation) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    const viz::scene::Camera& cam = scene.camera;
    const viz::scene::Light& spot = scene.lights.front();
    const viz::reference::RayProbe probe = viz::reference::probePixel(scene, kW, kH, kPickX, kPickY);
    ASSERT_EQ(probe.lights.size(), 1u);
    const auto& lit = probe.lights.front().lit;
    ASSERT_GE(lit.size(), 2u) << "the picked ray must cross shafts and shadows";
    const glm::dvec3 w = glm::dvec3(viz::testing::shaderPixelRay(cam, kW, kH, kPickX, kPickY));
    const double cosForward = glm::dot(w, cam.forward);
    const glm::dvec3 light = spot.position - cam.position;  // eye-relative world, as the shaders work
    const glm::dvec3 axis = glm::normalize(spot.direction);
    const double cosOuter = std::cos(spot.outerConeAngle);
    const double accumRange = 2.0;  // the parameter's default

    for (int accum = 0; accum < 4; ++accum) {
        SCOPED_TRACE("accum " + std::to_string(accum));
        // The paper's one sample per plane (integration=midpoint), the formula computed here.
        const Run run = renderPick(scene, accum, {{"integration", 0}});
        ASSERT_EQ(run.rows.size(), std::size_t(kPlanes));
        const double storeScale = accum == 0 ? 1.0 / accumRange : accum == 1 ? 4.0 / accumRange : 1.0;
        const double spacing = run.rows[0].s - run.rows[1].s;
        ASSERT_GT(spacing, 0.0);
        double worstValue = 0.0, worstGeometry = 0.0;
        int shadowChecked = 0, shadowDisagree = 0, roundingDiffers[2] = {0, 0}, shadowSeen[2] = {0, 0};
        glm::dvec4 before(0.0);
        for (std::size_t i = 0; i < run.rows.size(); ++i) {
            const Row& r = run.rows[i];
            EXPECT_EQ(r.plane, int(i));
            EXPECT_EQ(r.light, 0);
            // Geometry: planes back to front, evenly spaced (the nearest may be pulled out to znear);
            // t and dt along this pixel's ray.
            if (i + 1 < run.rows.size() - 1)
                worstGeometry = std::max(worstGeometry, std::abs((r.s - run.rows[i + 1].s) - spacing) / spacing);
            worstGeometry = std::max(worstGeometry, std::abs(r.t - r.s / cosForward) / r.t);
            worstGeometry = std::max(worstGeometry, std::abs(r.dt - spacing / cosForward) / r.dt);
            // Coverage: beyond the surface exactly when t > d; inside the spot's cone (inside its frustum)
            // and before the surface a plane must be shaded; a plane clipped by the frustum lies outside the cone.
            const glm::dvec3 p = r.t * w;
            const glm::dvec3 fromLight = glm::normalize(p - light);
            const double cd = glm::dot(axis, fromLight);
            const bool beforeSurface = r.t < probe.d * (1.0 - 1e-4);
            const bool beyondSurface = r.t > probe.d * (1.0 + 1e-4);
            // (Clipping comes first: a plane beyond the surface and outside the frustum is reported clipped.)
            if (beyondSurface) {
                EXPECT_NE(r.status, kAdded_) << "plane " << i << " t " << r.t;
            }
            if (r.status == kBeyond) {
                EXPECT_GT(r.t, r.d) << "plane " << i;
            }
            if (beforeSurface && cd > cosOuter * (1.0 + 1e-6)) {
                EXPECT_EQ(r.status, kAdded_) << "plane " << i;
            }
            if (r.status == kLightFrustum) {
                EXPECT_LT(cd, cosOuter * (1.0 + 1e-6)) << "plane " << i;
            }
            EXPECT_TRUE(r.status >= kAdded_ && r.status <= kOutsideQuad && r.status != kUserPlane)
                << "plane " << i << " status " << r.status;
            if (r.status == kAdded_ || r.status == kBeyond) {
                EXPECT_NEAR(r.d, probe.d, 1e-3 * probe.d);
            }
            // The physical weight with the GPU's V, times the store scale.
            glm::dvec4 expected(0.0);
            if (r.status == kAdded_) {
                ASSERT_TRUE(r.v == 0.0 || r.v == 1.0) << "nearest-texel shadow test";
                const glm::dvec3 v = spotIntegrand(scene, w, r.t) * (r.v * r.dt * storeScale);
                if (accum == 1) {
                    EXPECT_EQ(r.channel, int(i) % 4);
                    expected[int(i) % 4] = (v.r + v.g + v.b) / 3.0;
                } else {
                    EXPECT_EQ(r.channel, -1);
                    expected = glm::dvec4(v, 0.0);
                }
                // V against the reference's lit intervals, away from their ends (a shadow-map texel and
                // the depth bias blur the edges).
                const double margin = 0.05;
                bool inLit = false, nearEdge = false;
                for (const auto& iv : lit) {
                    inLit = inLit || (r.t > iv.a && r.t < iv.b);
                    nearEdge = nearEdge || std::abs(r.t - iv.a) < margin || std::abs(r.t - iv.b) < margin;
                }
                if (!nearEdge) {
                    ++shadowChecked;
                    ++shadowSeen[r.v == 1.0 ? 1 : 0];
                    shadowDisagree += (r.v == 1.0) != inLit ? 1 : 0;
                }
            }
            const double scale = std::max({expected.r, expected.g, expected.b, expected.a, 1e-30});
            for (int c = 0; c < 4; ++c)
                worstValue = std::max(worstValue, std::abs(r.value[c] - expected[c]) / scale);
            // Each format's rounding of dst + src, from the GPU's own src (the shader output), under two
            // rounding modes: the GL spec prefers round to nearest; llvmpipe rounds half toward zero.
            for (int c = 0; c < 4; ++c) {
                const double sum = before[c] + double(float(r.value[c]));
                for (int mode = 0; mode < 2; ++mode) {
                    auto round = [&](double x) { return mode == 0 ? std::nearbyint(x) : std::trunc(x); };
                    bool same = true;
                    if (accum <= 1)  // unorm8: compare the stored integers (the readback's k / 255 is inexact)
                        same = round(std::clamp(sum, 0.0, 1.0) * 255.0) == std::nearbyint(r.after[c] * 255.0);
                    else if (accum == 2)
                        same = toHalf(sum, round) == r.after[c];
                    else  // float: IEEE addition in float, whichever mode
                        same = double(float(before[c]) + float(r.value[c])) == r.after[c];
                    roundingDiffers[mode] += same ? 0 : 1;
                }
                before[c] = r.after[c];
            }
        }
        std::printf("accum %d: worst relative geometry error %.2e, value error %.2e; shadow test checked on "
                    "%d planes (%d in shadow), %d disagree with the reference; channel values rounded otherwise than to nearest "
                    "%d, than toward zero %d\n",
                    accum, worstGeometry, worstValue, shadowChecked, shadowSeen[0], shadowDisagree, roundingDiffers[0],
                    roundingDiffers[1]);
        EXPECT_LT(worstGeometry, 1e-5);
        EXPECT_LT(worstValue, 1e-4);
        EXPECT_GT(shadowChecked, kPlanes / 4);
        EXPECT_GT(shadowSeen[0], 0) << "some planes in the bars' shadows";
        EXPECT_GT(shadowSeen[1], 0) << "some planes in the shafts";
        EXPECT_EQ(shadowDisagree, 0);
        // Every stored value follows one rounding mode of dst + src.
        EXPECT_EQ(std::min(roundingDiffers[0], roundingDiffers[1]), 0);
    }
}

// At the default on grate (integration=auto: each plane integrates its slab) a plane's record is its slab's
// integral along the ray, [s - delta_s / 2, s + delta_s / 2] / dot(w, forward) cut to the surface, here
// against a 4,000-point midpoint quadrature of the integrand with the reference's visibility, on every slab
// that no shadow edge of the reference comes near (V is then one value over the slab for both). The
// shader's rule is a midpoint rule in the angle seen from the light with 1/r^2 exact, its nodes at most
// slab_angle = 0.1 rad apart. A slab that begins beyond the surface says so.
TEST_F(SlicesRayPlanesTest, EachSlabsRecordIsItsIntegralAlongTheRayAtTheDefault) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    const viz::reference::RayProbe probe = viz::reference::probePixel(scene, kW, kH, kPickX, kPickY);
    ASSERT_EQ(probe.lights.size(), 1u);
    const auto& lit = probe.lights.front().lit;
    const glm::dvec3 w = glm::dvec3(viz::testing::shaderPixelRay(scene.camera, kW, kH, kPickX, kPickY));
    const double cosForward = glm::dot(w, scene.camera.forward);
    const Run run = renderPick(scene, 3);  // rgba32f: what the shader wrote is what was added
    ASSERT_EQ(run.rows.size(), std::size_t(kPlanes));
    const double spacing = run.rows[0].s - run.rows[1].s;
    ASSERT_GT(spacing, 0.0);
    struct Slab {
        int plane;
        glm::dvec3 value, expected;
    };
    std::vector<Slab> slabs;
    int beyond = 0;
    for (std::size_t i = 0; i + 1 < run.rows.size(); ++i) {  // the nearest slab may be cut at the eye
        const Row& r = run.rows[i];
        const double t0 = (r.s - 0.5 * spacing) / cosForward, t1 = std::min((r.s + 0.5 * spacing) / cosForward, probe.d);
        if (r.status == kBeyond) {
            ++beyond;
            EXPECT_GT(t0, probe.d * (1.0 - 1e-4)) << "plane " << i;
            continue;
        }
        if (r.status != kAdded_ || !(t1 > t0)) continue;
        const double margin = 0.05;  // a shadow-map texel and the depth bias blur the edges
        bool inLit = false, nearEdge = false;
        for (const auto& iv : lit) {
            inLit = inLit || (0.5 * (t0 + t1) > iv.a && 0.5 * (t0 + t1) < iv.b);
            for (double edge : {iv.a, iv.b}) nearEdge = nearEdge || (edge > t0 - margin && edge < t1 + margin);
        }
        if (nearEdge) continue;
        glm::dvec3 expected(0.0);
        if (inLit) {
            constexpr int kNodes = 4000;
            const double dt = (t1 - t0) / kNodes;
            for (int k = 0; k < kNodes; ++k) expected += spotIntegrand(scene, w, t0 + (k + 0.5) * dt) * dt;
        }
        slabs.push_back({int(i), glm::dvec3(r.value), expected});
    }
    // Within 1 % of the slab's own value, or 0.1 % of the pixel's L_air (the reference's): the slabs where
    // the ray leaves the cone hold a sliver of the penumbra, where A_spot^2 rises from 0, and the lit
    // interval the slab is cut to is padded (common/lights.glsl, litInterval), so a node may fall outside
    // the cone (there: 2e-7 against 4e-6, with the pixel at 0.06).
    ASSERT_GT(probe.airlight.g, 0.0);
    double worst = 0.0;
    int lit_ = 0;
    for (const Slab& s : slabs) {
        lit_ += s.expected.g > 0.0 ? 1 : 0;
        for (int c = 0; c < 3; ++c) {
            const double error = std::abs(s.value[c] - s.expected[c]);
            worst = std::max(worst, error / std::max(s.expected[c], 1e-3 * probe.airlight[c]));
            EXPECT_LE(error, 0.01 * s.expected[c] + 1e-3 * probe.airlight[c])
                << "plane " << s.plane << " channel " << c << ": " << s.value[c] << " against " << s.expected[c];
        }
    }
    std::printf("%zu slabs away from shadow edges (%d lit, %d beyond the surface): worst error %.2e of the larger "
                "of the slab's value and 0.1 %% of the pixel's L_air (%.4g)\n",
                slabs.size(), lit_, beyond, worst, probe.airlight.g);
    EXPECT_GT(lit_, 3);
    EXPECT_GT(int(slabs.size()) - lit_, 0) << "some slabs in the bars' shadows";
}

// User planes and the light frustum are told apart, and a pixel outside the light volume's box reports
// that no plane reaches it.
TEST_F(SlicesRayPlanesTest, StatusNamesWhatRemovedEachPlane) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    // A floor plane at y = 1.5: the ray's samples below it are clipped by the user plane.
    const Run clipped = renderPick(scene, 3, {{"user_clip", 1}, {"clip_y_min", 1.5}});
    const glm::dvec3 w = glm::dvec3(viz::testing::shaderPixelRay(scene.camera, kW, kH, kPickX, kPickY));
    int user = 0;
    for (const Row& r : clipped.rows) {
        const double y = scene.camera.position.y + r.t * w.y;
        if (r.status == kUserPlane) {
            ++user;
            EXPECT_LT(y, 1.5 + 1e-4);
        }
        if (r.status == kAdded_) {
            EXPECT_GE(y, 1.5 - 1e-4);
        }
    }
    EXPECT_GT(user, 0) << "the picked ray dips below y = 1.5 inside the light volume";
    // The top-left corner looks past the spot's frustum: no plane covers it.
    const viz::FrameOutput corner = render(scene, "slices", {{"planes", 16}, {"pick_x", 0}, {"pick_y", 0}}, kW, kH, 2);
    const viz::Intermediate* table = find(corner, "slices.ray_planes");
    ASSERT_TRUE(table && table->image);
    for (const Row& r : rowsOf(*table->image)) {
        EXPECT_TRUE(r.status == kOutsideQuad || r.status == kLightFrustum) << "plane " << r.plane;
        EXPECT_EQ(r.added, glm::dvec4(0.0));
    }
}

// ray_planes=0 compiles the recording out and publishes no table; the image does not change.
TEST_F(SlicesRayPlanesTest, RecordingOffPublishesNothingAndChangesNothing) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    const viz::FrameOutput on = render(scene, "slices", {{"planes", 32}}, kW, kH);
    const viz::FrameOutput off = render(scene, "slices", {{"planes", 32}, {"ray_planes", 0}}, kW, kH);
    EXPECT_NE(find(on, "slices.ray_planes"), nullptr);
    EXPECT_EQ(find(off, "slices.ray_planes"), nullptr);
    EXPECT_TRUE(viz::featureEnabled(on.plan, "PICK_RAY"));
    EXPECT_FALSE(viz::featureEnabled(off.plan, "PICK_RAY"));
    ASSERT_EQ(on.airlight.pixels.size(), off.airlight.pixels.size());
    EXPECT_EQ(on.airlight.pixels, off.airlight.pixels);
}

// Benchmark (never gates): what recording the picked pixel's planes costs (the pick draw, the replay, the
// readback). 9 pairs of frames with ray_planes = 0 and 1 back to back; the figure is the median of the
// paired differences in process CPU time (std::clock), which other processes' load disturbs less than
// wall time; with LP_NUM_THREADS=0 llvmpipe renders on this thread, so that is all the frame's work. Run
// with LP_NUM_THREADS=0 --gtest_also_run_disabled_tests --gtest_filter='*PickCost*'.
TEST_F(SlicesRayPlanesTest, DISABLED_PickCostBenchmark) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    for (const glm::ivec2 size : {glm::ivec2(160, 120), glm::ivec2(640, 480)})
        for (int n : {128, 512, 2048}) {
            std::unique_ptr<viz::Technique> technique[2] = {viz::makeTechnique("slices"), viz::makeTechnique("slices")};
            viz::FrameInput in[2];
            for (int pick = 0; pick < 2; ++pick) {
                in[pick].scene = &scene;
                in[pick].width = size.x;
                in[pick].height = size.y;
                viz::setRunSettings(in[pick], viz::completeSettings(*technique[pick], {{"planes", n}, {"ray_planes", pick}}));
                technique[pick]->run(in[pick]);  // compiles and allocates
            }
            std::vector<double> frame[2], differences;
            for (int rep = 0; rep < 9; ++rep) {
                double ms[2] = {0.0, 0.0};
                for (int pick = 0; pick < 2; ++pick) {
                    const std::clock_t start = std::clock();
                    technique[pick]->run(in[pick]);
                    ms[pick] = 1000.0 * double(std::clock() - start) / double(CLOCKS_PER_SEC);
                    frame[pick].push_back(ms[pick]);
                }
                differences.push_back(ms[1] - ms[0]);
            }
            for (auto* v : {&frame[0], &frame[1], &differences}) std::sort(v->begin(), v->end());
            std::printf("pick cost %dx%d planes=%d: frame CPU time (median) %.1f ms without, %.1f ms with "
                        "ray_planes; median paired difference %+.2f ms\n",
                        size.x, size.y, n, frame[0][4], frame[1][4], differences[4]);
        }
}

}  // namespace
