// minmax's per-frame epipolar setup reads alpha's and beta's ranges and alpha's smallest step per pixel off
// the image's border and the pixels around the (anti-)epipole (epipolar_setup.cpp, sweepBorder) instead of
// every pixel's ray. Checked against the exhaustive sweep (SetupInput::everyPixel) over random cameras,
// lights, image sizes and pixel aspects: the same frame, slice count, spacing, beta range and smallest step,
// bit for bit, with the epipole on screen, off screen, behind the camera and at infinity (a sun).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "render/host_device.h"
#include "scene/builtin_scenes.h"
#include "scene/camera.h"
#include "techniques/minmax/epipolar_setup.h"

namespace {

using viz::minmax::setupLight;
using viz::minmax::SetupInput;

glm::dvec3 randomUnit(std::mt19937_64& rng) {
    std::normal_distribution<double> n;
    for (;;) {
        const glm::dvec3 v(n(rng), n(rng), n(rng));
        if (glm::length(v) > 1e-3) return glm::normalize(v);
    }
}

struct SweepCase {
    viz::scene::Camera camera;
    viz::render::GpuLightCpu light{};
    int width = 0, height = 0;
    bool fixedFrame = false;
    int oversampling = 1;
    const char* where = "";
};

// A light placed so that its epipole falls on screen, just off it, behind the camera or anywhere; a third
// of the lights are suns (a sun along the view plane has its epipole at infinity: parallel slices).
SweepCase randomCase(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    SweepCase c;
    c.camera.position = glm::dvec3(0.0);
    c.camera.forward = randomUnit(rng);
    c.camera.up = glm::normalize(glm::cross(glm::cross(c.camera.forward, randomUnit(rng)), c.camera.forward));
    c.camera.yfov = 0.15 + 2.3 * u(rng);
    c.width = 7 + int(200 * u(rng) * u(rng) + 40 * u(rng));
    c.height = 7 + int(150 * u(rng) * u(rng) + 30 * u(rng));
    if (u(rng) < 0.25) c.camera.aspectRatio = 0.5 + 2.0 * u(rng);  // pixels that are not square
    c.fixedFrame = u(rng) < 0.3;
    c.oversampling = u(rng) < 0.3 ? 4 : 1;
    const viz::scene::PixelRays rays(c.camera, c.width, c.height);
    glm::dvec3 toward;
    const double pick = u(rng);
    if (pick < 0.35) {
        toward = rays(u(rng) * c.width - 0.5, u(rng) * c.height - 0.5);  // epipole on screen
        c.where = "on screen";
    } else if (pick < 0.5) {
        toward = -rays(u(rng) * c.width - 0.5, u(rng) * c.height - 0.5);  // anti-epipole on screen
        c.where = "behind";
    } else if (pick < 0.65) {
        toward = rays(-3.0 + 6.0 * u(rng), (1.2 * u(rng) - 0.1) * c.height);  // by the left edge
        c.where = "at the edge";
    } else if (pick < 0.75) {
        toward = glm::normalize(glm::cross(c.camera.forward, randomUnit(rng)));  // in the view plane
        c.where = "at infinity";
    } else {
        toward = randomUnit(rng);
        c.where = "anywhere";
    }
    const double kind = u(rng);
    auto& L = c.light;
    if (kind < 0.33) {
        L.info = glm::ivec4(viz::render::hd::kLightDirectional, -1, 0, 0);
        L.direction = glm::vec4(glm::vec3(-toward), 0.0f);
        L.shadowMatrix = glm::mat4(1.0f);
    } else {
        const double distance = 0.5 + 50.0 * u(rng);
        L.info = glm::ivec4(kind < 0.66 ? viz::render::hd::kLightSpot : viz::render::hd::kLightPoint, -1, 0, 0);
        L.position = glm::vec4(glm::vec3(distance * toward), 1.0f);
        L.direction = glm::vec4(glm::vec3(randomUnit(rng)), 0.0f);
        L.spot = glm::vec4(1.0f, 0.0f, 1.0f, 0.5f);
    }
    return c;
}

// The border sweep's setup against the exhaustive one's, field by field, bit for bit; returns the latter.
viz::minmax::Setup expectSameFigures(SetupInput in, const std::string& what) {
    in.everyPixel = false;
    const auto border = setupLight(in);
    in.everyPixel = true;
    const auto every = setupLight(in);
    EXPECT_EQ(border.minAlphaGradient, every.minAlphaGradient) << what;
    EXPECT_EQ(border.betaLo, every.betaLo) << what;
    EXPECT_EQ(border.betaHi, every.betaHi) << what;
    EXPECT_EQ(border.frame.wrap, every.frame.wrap) << what;
    EXPECT_EQ(border.frame.slices, every.frame.slices) << what;
    EXPECT_EQ(border.frame.alphaLo, every.frame.alphaLo) << what;
    EXPECT_EQ(border.frame.alphaSpacing, every.frame.alphaSpacing) << what;
    EXPECT_EQ(border.maxSliceGap, every.maxSliceGap) << what;
    return every;
}

TEST(MinmaxEpipolarSweep, TheBorderAndTheEpipolesGiveEveryPixelsFigures) {
    std::mt19937_64 rng(20261203);
    int cases = 0, wrapped = 0, open = 0;
    for (int i = 0; i < 1500; ++i) {
        const SweepCase c = randomCase(rng);
        const std::string what = std::to_string(i) + ": " + c.where + ", " + std::to_string(c.width) + "x" +
                                 std::to_string(c.height) + ", light kind " + std::to_string(c.light.info.x);
        const auto every = expectSameFigures({.light = &c.light, .camera = &c.camera, .width = c.width,
                                              .height = c.height, .columns = 256, .oversampling = c.oversampling,
                                              .fixedFrame = c.fixedFrame},
                                             what);
        ++cases;
        (every.frame.wrap ? wrapped : open) += 1;
    }
    std::printf("%d cases: %d with wrapping slices, %d with an alpha interval\n", cases, wrapped, open);
    // Both kinds of grid were exercised.
    EXPECT_GT(wrapped, 200);
    EXPECT_GT(open, 200);
}

// At a real size, with the epipole on screen near a corner (the steepest fan of slices), at the centre and
// off screen: the same figures.
TEST(MinmaxEpipolarSweep, SameFiguresAtFullHd) {
    viz::scene::Camera cam;
    cam.position = glm::dvec3(0.0);
    cam.forward = glm::dvec3(0.0, 0.0, -1.0);
    cam.up = glm::dvec3(0.0, 1.0, 0.0);
    cam.yfov = 0.9;
    const int w = 1920, h = 1080;
    const viz::scene::PixelRays rays(cam, w, h);
    for (glm::dvec2 pixel : {glm::dvec2(5.3, 7.8), glm::dvec2(960.0, 540.0), glm::dvec2(-400.0, 300.0)}) {
        viz::render::GpuLightCpu L{};
        L.info = glm::ivec4(viz::render::hd::kLightSpot, -1, 0, 0);
        L.position = glm::vec4(glm::vec3(12.0 * rays(pixel.x, pixel.y)), 1.0f);
        L.direction = glm::vec4(0.0f, -1.0f, 0.0f, 0.0f);
        L.spot = glm::vec4(1.0f, 0.0f, 1.0f, 0.5f);
        expectSameFigures({.light = &L, .camera = &cam, .width = w, .height = h, .columns = 256},
                          "epipole at " + std::to_string(pixel.x) + ", " + std::to_string(pixel.y));
    }
}

// Every built-in scene's camera and spot, point and directional lights (eye-relative, as the run uploads
// them) at the report's and the GPU benchmark's sizes: the same figures, so the same images.
TEST(MinmaxEpipolarSweep, SameFiguresOnEveryBuiltinView) {
    int lights = 0;
    for (const std::string& name : viz::scene::builtinSceneNames()) {
        const viz::scene::Scene scene = viz::scene::makeBuiltinScene(name);
        viz::scene::Camera cam = scene.camera;
        cam.position = glm::dvec3(0.0);
        for (const viz::scene::Light& light : scene.lights) {
            viz::render::GpuLightCpu L{};
            using viz::scene::LightType;
            if (light.type == LightType::Area) continue;
            L.info = glm::ivec4(light.type == LightType::Directional ? viz::render::hd::kLightDirectional
                                : light.type == LightType::Spot      ? viz::render::hd::kLightSpot
                                                                     : viz::render::hd::kLightPoint,
                                -1, 0, 0);
            L.position = glm::vec4(glm::vec3(light.position - scene.camera.position), 1.0f);
            L.direction = glm::vec4(glm::vec3(light.direction), 0.0f);
            L.spot = glm::vec4(1.0f, 0.0f, 1.0f, float(std::cos(light.outerConeAngle)));
            L.shadowMatrix = glm::mat4(1.0f);
            ++lights;
            for (glm::ivec2 size : {glm::ivec2(160, 120), glm::ivec2(640, 480), glm::ivec2(1920, 1080)}) {
                expectSameFigures({.light = &L, .camera = &cam, .width = size.x, .height = size.y, .columns = 256},
                                  name + " " + light.name + " at " + std::to_string(size.x));
            }
        }
    }
    EXPECT_GE(lights, 5);
}

}  // namespace
