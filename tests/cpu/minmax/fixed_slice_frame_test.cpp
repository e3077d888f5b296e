// minmax's slice_frame=fixed (epipolar_setup.h, SetupInput::fixedFrame): while the eye-light axis stays
// put (the camera turning in place), every slice's half-plane is one of a fixed set in the world, the
// multiples of 2 pi / 2^m about the axis measured from the world frame makeFrame builds; and every ray is
// still within half a pixel of a slice. The paper's grid (slice_frame=screen) is shown to move.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "render/host_device.h"
#include "scene/camera.h"
#include "techniques/minmax/epipolar.h"
#include "techniques/minmax/epipolar_setup.h"

namespace {

// The eye at the origin, turned by `yaw` about +Y from looking down -z, 0.9 rad vertical field of view.
viz::scene::Camera turnedCamera(double yaw) {
    viz::scene::Camera cam;
    cam.position = glm::dvec3(0.0);
    cam.forward = glm::dvec3(-std::sin(yaw), 0.0, -std::cos(yaw));
    cam.up = glm::dvec3(0.0, 1.0, 0.0);
    cam.yfov = 0.9;
    return cam;
}

viz::render::GpuLightCpu spotAt(glm::vec3 position) {
    viz::render::GpuLightCpu L{};
    L.info = glm::ivec4(viz::render::hd::kLightSpot, -1, 0, 0);
    L.position = glm::vec4(position, 1.0f);
    L.direction = glm::vec4(glm::normalize(-position), 0.0f);
    L.spot = glm::vec4(1.0f, 0.0f, 1.0f, 0.5f);
    return L;
}

// Each slice's world direction e(alpha_row) as an angle about the axis in the world frame (makeFrame's u,
// v), in units of `spacing`: whole numbers when the slices sit on the fixed grid.
std::vector<double> sliceAnglesInSpacings(const viz::minmax::Setup& s, const viz::render::GpuLightCpu& L,
                                          double spacing) {
    const auto world = viz::minmax::makeFrame<double>(viz::minmax::LightKind::Spot, glm::dvec3(L.position),
                                                      glm::dvec3(L.direction));
    std::vector<double> out;
    for (int row = 0; row < s.frame.slices; ++row) {
        const glm::dvec3 e = viz::minmax::slicePerpendicular(s.frame, s.frame.sliceAlpha(row));
        out.push_back(std::atan2(glm::dot(e, world.v), glm::dot(e, world.u)) / spacing);
    }
    return out;
}

double worstOffGrid(const std::vector<double>& x) {
    double worst = 0.0;
    for (double v : x) worst = std::max(worst, std::abs(v - std::round(v)));
    return worst;
}

TEST(MinmaxFixedSliceFrame, SlicesStayOnAWorldGridWhileTheCameraTurns) {
    const int w = 64, h = 48;
    // Epipole off screen (light to the side), on screen (ahead), behind the camera.
    for (glm::vec3 light : {glm::vec3(9.0f, 2.0f, -3.0f), glm::vec3(0.5f, 0.3f, -6.0f), glm::vec3(0.4f, 1.0f, 5.0f)}) {
        const auto L = spotAt(light);
        SCOPED_TRACE(light.x);
        double spacing = 0.0;
        double screenWorst = 0.0;
        for (double yaw : {0.0, 0.01, 0.03, 0.07}) {
            const viz::scene::Camera cam = turnedCamera(yaw);
            const auto fixed = viz::minmax::setupLight(
                {.light = &L, .camera = &cam, .width = w, .height = h, .columns = 256, .oversampling = 2, .fixedFrame = true});
            // A power-of-two division of the circle, no coarser than the screen needs (half a pixel / 2).
            const double divisions = 2.0 * std::numbers::pi / fixed.frame.alphaSpacing;
            EXPECT_NEAR(divisions, std::exp2(std::round(std::log2(divisions))), 1e-6) << yaw;
            EXPECT_LE(fixed.maxSliceGap, 0.5 + 1e-9) << yaw;
            if (yaw == 0.0) spacing = fixed.frame.alphaSpacing;
            ASSERT_EQ(fixed.frame.alphaSpacing, spacing) << "the spacing changed at yaw " << yaw;
            EXPECT_LT(worstOffGrid(sliceAnglesInSpacings(fixed, L, spacing)), 1e-6) << yaw;
            // The paper's grid on the same views, measured the same way.
            const auto screen = viz::minmax::setupLight(
                {.light = &L, .camera = &cam, .width = w, .height = h, .columns = 256, .oversampling = 2});
            screenWorst = std::max(screenWorst, worstOffGrid(sliceAnglesInSpacings(screen, L, screen.frame.alphaSpacing)));
        }
        EXPECT_GT(screenWorst, 0.05) << "the paper's slices did not move: the test cannot tell the two apart";
    }
}

// Every pixel's ray within half a pixel of its slice (slice_oversampling 1), as for the paper's grid
// (epipolar_test.cpp), measured per pixel from its neighbours' alpha.
TEST(MinmaxFixedSliceFrame, KeepsEveryRayWithinHalfAPixel) {
    const int w = 64, h = 48;
    const viz::scene::Camera cam = turnedCamera(0.2);
    for (glm::vec3 light : {glm::vec3(0.5f, 0.3f, -6.0f), glm::vec3(9.0f, 2.0f, -3.0f), glm::vec3(0.4f, 1.0f, 5.0f)}) {
        const auto L = spotAt(light);
        const auto s = viz::minmax::setupLight(
            {.light = &L, .camera = &cam, .width = w, .height = h, .columns = 256, .fixedFrame = true});
        const auto& f = s.frame;
        for (int y = 1; y < h; ++y)
            for (int x = 1; x < w; ++x) {
                const double a = viz::minmax::alphaOf(f, viz::scene::pixelRay(cam, w, h, x, y));
                const double ax = viz::minmax::alphaOf(f, viz::scene::pixelRay(cam, w, h, x - 1, y));
                const double ay = viz::minmax::alphaOf(f, viz::scene::pixelRay(cam, w, h, x, y - 1));
                const double gx = viz::minmax::alphaStep(a, ax), gy = viz::minmax::alphaStep(a, ay);
                const double off = viz::minmax::alphaStep(a, f.sliceAlpha(viz::minmax::sliceRow(f, a)));
                EXPECT_LE(off / std::sqrt(gx * gx + gy * gy), 0.5 + 1e-6) << x << "," << y << " light " << light.x;
            }
    }
}

}  // namespace
