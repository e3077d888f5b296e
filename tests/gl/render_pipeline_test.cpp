// Tests of the shared GPU passes on tiny scenes: the surface pass (distance against CPU ray-plane
// intersections along scene::pixelRay, sky = zfar, Lambert under a point light against the CPU formula),
// textured albedo and emitters, and the final composite. Shadow visibility: shadow_maps_test.cpp.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "render/compose.h"
#include "render/gpu_lights.h"
#include "render/gpu_scene.h"
#include "render/shadow_maps.h"
#include "render/surface_pass.h"
#include "render_pipeline_util.h"
#include "scene/area_light.h"
#include "scene/camera.h"
#include "scene/texture_sampling.h"

namespace viz::render::test {
namespace {

// Checks the distance image against the CPU intersection, skipping pixels whose neighbours disagree on
// hit/miss (the quad's silhouette, where coverage depends on rasterisation rules). Returns #checked.
int checkDistances(const scene::Scene& s, const Image& distance, double y0, double cx, double cz, double half,
                   int* skyPixels) {
    const int w = distance.width, h = distance.height;
    auto hit = [&](int x, int y) {
        return hitFloor(s.camera.position, scene::pixelRay(s.camera, w, h, x, y), y0, cx, cz, half);
    };
    int checked = 0;
    *skyPixels = 0;
    for (int y = 1; y < h - 1; ++y) {
        for (int x = 1; x < w - 1; ++x) {
            const auto t = hit(x, y);
            const bool inside = t && *t <= s.camera.zfar;
            bool edge = false;
            for (auto [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
                const auto tn = hit(x + dx, y + dy);
                edge = edge || (bool(tn && *tn <= s.camera.zfar) != inside);
            }
            if (edge) continue;
            const double expected = inside ? *t : s.camera.zfar;
            EXPECT_NEAR(distance.at(x, y), expected, 1e-4 * expected) << "pixel " << x << "," << y;
            ++checked;
            if (!inside) ++*skyPixels;
        }
    }
    return checked;
}

TEST_F(RenderPipeline, SurfaceDistanceMatchesCpuRayPlaneAndSkyGetsZfar) {
    scene::Scene s;
    s.meshes.push_back(quad({0.0, 0.0, 0.0}, 1, {6.0, 6.0}));
    s.camera = lookCamera({0.3, 2.0, 4.0}, {0.0, 0.0, -1.0}, 30.0);
    scene::Light light;
    light.position = {0.0, 3.0, 0.0};
    s.lights = {light};
    const Frame f = renderSurface(s, 80, 60);
    int sky = 0;
    const int checked = checkDistances(s, f.distance, 0.0, 0.0, 0.0, 6.0, &sky);
    EXPECT_GT(checked, 3000);
    EXPECT_GT(sky, 300);             // the upper part of the image sees past the quad
    EXPECT_GT(checked - sky, 1500);  // and most of it sees the quad
    // Sky pixels carry no surface radiance.
    EXPECT_EQ(f.radiance.at(40, 0, 0), 0.0f);
}

TEST_F(RenderPipeline, SurfaceDistanceFarFromTheOriginKeepsPrecision) {
    // World coordinates around 1e4 (exactly representable). Interpolated fp32 world positions there
    // have steps of ~1e-3, i.e. 2e-4 of these ~5-unit distances, beyond the 1e-4 asked for; eye-relative
    // positions stay small and keep full precision.
    const glm::dvec3 o(10000.0, 0.0, -10000.0);
    scene::Scene s;
    s.meshes.push_back(quad(o, 1, {6.0, 6.0}));
    s.camera = lookCamera(o + glm::dvec3(0.25, 2.0, 4.0), o + glm::dvec3(0.0, 0.0, -1.0), 30.0);
    scene::Light light;
    light.position = o + glm::dvec3(0.0, 3.0, 0.0);
    s.lights = {light};
    const Frame f = renderSurface(s, 80, 60);
    int sky = 0;
    EXPECT_GT(checkDistances(s, f.distance, o.y, o.x, o.z, 6.0, &sky), 3000);
}

TEST_F(RenderPipeline, LambertUnderAPointLightMatchesTheCpuFormula) {
    scene::Scene s;
    scene::Material mat;
    mat.baseColorFactor = {0.8f, 0.6f, 0.4f, 1.0f};
    s.materials.push_back(mat);
    // Without vertex normals: the flat normal (+y by winding) is used and flipped toward the eye.
    s.meshes.push_back(quad({0.0, 0.0, 0.0}, 1, {6.0, 6.0}, /*withNormals=*/false, 0));
    s.camera = lookCamera({0.3, 2.0, 4.0}, {0.0, 0.0, -1.0}, 30.0);
    s.medium.sigma_s = 0.05;
    s.medium.sigma_a = 0.02;
    scene::Light light{.type = scene::LightType::Point,
                       .position = {0.5, 3.0, -1.0},
                       .colour = {1.0, 0.9, 0.8},
                       .intensity = 20.0};
    s.lights = {light};
    const int w = 80, h = 60;
    const Frame f = renderSurface(s, w, h);
    int checked = 0;
    for (int y = 0; y < h; y += 3) {
        for (int x = 0; x < w; x += 3) {
            const glm::dvec3 d = scene::pixelRay(s.camera, w, h, x, y);
            const auto t = hitFloor(s.camera.position, d, 0.0, 0.0, 0.0, 5.5);
            if (!t) continue;
            const glm::dvec3 p = s.camera.position + *t * d;
            const glm::dvec3 toLight = light.position - p;
            const double r = glm::length(toLight);
            const double cosSurface = toLight.y / r;  // n = (0, 1, 0), facing the eye (above the floor)
            const glm::dvec3 E = light.intensity * light.colour * std::exp(-s.medium.sigma_t() * r) / (r * r);
            const glm::dvec3 expected = glm::dvec3(mat.baseColorFactor) / std::numbers::pi * E * cosSurface;
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(f.radiance.at(x, y, c), expected[c], 1e-4 * expected[c]) << x << "," << y << " c" << c;
            }
            ++checked;
        }
    }
    EXPECT_GT(checked, 200);
}

TEST_F(RenderPipeline, LambertSumsSpotAndDirectionalLights) {
    scene::Scene s;
    s.meshes.push_back(quad({0.0, 0.0, 0.0}, 1, {6.0, 6.0}));
    s.camera = lookCamera({0.3, 2.0, 4.0}, {0.0, 0.0, -1.0}, 30.0);
    s.medium.sigma_s = 0.1;
    scene::Light spot{.type = scene::LightType::Spot,
                      .position = {0.2, 2.5, -0.5},
                      .direction = glm::normalize(glm::dvec3(0.1, -1.0, 0.3)),
                      .colour = {0.9, 1.0, 0.7},
                      .intensity = 15.0,
                      .innerConeAngle = 0.3,
                      .outerConeAngle = 0.7};
    scene::Light sun{.type = scene::LightType::Directional,
                     .direction = glm::normalize(glm::dvec3(0.4, -1.0, -0.2)),
                     .colour = {1.0, 0.5, 0.25},
                     .intensity = 2.0};
    s.lights = {spot, sun};
    const int w = 80, h = 60;
    const Frame f = renderSurface(s, w, h);
    const double scale = 1.0 / std::max(0.001, std::cos(spot.innerConeAngle) - std::cos(spot.outerConeAngle));
    const double offset = -std::cos(spot.outerConeAngle) * scale;
    int checked = 0, inCone = 0;
    for (int y = 0; y < h; y += 3) {
        for (int x = 0; x < w; x += 3) {
            const glm::dvec3 d = scene::pixelRay(s.camera, w, h, x, y);
            const auto t = hitFloor(s.camera.position, d, 0.0, 0.0, 0.0, 5.5);
            if (!t) continue;
            const glm::dvec3 p = s.camera.position + *t * d;
            const glm::dvec3 toLight = spot.position - p;
            const double r = glm::length(toLight);
            const double a = std::clamp(glm::dot(spot.direction, -toLight / r) * scale + offset, 0.0, 1.0);
            const glm::dvec3 Espot = spot.intensity * spot.colour * a * a * std::exp(-s.medium.sigma_t() * r) / (r * r);
            const glm::dvec3 Esun = sun.intensity * sun.colour;
            const glm::dvec3 expected = (Espot * (toLight.y / r) + Esun * -sun.direction.y) / std::numbers::pi;
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(f.radiance.at(x, y, c), expected[c], 1e-4 * expected[c]) << x << "," << y << " c" << c;
            }
            ++checked;
            if (a > 0.0) ++inCone;
        }
    }
    EXPECT_GT(checked, 200);
    EXPECT_GT(inCone, 20);
}

scene::Texture randomTexture(const std::string& name, int w, int h, unsigned seed) {
    scene::Texture t;
    t.name = name;
    t.width = w;
    t.height = h;
    unsigned state = seed;
    for (int i = 0; i < w * h * 4; ++i) {
        state = state * 1664525u + 1013904223u;  // fixed LCG: deterministic everywhere
        t.rgba8.push_back(std::uint8_t((state >> 24) | (i % 4 == 3 ? 255u : 0u)));
    }
    return t;
}

TEST_F(RenderPipeline, TexturedAlbedoMatchesTheCpuFormula) {
    scene::Scene s;
    s.textures.push_back(randomTexture("albedo", 4, 3, 11));
    s.textures.push_back(randomTexture("bigger", 8, 8, 12));  // makes the array larger than "albedo"
    scene::Material mat;
    mat.baseColorFactor = {0.9f, 0.7f, 0.8f, 1.0f};
    mat.baseColorTexture = 0;
    scene::Material other;
    other.baseColorTexture = 1;
    s.materials = {mat, other};
    // Floor [-2, 2]^2 at y = 0: uv = ((z + 2) / 4, (x + 2) / 4) (quad(): u along z, v along x).
    s.meshes.push_back(quad({0.0, 0.0, 0.0}, 1, {2.0, 2.0}, true, 0));
    s.meshes.push_back(quad({0.0, -5.0, 0.0}, 1, {0.5, 0.5}, true, 1));  // out of view
    s.camera = lookCamera({0.2, 3.0, 2.5}, {0.0, 0.0, 0.0}, 30.0);
    scene::Light light{.position = {0.3, 2.5, 0.4}, .intensity = 8.0};
    s.lights = {light};
    const int w = 64, h = 48;
    const Frame f = renderSurface(s, w, h);
    int checked = 0;
    for (int y = 0; y < h; y += 2) {
        for (int x = 0; x < w; x += 2) {
            const glm::dvec3 d = scene::pixelRay(s.camera, w, h, x, y);
            const auto t = hitFloor(s.camera.position, d, 0.0, 0.0, 0.0, 1.95);
            if (!t) continue;
            const glm::dvec3 p = s.camera.position + *t * d;
            const glm::dvec2 uv((p.z + 2.0) / 4.0, (p.x + 2.0) / 4.0);
            const glm::dvec3 albedo = glm::dvec3(mat.baseColorFactor) * glm::dvec3(scene::sampleLinearRgb(s.textures[0], uv));
            const glm::dvec3 toLight = light.position - p;
            const double r = glm::length(toLight);
            const glm::dvec3 expected = albedo / std::numbers::pi * light.intensity / (r * r) * (toLight.y / r);
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(f.radiance.at(x, y, c), expected[c], 1e-4 * expected[c] + 1e-7) << x << "," << y << " c" << c;
            }
            ++checked;
        }
    }
    EXPECT_GT(checked, 300);
}

TEST_F(RenderPipeline, EmitterShowsTextureRadianceOnItsEmittingSideOnly) {
    scene::Scene s;
    s.textures.push_back(randomTexture("emission", 3, 2, 5));
    scene::Material glow;
    glow.emissiveFactor = {2.0f, 3.0f, 4.0f};
    glow.emissiveStrength = 1.5f;
    glow.emissiveTexture = 0;
    s.materials = {glow};
    // Emitter at y = 2 facing down (clockwise seen from above), [-1, 1]^2: uv = ((z + 1) / 2, (x + 1) / 2).
    scene::Mesh emitter = quad({0.0, 2.0, 0.0}, 1, {1.0, 1.0}, false, 0);
    emitter.indices = {0, 2, 1, 0, 3, 2};
    s.meshes.push_back(emitter);
    s.lights.push_back(scene::areaLightFromMesh(s, 0));
    ASSERT_NEAR(s.lights[0].direction.y, -1.0, 1e-12);
    const glm::dvec3 radiance = glm::dvec3(glow.emissiveFactor) * double(glow.emissiveStrength);
    const int w = 40, h = 30;
    for (bool below : {true, false}) {
        s.camera = lookCamera(below ? glm::dvec3(0.1, 0.5, 0.8) : glm::dvec3(0.1, 3.5, 0.8), {0.0, 2.0, 0.0}, 30.0);
        const Frame f = renderSurface(s, w, h);
        int checked = 0;
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                const glm::dvec3 d = scene::pixelRay(s.camera, w, h, x, y);
                const double t = (2.0 - s.camera.position.y) / d.y;
                const glm::dvec3 p = s.camera.position + t * d;
                if (t <= 0.0 || std::abs(p.x) > 0.95 || std::abs(p.z) > 0.95) continue;
                const glm::dvec3 le = radiance * glm::dvec3(scene::sampleLinearRgb(s.textures[0], {(p.z + 1.0) / 2.0, (p.x + 1.0) / 2.0}));
                // The emitter's own VPLs lie in its plane: n.l = 0, no Lambert term on the emitter itself.
                // In fp32 both cosines are rounding-sized next to a VPL (r -> 0), so allow 1e-5 of the
                // emitter's radiance scale on top of the 1e-4 relative error.
                const glm::dvec3 expected = below ? le : glm::dvec3(0.0);
                const double floor = 1e-5 * radiance.z;
                for (int c = 0; c < 3; ++c) EXPECT_NEAR(f.radiance.at(x, y, c), expected[c], 1e-4 * expected[c] + floor);
                ++checked;
            }
        }
        EXPECT_GT(checked, 100) << (below ? "below" : "above");
    }
}

TEST_F(RenderPipeline, ComposeFinalAttenuatesTheSurfaceAndAddsAirlight) {
    const int w = 7, h = 5;
    std::vector<float> surface(w * h * 4), dist(w * h), air(w * h * 4);
    for (int i = 0; i < w * h; ++i) {
        for (int c = 0; c < 4; ++c) {
            surface[std::size_t(4 * i + c)] = 0.1f * float(i % 5) + 0.3f * float(c);
            air[std::size_t(4 * i + c)] = 0.01f * float(i) + 0.02f * float(c);
        }
        dist[std::size_t(i)] = 0.5f * float(i);
    }
    auto make = [&](GLenum format, GLenum pixelFormat, const std::vector<float>& data) {
        auto t = gl::Texture::create({.format = format, .size = {w, h, 1}, .label = "test.input"});
        t.upload(pixelFormat, GL_FLOAT, data.data());
        return t;
    };
    const auto s = make(GL_RGBA32F, GL_RGBA, surface);
    const auto d = make(GL_R32F, GL_RED, dist);
    const auto a = make(GL_RGBA32F, GL_RGBA, air);
    auto out = gl::Texture::create({.format = GL_RGBA32F, .size = {w, h, 1}, .label = "test.final"});
    const float sigma_t = 0.3f;
    const scene::Medium medium{.sigma_s = 0.0, .sigma_a = 0.3, .g = 0.0};  // sigma_t() = 0.3
    composeFinal(s, d, a, medium, out);
    const Image img = gl::readTexture(out);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            // Image row y is GL row h - 1 - y.
            const int i = (h - 1 - y) * w + x;
            for (int c = 0; c < 3; ++c) {
                const double expected = double(surface[std::size_t(4 * i + c)]) * std::exp(-double(sigma_t) * dist[std::size_t(i)]) +
                                        double(air[std::size_t(4 * i + c)]);
                EXPECT_NEAR(img.at(x, y, c), expected, 1e-6 * (1.0 + expected));
            }
        }
    }
}

// Not a pass/fail test: prints how long the shared passes take here (run with
// --gtest_also_run_disabled_tests --gtest_filter='*RenderBenchmark*').
TEST_F(RenderPipeline, DISABLED_RenderBenchmark) {
    scene::Scene s = occluderScene();
    for (int i = 0; i < 20; ++i) {
        const double x = -3.0 + 0.3 * i, z = 1.5 * std::sin(i);
        s.meshes.push_back(quad({x, 0.5 + 0.05 * i, z}, i % 3, {0.2, 0.3}));
    }
    scene::Light spot{.type = scene::LightType::Spot, .position = {0.0, 3.0, 0.0}, .direction = {0.0, -1.0, 0.0}};
    scene::Light point = spot;
    point.type = scene::LightType::Point;
    point.position = {1.0, 2.0, 1.0};
    scene::Light sun{.type = scene::LightType::Directional, .direction = glm::normalize(glm::dvec3(0.3, -1.0, 0.2))};
    scene::Light area{.type = scene::LightType::Area,
                      .position = {-1.0, 2.5, 0.0},
                      .direction = {0.0, -1.0, 0.0},
                      .halfU = {0.3, 0.0, 0.0},
                      .halfV = {0.0, 0.0, 0.3},
                      .radiance = {1.0, 1.0, 1.0}};
    s.lights = {spot, point, sun, area};
    auto ms = [](auto&& f) {
        glFinish();
        const auto t0 = std::chrono::steady_clock::now();
        f();
        glFinish();
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    };
    GpuScene gpuScene(s);
    ShadowMaps shadows;
    SurfacePass pass;
    {
        // Without the area light: three maps (spot 2D, point cube, directional 2D).
        scene::Scene noArea = s;
        noArea.lights.pop_back();
        GpuLights few(noArea, s.camera.position, 1);
        for (int size : {256, 1024}) {
            shadows.build(gpuScene, few, size, 1);
            const double t = ms([&] { shadows.build(gpuScene, few, size, 1); });
            std::printf("shadow maps: spot + point + directional, size %d: %.1f ms\n", size, t);
        }
        pass.run(gpuScene, few, shadows, noArea, 160, 120);
        const double t = ms([&] { pass.run(gpuScene, few, shadows, noArea, 160, 120); });
        std::printf("surface pass 160x120, 3 lights: %.1f ms\n", t);
    }
    GpuLights lights(s, s.camera.position, 4);
    for (int size : {256, 512, 1024, 2048}) {
        shadows.build(gpuScene, lights, size, std::min(size, 256));  // allocation and first use
        const double t = ms([&] { shadows.build(gpuScene, lights, size, std::min(size, 256)); });
        std::printf("shadow maps: 3 lights + 16 VPLs, size %d (VPL %d): %.1f ms\n", size, std::min(size, 256), t);
    }
    for (glm::ivec2 r : {glm::ivec2(160, 120), glm::ivec2(640, 480)}) {
        pass.run(gpuScene, lights, shadows, s, r.x, r.y);
        const double t = ms([&] { pass.run(gpuScene, lights, shadows, s, r.x, r.y); });
        std::printf("surface pass %dx%d, 19 lights: %.1f ms\n", r.x, r.y, t);
    }
}

}  // namespace
}  // namespace viz::render::test
