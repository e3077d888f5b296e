// slices with integration=equiangular: each plane integrates its slab along the ray with nodes equally
// spaced in the angle seen from the light. Checked against the reference (error and convergence), against
// the unclipped planes (the widened clip keeps every fragment that adds light), and the widened plane
// polygons against points sampled inside the light's frustum.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "technique_test_util.h"
#include "scene/builtin_scenes.h"
#include "scene/stiff_scenes.h"
#include "techniques/slices/slice_geometry.h"

namespace {

using viz::testing::relativeL2;

class SlicesEquiangularTest : public viz::testing::TechniqueTest {
protected:
    // Relative L2 against the reference of slices with integration=equiangular at each plane count
    // (160x120), printed under `label`.
    std::vector<double> equiangularErrors(const viz::scene::Scene& scene, const viz::FrameOutput& reference,
                                          std::initializer_list<int> counts, const char* label) {
        std::vector<double> errors;
        for (int n : counts) {
            const viz::FrameOutput out = render(scene, "slices", {{"planes", n}, {"integration", 1}}, 160, 120);
            errors.push_back(relativeL2(out.airlight, reference.airlight));
            std::printf("%s, equiangular planes=%3d: relative L2 %.4f\n", label, n, errors.back());
        }
        return errors;
    }
};

void expectFalling(const std::vector<double>& errors) {
    for (std::size_t i = 1; i < errors.size(); ++i) EXPECT_LT(errors[i], errors[i - 1]) << "step " << i;
}

// Whether p (on the plane of `poly`, a convex polygon) lies inside it, with a tolerance relative to size.
bool insideConvex(const std::vector<glm::dvec3>& poly, const glm::dvec3& p, const glm::dvec3& normal) {
    if (poly.size() < 3) return false;
    double sign = 0.0;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const glm::dvec3& a = poly[i];
        const glm::dvec3& b = poly[(i + 1) % poly.size()];
        const double side = glm::dot(glm::cross(b - a, p - a), normal);
        const double tolerance = 1e-9 * glm::length(b - a) * (1.0 + glm::length(p - a));
        if (std::abs(side) <= tolerance) continue;
        if (sign == 0.0) sign = side;
        else if ((side > 0.0) != (sign > 0.0)) return false;
    }
    return true;
}

}  // namespace

// On grate the spot shines down from the top of the image: rays next to it cross its cone near the apex,
// in a stretch much shorter than the plane spacing, where 1/r^2 is large. One sample per plane misses or
// overweights that stretch (the midpoint rule's error there is most of its error on grate); the slab
// integral with nodes by angle does not. Against the reference at 160x120: with 16 planes the error is
// below 5 % and below the midpoint rule's with 8 times as many planes, and it falls with N.
TEST_F(SlicesEquiangularTest, FewPlanesMatchTheReferenceOnGrate) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    const viz::FrameOutput reference = render(scene, "reference", {}, 160, 120);
    ASSERT_FALSE(reference.airlight.empty());
    const viz::FrameOutput midpoint = render(scene, "slices", {{"planes", 128}, {"integration", 0}}, 160, 120);
    const double midpointError = relativeL2(midpoint.airlight, reference.airlight);
    const std::vector<double> errors = equiangularErrors(scene, reference, {16, 128, 512}, "grate");
    std::printf("grate, midpoint planes=128: relative L2 %.4f\n", midpointError);
    EXPECT_LT(errors[0], 0.05);
    EXPECT_LT(errors[0], midpointError);
    expectFalling(errors);
}

// In a spot's penumbra, between its outer and inner cone, A_spot^2 rises from 0 to 1 over the penumbra's
// angle (0.15 rad on grate). Nodes only slab_angle = 0.1 rad apart sampled it once or twice per slab, often
// outside the cone: 8 planes read 0.0208 against the reference (160x120), most of it at the cone's edge.
// With at most an eighth of the penumbra's angle a node wherever a slab's part is not wholly inside the
// inner cone: 0.0079.
TEST_F(SlicesEquiangularTest, ThePenumbraIsSampledFinely) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    const viz::FrameOutput reference = render(scene, "reference", {}, 160, 120);
    const std::vector<double> errors = equiangularErrors(scene, reference, {8}, "grate");
    EXPECT_LT(errors[0], 0.0125);
}

// The same with the spot made a point light (the unbounded planes over the camera frustum, no cone): the
// slab integral converges too, and with 32 planes it is closer to the reference than the midpoint rule.
TEST_F(SlicesEquiangularTest, APointLightConvergesToo) {
    viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    scene.lights[0].type = viz::scene::LightType::Point;
    const viz::FrameOutput reference = render(scene, "reference", {}, 160, 120);
    const double midpoint =
        relativeL2(render(scene, "slices", {{"planes", 32}, {"integration", 0}}, 160, 120).airlight, reference.airlight);
    const std::vector<double> errors = equiangularErrors(scene, reference, {32, 128, 512}, "grate with a point light");
    std::printf("grate with a point light, midpoint planes= 32: relative L2 %.4f\n", midpoint);
    EXPECT_LT(errors[0], midpoint);
    expectFalling(errors);
}

// Clipping only saves work: a fragment the widened clip planes remove must add nothing. With clip=0 every
// plane covers the whole (widened) box and plane.frag cuts each ray to the cone itself, so the two
// images are the same to the bit. Before the widening, a slab whose plane point lay outside the cone while
// the slab crossed it was clipped away (grate's top rows got no plane at all).
TEST_F(SlicesEquiangularTest, TheWidenedClipKeepsEveryFragmentThatAddsLight) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    for (int n : {16, 64}) {
        const viz::FrameOutput clipped = render(scene, "slices", {{"planes", n}, {"integration", 1}}, 160, 120);
        const viz::FrameOutput whole =
            render(scene, "slices", {{"planes", n}, {"integration", 1}, {"clip", 0}}, 160, 120);
        ASSERT_EQ(clipped.airlight.pixels.size(), whole.airlight.pixels.size());
        EXPECT_EQ(clipped.airlight.pixels, whole.airlight.pixels) << "planes=" << n;
    }
}

// The widened polygons as the mesh view draws them: every point of the light's frustum, followed along its
// eye ray to the plane of its slab, lands inside that plane's widened polygon (points sampled uniformly in
// the frustum's clip cube, 20,000 of them). The plain polygons miss some (the reason for the widening).
TEST(SliceGeometry, WidenedPolygonsHoldEveryFrustumPointOfTheirSlab) {
    const glm::dmat4 m = glm::perspective(0.9, 1.0, 0.1, 12.0) *
                         glm::lookAt(glm::dvec3(1, 5, -4), glm::dvec3(0, 0, -5), glm::dvec3(0, 0, -1));
    const viz::CameraBasis basis{{0, 0, -1}, {1, 0, 0}, {0, 1, 0}};
    const int planes = 16;
    const viz::PlaneRange r = viz::planeRange(m, basis, 0.05, 100.0, planes);
    ASSERT_FALSE(r.empty);
    const auto widened = viz::planePolygons(r, basis, m, planes, true, true);
    const auto plain = viz::planePolygons(r, basis, m, planes, true, false);
    const glm::dmat4 inverse = glm::inverse(m);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int tested = 0, missedPlain = 0;
    for (int k = 0; k < 20000; ++k) {
        glm::dvec4 q = inverse * glm::dvec4(u(rng), u(rng), u(rng), 1.0);
        const glm::dvec3 p = glm::dvec3(q) / q.w;
        const double depth = glm::dot(p, basis.forward);
        const int slab = int(std::floor((r.far - depth) / r.spacing));
        if (slab < 0 || slab >= planes) continue;  // outside the slabs' depth range (behind the eye, past far)
        const double s = std::max(r.far - (double(slab) + 0.5) * r.spacing, r.drawNear);
        const glm::dvec3 onPlane = p * (s / depth);
        ++tested;
        EXPECT_TRUE(insideConvex(widened[std::size_t(slab)], onPlane, basis.forward))
            << "point " << k << " of slab " << slab;
        if (!insideConvex(plain[std::size_t(slab)], onPlane, basis.forward)) ++missedPlain;
    }
    EXPECT_GT(tested, 10000);
    EXPECT_GT(missedPlain, 0);
}

// With the camera inside the spot's cone the nearest slab reaches the eye, and the widened box would grow
// without bound (s / s_lo); cut to the view, its plane is drawn. Before the cut llvmpipe dropped that
// quad (a thousand times the screen) and the image lost the slab nearest the eye: at N = 512 the error
// against the reference was 0.025, twice the midpoint rule's 0.012. Now the two agree within 10 %.
TEST_F(SlicesEquiangularTest, TheSlabAtTheEyeIsDrawnWhenTheCameraIsInTheLitVolume) {
    const viz::scene::StiffCase* c = viz::scene::findStiffCase("camera-in-lit-volume");
    ASSERT_NE(c, nullptr);
    const viz::scene::Scene scene = viz::scene::buildStiffScene(*c);
    const viz::FrameOutput reference = render(scene, "reference", {}, 80, 60);
    const double midpoint =
        relativeL2(render(scene, "slices", {{"planes", 512}, {"integration", 0}}, 80, 60).airlight, reference.airlight);
    const double equiangular =
        relativeL2(render(scene, "slices", {{"planes", 512}, {"integration", 1}}, 80, 60).airlight, reference.airlight);
    std::printf("camera-in-lit-volume, 512 planes: midpoint %.4f, equiangular %.4f\n", midpoint, equiangular);
    EXPECT_LT(equiangular, 1.1 * midpoint);
}

// Under a cookie the nodes follow its texels: on stained-glass the spot projects a coloured window, and
// a ray passing the apex crosses all of it within a few degrees. With nodes only slab_angle apart the
// error stayed at 0.11 at 32 planes and 0.098 at 128 (the midpoint rule: 0.95 and 3.2); one node per
// cookie texel brings 32 planes below 1 %.
TEST_F(SlicesEquiangularTest, NodesFollowTheCookiesTexelsOnStainedGlass) {
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("stained-glass");
    const viz::FrameOutput reference = render(scene, "reference", {}, 160, 120);
    const double error =
        relativeL2(render(scene, "slices", {{"planes", 32}, {"integration", 1}}, 160, 120).airlight, reference.airlight);
    std::printf("stained-glass, equiangular planes=32: relative L2 %.4f\n", error);
    EXPECT_LT(error, 0.01);
}

// integration=auto, the default: the slab integral where a light has a position (a spot or point light) and
// for suns alone, the midpoint rule where an area light's VPLs are the only such lights; the plan says
// which and why. Each choice draws exactly the image of the setting it stands for. On terrain (a sun) the
// slab integral, one node cut at the surface, is no less accurate than one sample at the plane.
TEST_F(SlicesEquiangularTest, AutoChoosesTheSlabIntegralExceptForVplsAlone) {
    viz::scene::Scene tvWithPoint = viz::scene::makeBuiltinScene("tv-room");
    viz::scene::Light point = tvWithPoint.lights.front();
    point.type = viz::scene::LightType::Point;
    point.intensity *= 0.1;
    tvWithPoint.lights.push_back(point);
    const std::vector<std::pair<std::string, viz::scene::Scene>> scenes = {
        {"grate", viz::scene::makeBuiltinScene("grate")},
        {"terrain", viz::scene::makeBuiltinScene("terrain")},
        {"tv-room", viz::scene::makeBuiltinScene("tv-room")},
        {"tv-room with a point light", tvWithPoint}};
    const auto slices = viz::makeTechnique("slices");
    for (const auto& [name, scene] : scenes) {
        SCOPED_TRACE(name);
        const bool vplsAlone = name == "tv-room";
        ASSERT_EQ(vplsAlone, scene.lights.size() == 1 && scene.lights[0].type == viz::scene::LightType::Area);
        const viz::Plan plan = slices->plan(scene, viz::completeSettings(*slices, {}));
        const viz::FeaturePlan* feature = viz::findFeature(plan, "SLAB_EQUIANGULAR");
        ASSERT_NE(feature, nullptr);
        EXPECT_EQ(feature->enabled, !vplsAlone);
        EXPECT_EQ(feature->why.rfind("integration=auto", 0), 0u) << feature->why;
        const viz::FrameOutput automatic = render(scene, "slices", {{"planes", 16}}, 80, 60);
        const viz::FrameOutput chosen = render(scene, "slices", {{"planes", 16}, {"integration", vplsAlone ? 0 : 1}}, 80, 60);
        EXPECT_EQ(automatic.airlight.pixels, chosen.airlight.pixels);
    }
    const viz::scene::Scene& terrain = scenes[1].second;
    const viz::FrameOutput reference = render(terrain, "reference", {}, 160, 120);
    const double slab = relativeL2(render(terrain, "slices", {{"planes", 128}}, 160, 120).airlight, reference.airlight);
    const double midpoint =
        relativeL2(render(terrain, "slices", {{"planes", 128}, {"integration", 0}}, 160, 120).airlight, reference.airlight);
    std::printf("terrain, 128 planes: auto (one node a slab) %.4f, midpoint %.4f\n", slab, midpoint);
    EXPECT_LE(slab, midpoint);
}
