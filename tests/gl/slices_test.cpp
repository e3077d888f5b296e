// slices (Mitchell 2004) against the reference on `grate`, the precision lab, clipping, stepping plane by
// plane, shader permutations, and a benchmark (DISABLED_: run with --gtest_also_run_disabled_tests).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "technique_test_util.h"
#include "gl/readback.h"
#include "gl/work_counters.h"
#include "render/host_device.h"
#include "scene/builtin_scenes.h"
#include "scene/stiff_scenes.h"
#include "techniques/registry.h"
#include "techniques/slices/slice_geometry.h"

namespace {

class SlicesTest : public viz::testing::TechniqueTest {};

using viz::testing::relativeL2;

float maxValue(const viz::Image& a) { return *std::max_element(a.pixels.begin(), a.pixels.end()); }

std::vector<std::string> split(const std::string& key) {
    std::vector<std::string> out;
    std::stringstream in(key);
    for (std::string token; std::getline(in, token, ';');) out.push_back(token);
    return out;
}

bool contains(const std::vector<std::string>& v, const std::string& s) {
    return std::find(v.begin(), v.end(), s) != v.end();
}

std::string permutation(const viz::Plan& plan) {
    for (const auto& f : plan.features)
        if (f.feature == "PERMUTATION") return f.why;
    ADD_FAILURE() << "plan has no PERMUTATION entry";
    return {};
}

}  // namespace

// The acceptance figure: physical weighting with float accumulation converges to the reference
// on grate; at N = 512 the relative L2 error of L_air at 160x120 is below 5 %. The paper's one sample per
// plane (integration=midpoint), whose error falls at every step. The default's slab integral is already
// at 0.8 % with 8 planes, where the nodes' shadow tests decide the rest: 32 planes read 1.1 % (their nodes
// alias with the grate's bar shadows on some rays) before 128 read 0.43 %
// (SlicesEquiangularTest.FewPlanesMatchTheReferenceOnGrate checks it from 16 planes up).
TEST_F(SlicesTest, PhysicalWeightingConvergesToTheReferenceOnGrate) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    const viz::FrameOutput reference = render(scene, "reference", {}, 160, 120);
    ASSERT_FALSE(reference.airlight.empty());
    std::vector<double> errors;
    for (int n : {8, 32, 128, 512}) {
        const viz::FrameOutput out =
            render(scene, "slices", {{"planes", n}, {"weighting", 1}, {"accum", 3}, {"shadow_map", 2048}, {"integration", 0}},
                   160, 120);
        ASSERT_EQ(out.airlight.pixels.size(), reference.airlight.pixels.size());
        errors.push_back(relativeL2(out.airlight, reference.airlight));
        std::printf("slices physical rgba32f planes=%4d: relative L2 = %.4f\n", n, errors.back());
    }
    for (std::size_t i = 1; i < errors.size(); ++i) EXPECT_LT(errors[i], errors[i - 1]) << "step " << i;
    EXPECT_LT(errors.back(), 0.05);
}

// The paper's channel-mask trick: each RGBA8 channel holds a quarter of the planes, so each plane may be
// stored 4x larger and loses less to 8-bit rounding. Measured against the reference at N = 256.
TEST_F(SlicesTest, ChannelMaskRgba8HasALowerErrorThanPlainRgba8) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    const viz::FrameOutput reference = render(scene, "reference", {}, 160, 120);
    const viz::Settings base{{"planes", 256}, {"shadow_map", 2048}};
    auto error = [&](int accum) {
        viz::Settings s = base;
        s["accum"] = accum;
        return relativeL2(render(scene, "slices", s, 160, 120).airlight, reference.airlight);
    };
    const double e8 = error(0), eMask = error(1), e16 = error(2), e32 = error(3);
    std::printf("planes=256 relative L2: rgba8 %.4f  rgba8-mask %.4f  rgba16f %.4f  rgba32f %.4f\n", e8, eMask,
                e16, e32);
    EXPECT_LT(eMask, e8);
    EXPECT_LT(e32, eMask);
}

// With clip planes on, no shaded fragment lies outside the light frustum (atomic counter in the fragment
// shader), fewer fragments are shaded, and the image is the same within float tolerance (the integrand is
// zero outside the frustum anyway).
TEST_F(SlicesTest, ClippingShadesNothingOutsideTheLightFrustum) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    // The paper's planes (integration=midpoint): under the slab integral the planes and their clip planes
    // are widened by the slab, so fragments whose plane point lies outside the frustum are kept on purpose
    // (SlicesEquiangularTest.TheWidenedClipKeepsEveryFragmentThatAddsLight covers that clip).
    const viz::Settings base{{"planes", 64}, {"count_fragments", 1}, {"integration", 0}};
    viz::Settings on = base, off = base;
    on["clip"] = 1;
    off["clip"] = 0;
    const viz::FrameOutput a = render(scene, "slices", on, 160, 120);
    const viz::FrameOutput b = render(scene, "slices", off, 160, 120);
    const viz::Intermediate* ca = find(a, "slices.fragments");
    const viz::Intermediate* cb = find(b, "slices.fragments");
    ASSERT_TRUE(ca && ca->image && cb && cb->image);
    for (int row = 0; row < 2; ++row)
        std::printf("fragments (%s): clip on %.0f (outside %.0f), clip off %.0f (outside %.0f)\n",
                    row == 0 ? "occlusion query" : "atomic counters", ca->image->at(1, row), ca->image->at(0, row),
                    cb->image->at(1, row), cb->image->at(0, row));
    // The two counts agree (count_fragments runs without the depth test, under which the query would
    // count only the fragments in front of the surface and the counter all of them).
    for (const viz::Intermediate* c : {ca, cb}) {
        EXPECT_EQ(c->image->at(0, 0), c->image->at(0, 1));
        EXPECT_EQ(c->image->at(1, 0), c->image->at(1, 1));
    }
    EXPECT_EQ(ca->image->at(0, 0), 0.0f);
    EXPECT_GT(ca->image->at(1, 0), 0.0f);
    EXPECT_GT(cb->image->at(0, 0), 0.0f) << "the unclipped planes must reach outside the frustum";
    EXPECT_LT(ca->image->at(1, 0), cb->image->at(1, 0));
    // Clipping re-triangulates the planes, so interpolated positions differ by fp32 rounding, which the
    // 1/r^2 near the light amplifies: compare per value, relative.
    const float scale = maxValue(b.airlight);
    ASSERT_GT(scale, 0.0f);
    double worst = 0.0;
    for (std::size_t i = 0; i < a.airlight.pixels.size(); ++i) {
        const double diff = std::abs(double(a.airlight.pixels[i]) - double(b.airlight.pixels[i]));
        worst = std::max(worst, diff / std::max(double(b.airlight.pixels[i]), 1e-3 * double(scale)));
    }
    std::printf("clip on vs off: largest relative difference %.2e\n", worst);
    EXPECT_LT(worst, 1e-4);
}

// Stepping: the accumulation after k planes equals the CPU sum of the single planes 1..k read back one
// run at a time (each run draws the k farthest planes and publishes plane k alone).
TEST_F(SlicesTest, AccumulationAfterKPlanesIsTheSumOfThePlanes) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    constexpr int kPlanes = 24, kStep = 12;
    const int planesStage = 2;
    viz::Image sum;
    for (int k = 1; k <= kStep; ++k) {
        const viz::FrameOutput out = render(scene, "slices", {{"planes", kPlanes}, {"planes_drawn", k}}, 80, 60,
                                            planesStage, {"slices.plane"});
        const viz::Intermediate* plane = find(out, "slices.plane");
        ASSERT_TRUE(plane && plane->image);
        if (sum.empty()) sum = viz::Image(plane->image->width, plane->image->height, plane->image->channels);
        for (std::size_t i = 0; i < sum.pixels.size(); ++i) sum.pixels[i] += plane->image->pixels[i];
    }
    const viz::FrameOutput out = render(scene, "slices", {{"planes", kPlanes}, {"planes_drawn", kStep}}, 80, 60,
                                        planesStage, {"slices.accumulation"});
    const viz::Intermediate* accum = find(out, "slices.accumulation");
    ASSERT_TRUE(accum && accum->image);
    ASSERT_EQ(accum->image->pixels.size(), sum.pixels.size());
    const float scale = maxValue(sum);
    ASSERT_GT(scale, 0.0f) << "the first planes must add light";
    for (std::size_t i = 0; i < sum.pixels.size(); ++i)
        ASSERT_NEAR(accum->image->pixels[i], sum.pixels[i], 1e-6f * scale) << "value " << i;
    // And the accumulation grows with k: all N planes add more than the first kStep.
    const viz::FrameOutput all =
        render(scene, "slices", {{"planes", kPlanes}}, 80, 60, planesStage, {"slices.accumulation"});
    const viz::Intermediate* full = find(all, "slices.accumulation");
    ASSERT_TRUE(full && full->image);
    double a = 0.0, b = 0.0;
    for (float v : full->image->pixels) a += v;
    for (float v : sum.pixels) b += v;
    EXPECT_GT(a, b);
}

// Plane k's note counts its fragments (an occlusion query on the draw of that plane alone). The image read
// back bounds the count from below: a texel with any non-zero channel took a fragment (a fragment in shadow
// may write zero), and a plane with no fragment is black and says why. One spot light: one plane per
// pixel at most.
TEST_F(SlicesTest, ThePlanesNoteCountsItsFragmentsAndABlackPlaneSaysWhy) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    constexpr int kW = 80, kH = 60, kPlanes = 24;
    int withFragments = 0, withoutFragments = 0;
    for (int k = 1; k <= kPlanes; ++k) {
        const viz::FrameOutput out =
            render(scene, "slices", {{"planes", kPlanes}, {"planes_drawn", k}}, kW, kH, 2, {"slices.plane"});
        const viz::Intermediate* plane = find(out, "slices.plane");
        ASSERT_TRUE(plane && plane->image);
        ASSERT_TRUE(!plane->note.empty() && std::isdigit(static_cast<unsigned char>(plane->note[0]))) << plane->note;
        const long fragments = std::stol(plane->note);
        EXPECT_NE(plane->note.find(" fragments"), std::string::npos) << plane->note;
        long lit = 0;
        const viz::Image& image = *plane->image;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) {
                bool any = false;
                for (int c = 0; c < image.channels; ++c) any = any || image.at(x, y, c) != 0.0f;
                lit += any ? 1 : 0;
            }
        EXPECT_LE(lit, fragments) << "plane " << k;
        EXPECT_LE(fragments, long(kW) * kH) << "plane " << k;
        if (fragments == 0) {
            ++withoutFragments;
            EXPECT_NE(plane->note.find("beyond the first surface"), std::string::npos) << plane->note;
        } else {
            ++withFragments;
            EXPECT_EQ(plane->note.find("beyond the first surface"), std::string::npos) << plane->note;
        }
    }
    std::printf("grate, %d planes: %d with fragments, %d without\n", kPlanes, withFragments, withoutFragments);
    EXPECT_GT(withFragments, 0);
}

// slices.plane is drawn only for a caller that shows it (StageInfo::onDemand): unasked, the run publishes its
// entry without a texture and a note saying when it is drawn, and every other image is the same to the bit
// (the extra plane is drawn into its own target).
TEST_F(SlicesTest, TheLastPlaneAloneIsDrawnOnlyWhenShown) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    const viz::Settings settings = {{"planes", 24}, {"planes_drawn", 12}};
    auto technique = viz::makeTechnique("slices");
    const viz::Settings complete = viz::completeSettings(*technique, settings);
    const viz::FrameOutput unasked = viz::testing::runTechnique(*technique, scene, complete, 80, 60);
    const viz::Intermediate* plane = find(unasked, "slices.plane");
    ASSERT_TRUE(plane);
    EXPECT_EQ(plane->glTexture, 0u);
    EXPECT_FALSE(plane->image);
    EXPECT_NE(plane->note.find("drawn when this view is shown"), std::string::npos) << plane->note;
    const viz::Image unaskedAccum = viz::gl::readTexture(find(unasked, "slices.accumulation")->glTexture);
    const viz::Image unaskedAirlight = unasked.airlight;

    const viz::FrameOutput shown = viz::testing::runTechnique(*technique, scene, complete, 80, 60, -1, 0, {"slices.plane"});
    plane = find(shown, "slices.plane");
    ASSERT_TRUE(plane);
    EXPECT_NE(plane->glTexture, 0u);
    EXPECT_NE(plane->note.find(" fragments"), std::string::npos) << plane->note;
    EXPECT_EQ(viz::gl::readTexture(find(shown, "slices.accumulation")->glTexture).pixels, unaskedAccum.pixels);
    EXPECT_EQ(shown.airlight.pixels, unaskedAirlight.pixels);
    EXPECT_EQ(shown.final.pixels, unasked.final.pixels);
}

// The cookie view says whether it shows cookies or the placeholder a scene without one binds.
TEST_F(SlicesTest, TheCookieViewSaysWhenItIsThePlaceholder) {
    for (const auto& [name, hasCookie] : {std::pair<std::string, bool>{"forest", false}, {"stained-glass", true}}) {
        const viz::scene::Scene scene = viz::scene::makeBuiltinScene(name);
        bool cookie = false;
        for (const viz::scene::Light& l : scene.lights) cookie = cookie || l.cookie >= 0;
        ASSERT_EQ(cookie, hasCookie) << name;
        const viz::FrameOutput out = render(scene, "slices", {}, 32, 24, 0);
        const viz::Intermediate* view = find(out, "slices.cookie");
        ASSERT_TRUE(view) << name;
        EXPECT_EQ(view->note.find("placeholder") != std::string::npos, !hasCookie) << name << ": " << view->note;
    }
}

// A scene with no cookie and no noise compiles the plane shader without those terms; a scene with a
// cookie and noise on compiles them in.
TEST_F(SlicesTest, PermutationKeyLeavesOutUnusedTerms) {
    auto technique = viz::makeTechnique("slices");
    const viz::Settings defaults = viz::completeSettings(*technique, {});
    const auto grate = split(permutation(technique->plan(viz::scene::makeBuiltinScene("grate"), defaults)));
    EXPECT_FALSE(contains(grate, "COOKIE"));
    EXPECT_FALSE(contains(grate, "NOISE"));
    EXPECT_TRUE(contains(grate, "SPOT_FALLOFF"));
    EXPECT_TRUE(contains(grate, "SHADOW"));
    const viz::Settings noise = viz::completeSettings(*technique, {{"noise", 1}});
    const auto glass = split(permutation(technique->plan(viz::scene::makeBuiltinScene("stained-glass"), noise)));
    EXPECT_TRUE(contains(glass, "COOKIE"));
    EXPECT_TRUE(contains(glass, "NOISE"));
    // A directional-light scene has no spot falloff.
    const auto colonnade = split(permutation(technique->plan(viz::scene::makeBuiltinScene("colonnade"), defaults)));
    EXPECT_FALSE(contains(colonnade, "SPOT_FALLOFF"));
    EXPECT_FALSE(contains(colonnade, "COOKIE"));
}

TEST_F(SlicesTest, StoppingAfterEachStagePublishesOnlyWhatExists) {
    expectEachStageStopsCleanly("slices", viz::scene::makeBuiltinScene("grate"), {{"planes", 8}}, 3, 4);
}

// Point lights have no frustum: they share unclipped planes over the camera frustum, and converge to the
// reference like the spot does (grate with its spot turned into a point light at the same place).
TEST_F(SlicesTest, PointLightsUseCameraFrustumPlanesAndConverge) {
    viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    scene.lights[0].type = viz::scene::LightType::Point;
    auto technique = viz::makeTechnique("slices");
    const viz::Plan plan = technique->plan(scene, viz::completeSettings(*technique, {}));
    EXPECT_TRUE(plan.stages[2].runs);
    const viz::FrameOutput reference = render(scene, "reference", {}, 160, 120);
    std::vector<double> errors;
    for (int n : {32, 128, 512}) {
        const viz::FrameOutput out = render(scene, "slices", {{"planes", n}, {"shadow_map", 2048}}, 160, 120);
        errors.push_back(relativeL2(out.airlight, reference.airlight));
        std::printf("grate with a point light, slices planes=%3d: relative L2 = %.4f\n", n, errors.back());
    }
    for (std::size_t i = 1; i < errors.size(); ++i) EXPECT_LT(errors[i], errors[i - 1]) << "step " << i;
}

// The paper's artistic formula against its closed forms (Mitchell 2004, "Light Shaft Pixel Shader"): each
// plane in front of the surface adds compositeNoise 0.015 x scale 9 / (N / 100) x atten x colour, colour
// the light's normalised to a maximum of 1. With a sun and the shadow test off, atten = 1, so every pixel
// is k x 13.5 / N x colour for a whole number k of planes in 0..N, and the image hardly depends on N (the
// fraction of planes in front). With a point light, atten = ambient 0.35 + 20000 / |p - L|^2 in paper
// units (artistic_units per scene unit): the ambient adds exactly 0.35 x the constant-intensity image,
// and the 1/d^2 part scales as 1 / artistic_units^2.
TEST_F(SlicesTest, ArtisticWeightingFollowsThePapersFormula) {
    const int w = 64, h = 48;
    {
        const viz::scene::Scene terrain = viz::scene::makeBuiltinScene("terrain");
        const glm::dvec3 c = terrain.lights[0].colour;
        const double top = std::max({c.r, c.g, c.b});
        std::vector<double> means;
        for (int n : {50, 100, 200}) {
            const viz::FrameOutput out =
                render(terrain, "slices", {{"weighting", 0}, {"shadow", 0}, {"planes", n}}, w, h);
            double worst = 0.0, mean = 0.0;
            int kMax = 0;
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x)
                    for (int ch = 0; ch < 3; ++ch) {
                        const double k = out.airlight.at(x, y, ch) * n / (13.5 * c[ch] / top);
                        worst = std::max(worst, std::abs(k - std::round(k)));
                        kMax = std::max(kMax, int(std::lround(k)));
                        ASSERT_GE(k, -1e-3);
                        ASSERT_LE(k, n + 1e-3);
                        if (ch == 0) mean += k / n / (w * h);
                    }
            std::printf("slices artistic, terrain, N=%d: planes in front, furthest from a whole number %.2e, most "
                        "%d, mean fraction %.4f\n", n, worst, kMax, mean);
            EXPECT_LT(worst, 2e-3) << n;
            EXPECT_GT(kMax, n / 4) << n;
            means.push_back(mean);
        }
        EXPECT_NEAR(means[0], means[2], 2.0 / 50.0);
        EXPECT_NEAR(means[1], means[2], 2.0 / 100.0);
    }
    viz::scene::Scene point = viz::scene::makeBuiltinScene("grate");
    point.lights[0].type = viz::scene::LightType::Point;
    const viz::Settings base = {{"weighting", 0}, {"shadow", 0}, {"planes", 64}};
    auto with = [&](std::initializer_list<std::pair<const std::string, double>> extra) {
        viz::Settings s = base;
        for (const auto& [k, v] : extra) s[k] = v;
        return render(point, "slices", s, w, h).airlight;
    };
    const viz::Image both = with({{"falloff", 1}, {"ambient", 1}});
    const viz::Image inverseSquare = with({{"falloff", 1}, {"ambient", 0}});
    const viz::Image constant = with({{"falloff", 0}});
    const viz::Image coarserUnits = with({{"falloff", 1}, {"ambient", 0}, {"artistic_units", 200}});
    double ambientWorst = 0.0, unitsWorst = 0.0, peak = 0.0;
    for (std::size_t i = 0; i < both.pixels.size(); ++i) {
        peak = std::max(peak, double(both.pixels[i]));
        ambientWorst = std::max(ambientWorst, std::abs(double(both.pixels[i]) - inverseSquare.pixels[i] -
                                                       0.35 * constant.pixels[i]));
        unitsWorst = std::max(unitsWorst, std::abs(4.0 * coarserUnits.pixels[i] - inverseSquare.pixels[i]));
    }
    std::printf("slices artistic, point-light grate: |both - 1/d^2 - 0.35 constant| %.2e, |4 x (units 200) - "
                "(units 100)| %.2e, of a peak %.3g\n", ambientWorst, unitsWorst, peak);
    ASSERT_GT(maxValue(constant), 0.0f);
    EXPECT_LT(ambientWorst, 1e-5 * peak);
    EXPECT_LT(unitsWorst, 1e-5 * peak);
}

// Artistic weighting (the paper's constants), noise, cookie, PCF and blur all produce finite light.
TEST_F(SlicesTest, ArtisticWeightingAndOptionalTermsGiveFiniteLight) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("stained-glass");
    for (const viz::Settings& s : std::vector<viz::Settings>{{{"weighting", 0}},
                                                             {{"noise", 1}, {"time", 3}},
                                                             {{"shadow", 2}, {"blur", 1}},
                                                             {{"accum", 1}, {"blur", 1}}}) {
        viz::Settings all = s;
        all["planes"] = 32;
        const viz::FrameOutput out = render(scene, "slices", all, 64, 48);
        EXPECT_GT(maxValue(out.airlight), 0.0f);
        for (float v : out.airlight.pixels) ASSERT_TRUE(std::isfinite(v));
    }
}

// The planes' box bounds the frustum: every NDC corner maps inside [minXY, maxXY] x [near, far].
TEST(SliceGeometry, BoxContainsTheFrustumCorners) {
    const glm::dmat4 proj = glm::perspective(1.0, 1.0, 0.5, 10.0);
    const glm::dmat4 view = glm::lookAt(glm::dvec3(0, 5, -3), glm::dvec3(0, 0, -3), glm::dvec3(0, 0, -1));
    const glm::dmat4 m = proj * view;
    const viz::CameraBasis basis{{0, 0, -1}, {1, 0, 0}, {0, 1, 0}};
    const viz::PlaneRange r = viz::planeRange(m, basis, 0.05, 100.0, 10);
    ASSERT_FALSE(r.empty);
    EXPECT_NEAR(r.spacing * 10.0, r.far - r.near, 1e-12);
    const glm::dmat4 inv = glm::inverse(m);
    for (int c = 0; c < 8; ++c) {
        glm::dvec4 p = inv * glm::dvec4(c & 1 ? 1 : -1, c & 2 ? 1 : -1, c & 4 ? 1 : -1, 1);
        p /= p.w;
        EXPECT_GE(p.x, r.minXY.x - 1e-9);
        EXPECT_LE(p.x, r.maxXY.x + 1e-9);
        EXPECT_GE(p.y, r.minXY.y - 1e-9);
        EXPECT_LE(p.y, r.maxXY.y + 1e-9);
        // Depth is cut to the camera's [znear, zfar]: the box covers the clamped corner depths.
        const double depth = std::clamp(-p.z, 0.05, 100.0);
        EXPECT_GE(depth, r.near - 1e-9);
        EXPECT_LE(depth, r.far + 1e-9);
    }
}

// Clipped plane polygons stay inside the frustum; unclipped ones reach outside it.
TEST(SliceGeometry, ClippedPolygonsLieInsideTheFrustum) {
    const glm::dmat4 m = glm::perspective(0.9, 1.0, 0.1, 12.0) *
                         glm::lookAt(glm::dvec3(0, 5, -4), glm::dvec3(0, 0, -4), glm::dvec3(0, 0, -1));
    const viz::CameraBasis basis{{0, 0, -1}, {1, 0, 0}, {0, 1, 0}};
    const viz::PlaneRange r = viz::planeRange(m, basis, 0.05, 100.0, 16);
    const auto planes = viz::frustumPlanes(m);
    bool anyOutside = false;
    for (bool clip : {true, false}) {
        const auto polys = viz::planePolygons(r, basis, m, 16, clip);
        ASSERT_EQ(polys.size(), 16u);
        for (const auto& poly : polys)
            for (const glm::dvec3& p : poly)
                for (const glm::dvec4& pl : planes) {
                    const double side = glm::dot(glm::dvec3(pl), p) + pl.w;
                    if (clip) EXPECT_GE(side, -1e-9 * glm::length(glm::dvec3(pl)) * (1.0 + glm::length(p)));
                    else anyOutside = anyOutside || side < 0.0;
                }
    }
    EXPECT_TRUE(anyOutside);
}

TEST(SliceGeometry, DistanceScaledPlaneCount) {
    EXPECT_EQ(viz::scaledPlaneCount(128, 5.0, 0.0, 8), 128);    // off
    EXPECT_EQ(viz::scaledPlaneCount(128, 5.0, 10.0, 8), 128);   // nearer than the reference distance
    EXPECT_EQ(viz::scaledPlaneCount(128, 20.0, 10.0, 8), 64);   // twice as far: half the planes
    EXPECT_EQ(viz::scaledPlaneCount(128, 1e6, 10.0, 8), 8);     // floor
    EXPECT_EQ(viz::scaledPlaneCount(4, 1e6, 10.0, 8), 4);       // never more than N
}

// Distance-scaled plane count: fewer planes, and the spacing-based weight keeps L_air of the same size.
TEST_F(SlicesTest, DistanceScaledPlanesKeepTheLightLevel) {
    // The camera pulled 12 m back: the light's box starts ~12 m away, so distance_scale = 3 gives ~N / 4.
    viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    scene.camera.position -= 12.0 * scene.camera.forward;
    const viz::FrameOutput full = render(scene, "slices", {{"planes", 256}}, 80, 60);
    const viz::FrameOutput fewer = render(scene, "slices", {{"planes", 256}, {"distance_scale", 3}}, 80, 60);
    const viz::Intermediate* mesh = find(fewer, "slices.plane_mesh");
    ASSERT_TRUE(mesh && mesh->image);
    // The eye is about 12 units from the light's box: 256 x 3 / 12 = 64 planes (the scene's geometry,
    // not the code's formula), give or take the box's exact distance.
    EXPECT_GE(mesh->image->height, 48);
    EXPECT_LE(mesh->image->height, 85);
    double a = 0.0, b = 0.0;
    for (float v : full.airlight.pixels) a += v;
    for (float v : fewer.airlight.pixels) b += v;
    std::printf("distance_scale=3: %d planes, total L_air %.4g vs %.4g with 256\n", mesh->image->height, b, a);
    EXPECT_NEAR(b / a, 1.0, 0.1);
}

// Benchmark (never gates): time per frame and error against the reference for N = 16 .. 512 on grate
// and colonnade, float accumulation, physical weighting. Run with --gtest_also_run_disabled_tests
// --gtest_filter='*Benchmark*' in a RelWithDebInfo build.
// depth_test=1 (the default): the planes are tested against the surface's depth before they are shaded,
// placed where each plane's part of the ray begins. The test may reject only fragments the shader itself
// drops as beyond the first surface: every built-in scene, with the slab integral and with one sample per
// plane, renders to the bit as with depth_test=0, where the shader decides alone. And it does reject them:
// on colonnade (walls and a floor in the view) the counted fragments fall, the shadow lookups of the
// fragments that add light do not.
TEST_F(SlicesTest, TheDepthTestRejectsOnlyFragmentsBehindTheFirstSurface) {
    // With the stiff case of a ground quad 1e6 across, whose rasterised depth lies per cents off its
    // distance (a test against the scene's own depth buffer darkened the floor by up to 13 %).
    std::vector<std::string> names = viz::scene::builtinSceneNames();
    names.push_back("depth-range-1e6");
    for (const std::string& name : names)
        for (const double integration : {0.0, 1.0}) {
            const viz::scene::StiffCase* stiff = viz::scene::findStiffCase(name);
            const viz::scene::Scene scene = stiff ? viz::scene::buildStiffScene(*stiff) : viz::scene::makeBuiltinScene(name);
            const viz::Settings base{{"planes", 24}, {"integration", integration}, {"area_samples", 2}};
            viz::Settings off = base, on = base;
            off["depth_test"] = 0;
            on["depth_test"] = 1;
            const viz::FrameOutput a = render(scene, "slices", off, 48, 36);
            const viz::FrameOutput b = render(scene, "slices", on, 48, 36);
            ASSERT_FALSE(a.airlight.empty()) << name;
            EXPECT_EQ(a.airlight.pixels, b.airlight.pixels) << name << " integration " << integration;
            EXPECT_EQ(a.final.pixels, b.final.pixels) << name << " integration " << integration;
        }
    const viz::scene::Scene colonnade = viz::scene::makeBuiltinScene("colonnade");
    viz::gl::WorkCounters::setEnabled(true);
    const viz::FrameOutput off = render(colonnade, "slices", {{"planes", 32}, {"depth_test", 0}}, 64, 48);
    const viz::FrameOutput on = render(colonnade, "slices", {{"planes", 32}, {"depth_test", 1}}, 64, 48);
    viz::gl::WorkCounters::setEnabled(false);
    auto planes = [](const viz::FrameOutput& out) {
        for (const viz::StageTiming& s : out.timing.stages)
            if (s.stage == "slices.planes") return s.work;
        return std::vector<std::uint64_t>{};
    };
    ASSERT_EQ(planes(off).size(), std::size_t(viz::gl::kWorkCounts));
    ASSERT_EQ(planes(on).size(), std::size_t(viz::gl::kWorkCounts));
    const std::uint64_t shadedOff = planes(off)[viz::render::hd::kWorkFragments];
    const std::uint64_t shadedOn = planes(on)[viz::render::hd::kWorkFragments];
    std::printf("colonnade, 32 planes, 64x48: %llu fragments shaded without the depth test, %llu with it\n",
                (unsigned long long)shadedOff, (unsigned long long)shadedOn);
    EXPECT_LT(2 * shadedOn, shadedOff) << "most of colonnade's plane fragments lie behind its walls and floor";
    EXPECT_EQ(planes(on)[viz::render::hd::kWorkShadowLookups], planes(off)[viz::render::hd::kWorkShadowLookups]);
}

TEST_F(SlicesTest, DISABLED_Benchmark) {
    for (const char* name : {"grate", "colonnade"}) {
        const viz::scene::Scene scene = viz::scene::makeBuiltinScene(name);
        const viz::FrameOutput reference = render(scene, "reference", {}, 160, 120);
        // What the shared shadow maps allow: raymarch with many samples at the same map size.
        const viz::FrameOutput march = render(scene, "raymarch", {{"samples", 1024}, {"shadow_map", 2048}}, 160, 120);
        std::printf("bench %-9s raymarch samples=1024 relative L2 %.4f\n", name,
                    relativeL2(march.airlight, reference.airlight));
        for (int n : {16, 32, 64, 128, 256, 512}) {
            // One technique per N: the first run compiles shaders and allocates; the best of 3 later runs counts.
            auto t = viz::makeTechnique("slices");
            viz::FrameInput in;
            in.scene = &scene;
            in.width = 160;
            in.height = 120;
            viz::setRunSettings(in, viz::completeSettings(*t, {{"planes", n}, {"shadow_map", 2048}}));
            t->run(in);
            double best = 1e30, planes = 1e30, err = 0.0;
            for (int rep = 0; rep < 3; ++rep) {
                const viz::FrameOutput out = t->run(in);
                best = std::min(best, out.timing.totalMilliseconds());
                for (const auto& st : out.timing.stages)
                    if (st.stage == "slices.planes") planes = std::min(planes, st.milliseconds);
                err = relativeL2(out.airlight, reference.airlight);
            }
            std::printf("bench %-9s planes=%3d total %7.1f ms  planes stage %7.1f ms  relative L2 %.4f\n", name, n,
                        best, planes, err);
        }
    }
}

