// Epipolar coordinates (minmax/epipolar.h) and the per-light setup (epipolar_setup.h) on the CPU.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "render/host_device.h"
#include "scene/camera.h"
#include "techniques/minmax/epipolar.h"
#include "techniques/minmax/epipolar_setup.h"

namespace {

using viz::minmax::EpipolarFrame;
using viz::minmax::LightKind;

glm::dvec3 randomUnit(std::mt19937& rng) {
    std::normal_distribution<double> n;
    return glm::normalize(glm::dvec3(n(rng), n(rng), n(rng)));
}

// A world point goes to (alpha, beta, gamma) and back to itself, for spot, point and directional lights in every
// direction (the light behind the camera included: the frame does not depend on the camera).
TEST(MinmaxEpipolar, RoundTripOfRandomPoints) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-10.0, 10.0);
    for (LightKind kind : {LightKind::Spot, LightKind::Directional, LightKind::Point}) {
        for (int light = 0; light < 20; ++light) {
            const glm::dvec3 position = 8.0 * randomUnit(rng);
            const auto f = viz::minmax::makeFrame<double>(kind, position, randomUnit(rng));
            for (int i = 0; i < 200; ++i) {
                const glm::dvec3 p(u(rng), u(rng), u(rng));
                const double alpha = viz::minmax::alphaOf(f, p), beta = viz::minmax::betaOf(f, p);
                const double gamma = viz::minmax::gammaOf(f, p);
                const glm::dvec3 back = viz::minmax::pointOf(f, alpha, beta, gamma);
                EXPECT_LT(glm::length(back - p), 1e-9 * (1.0 + glm::length(p))) << "kind " << int(kind);
                // The same gamma along the camera ray at the point's distance.
                EXPECT_NEAR(viz::minmax::gammaAlongRay(f, beta, glm::length(p)), gamma, 1e-9 * (1.0 + gamma));
            }
        }
    }
}

// On a light ray, beta grows with the distance travelled: a point is closer to the light than the
// occluder (lit) exactly when its beta is below the occluder's beta, the rule S > beta of the tree.
TEST(MinmaxEpipolar, OccluderBetaSeparatesLitFromShadowed) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (LightKind kind : {LightKind::Spot, LightKind::Directional, LightKind::Point}) {
        const auto f = viz::minmax::makeFrame<double>(kind, glm::dvec3(1.0, 6.0, -2.0), glm::dvec3(0.3, -1.0, 0.2));
        for (int i = 0; i < 2000; ++i) {
            const double alpha = 2.0 * std::numbers::pi * unit(rng) - std::numbers::pi;
            const bool fromLight = kind != LightKind::Directional;
            const double gamma = fromLight ? 0.05 + 3.0 * unit(rng) : 20.0 * unit(rng);
            // Occluder and a test point on the light ray: spot, distances from the light; directional, depths
            // along the travel direction (-a) of the points gamma e + z a.
            const double occluder = fromLight ? 30.0 * unit(rng) : 40.0 * unit(rng) - 20.0;
            const double point = fromLight ? 30.0 * unit(rng) : 40.0 * unit(rng) - 20.0;
            const glm::dvec3 e = viz::minmax::slicePerpendicular(f, alpha);
            const glm::dvec3 p = fromLight
                                     ? f.lightDistance * f.axis + point * (-std::cos(gamma) * f.axis + std::sin(gamma) * e)
                                     : gamma * e - point * f.axis;
            const bool lit = point <= occluder;
            const double beta = viz::minmax::betaOf(f, p);
            const double S = viz::minmax::occluderBeta(f, gamma, occluder);
            if (std::abs(point - occluder) < 1e-9) continue;
            EXPECT_EQ(beta < S, lit) << "kind " << int(kind) << " gamma " << gamma;
            EXPECT_NEAR(viz::minmax::gammaOf(f, p), gamma, 1e-9 * (1.0 + gamma));
            EXPECT_NEAR(std::remainder(viz::minmax::alphaOf(f, p) - alpha, 2.0 * std::numbers::pi), 0.0, 1e-9);
        }
    }
}

// distanceAtGamma inverts gammaAlongRay over the ray's reach.
TEST(MinmaxEpipolar, DistanceAtGammaInvertsGammaAlongRay) {
    for (LightKind kind : {LightKind::Spot, LightKind::Directional, LightKind::Point}) {
        const auto f = viz::minmax::makeFrame<double>(kind, glm::dvec3(0.0, 5.0, 1.0), glm::dvec3(0.0, -1.0, 0.0));
        for (double beta : {0.01, 0.3, 1.0, 2.0, 3.1}) {
            for (double t : {0.01, 0.5, 3.0, 40.0}) {
                const double g = viz::minmax::gammaAlongRay(f, beta, t);
                EXPECT_NEAR(viz::minmax::distanceAtGamma(f, beta, g), t, 1e-9 * t) << beta;
            }
        }
    }
}

// The eye at the origin looking down -z, 0.9 rad vertical field of view.
viz::scene::Camera testCamera() {
    viz::scene::Camera cam;
    cam.position = glm::dvec3(0.0);
    cam.forward = glm::dvec3(0.0, 0.0, -1.0);
    cam.up = glm::dvec3(0.0, 1.0, 0.0);
    cam.yfov = 0.9;
    return cam;
}

// The automatic slice count puts every pixel's ray within half a pixel of its slice: the pixel's alpha
// differs from its row's alpha by at most half the pixel's own alpha step, for the epipole on screen, off
// screen and behind the camera.
TEST(MinmaxEpipolar, AutomaticSlicesKeepEveryRayWithinHalfAPixel) {
    const viz::scene::Camera cam = testCamera();
    const int w = 64, h = 48;
    for (glm::vec3 light : {glm::vec3(0.5f, 0.3f, -6.0f), glm::vec3(9.0f, 2.0f, -3.0f), glm::vec3(0.4f, 1.0f, 5.0f)}) {
        viz::render::GpuLightCpu L{};
        L.info = glm::ivec4(viz::render::hd::kLightSpot, -1, 0, 0);
        L.position = glm::vec4(light, 1.0f);
        L.direction = glm::vec4(glm::normalize(-light), 0.0f);
        L.spot = glm::vec4(1.0f, 0.0f, 1.0f, 0.5f);
        const auto s = viz::minmax::setupLight({.light = &L, .camera = &cam, .width = w, .height = h, .slices = 0,
                                                .columns = 256});
        const auto& f = s.frame;
        EXPECT_LE(s.maxSliceGap, 1.0 + 1e-9);
        for (int y = 1; y < h; ++y) {
            for (int x = 1; x < w; ++x) {
                const double a = viz::minmax::alphaOf(f, viz::scene::pixelRay(cam, w, h, x, y));
                const double ax = viz::minmax::alphaOf(f, viz::scene::pixelRay(cam, w, h, x - 1, y));
                const double ay = viz::minmax::alphaOf(f, viz::scene::pixelRay(cam, w, h, x, y - 1));
                const double gx = viz::minmax::alphaStep(a, ax), gy = viz::minmax::alphaStep(a, ay);
                const double perPixel = std::sqrt(gx * gx + gy * gy);
                const int row = viz::minmax::sliceRow(f, a);
                const double off = viz::minmax::alphaStep(a, f.sliceAlpha(row));
                EXPECT_LE(off / perPixel, 0.5 + 1e-6) << "pixel " << x << "," << y << " light " << light.x;
            }
        }
    }
}

// Point lights: random world points in front of the camera map to (alpha, beta, gamma) and back, the
// point's slice row and column (in a row range covering its gamma) map back to within one slice and one
// column of it, and the light ray (alpha, gamma) leaves the light exactly toward the point: that direction
// is the cube-map lookup rectify.comp makes for S[alpha, gamma]. Light on screen, off screen (to the side)
// and behind the camera.
TEST(MinmaxEpipolar, PointLightRoundTripAndCubeDirection) {
    const viz::scene::Camera cam = testCamera();
    const int w = 64, h = 48;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (glm::vec3 light : {glm::vec3(0.5f, 0.3f, -6.0f), glm::vec3(9.0f, 2.0f, -3.0f), glm::vec3(0.4f, 1.0f, 5.0f)}) {
        viz::render::GpuLightCpu L{};
        L.info = glm::ivec4(viz::render::hd::kLightPoint, -1, 0, 0);
        L.position = glm::vec4(light, 1.0f);
        const auto s = viz::minmax::setupLight({.light = &L, .camera = &cam, .width = w, .height = h, .slices = 0,
                                                .columns = 256});
        EXPECT_EQ(s.frame.kind, LightKind::Point);
        EXPECT_NEAR(s.frame.lightDistance, glm::length(glm::dvec3(light)), 1e-6);
        // Every row's range starts at the eye (gamma = 0) and lies within [0, pi].
        EXPECT_EQ(s.frame.gammaLo, 0.0);
        EXPECT_LE(s.frame.gammaHi, std::numbers::pi);
        for (int i = 0; i < 500; ++i) {
            // A pixel's ray, at a random distance up to 30.
            const glm::dvec3 ray = viz::scene::pixelRay(cam, w, h, w * unit(rng), h * unit(rng));
            const glm::dvec3 p = (0.05 + 30.0 * unit(rng)) * ray;
            const double alpha = viz::minmax::alphaOf(s.frame, p), beta = viz::minmax::betaOf(s.frame, p);
            const double gamma = viz::minmax::gammaOf(s.frame, p);
            ASSERT_GE(gamma, 0.0);
            ASSERT_LE(gamma, std::numbers::pi - beta + 1e-12);
            const glm::dvec3 point = viz::minmax::pointOf(s.frame, alpha, beta, gamma);
            EXPECT_LT(glm::length(point - p), 1e-9 * (1.0 + glm::length(p)));
            const glm::dvec3 fromLight = glm::normalize(p - glm::dvec3(light));
            EXPECT_LT(glm::length(viz::minmax::lightRayDirection(s.frame, alpha, gamma) - fromLight), 1e-9);
            // A row range that reaches just past the point: its column maps back within one column.
            const auto row = s.frame.withGammaRange(0.0, std::min(std::numbers::pi, gamma * (1.0 + unit(rng))));
            const double column = viz::minmax::columnOf(row, gamma);
            ASSERT_LE(column, double(row.columns) + 1e-9);
            const double back = viz::minmax::gammaOfColumn(row, std::floor(column) + 0.5);
            EXPECT_LE(std::abs(back - gamma), 0.5 * row.columnWidth() + 1e-12);
            const int r = viz::minmax::sliceRow(s.frame, alpha);
            EXPECT_LE(viz::minmax::alphaStep(alpha, s.frame.sliceAlpha(r)), 0.5 * s.frame.alphaSpacing + 1e-12);
        }
    }
}

}  // namespace
