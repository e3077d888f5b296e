// What the tests of the shared GPU passes share (render_pipeline_test.cpp: the surface pass, textures and the
// final composite; shadow_maps_test.cpp: shadow visibility): the fixture, tiny scenes built from quads, a
// camera, the surface pass run on a scene, and shadowVisibility evaluated at world points.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "gl/gl.h"
#include "gl/gl_test_fixture.h"
#include "render/gpu_lights.h"
#include "render/gpu_scene.h"
#include "render/shadow_maps.h"
#include "render/surface_pass.h"
#include "scene/camera.h"

namespace viz::render::test {

// One headless GL 4.5 context per suite (skips without GL unless VIZ_REQUIRE_GL=1).
class RenderPipeline : public gl::GlTest {};

// Axis-aligned quad: centre c, half extents along two axes, normal along the third (+1 or -1).
inline scene::Mesh quad(glm::dvec3 c, int normalAxis, glm::dvec2 half, bool withNormals = true, int material = -1) {
    const int a = (normalAxis + 1) % 3, b = (normalAxis + 2) % 3;
    scene::Mesh m;
    m.name = "quad";
    for (auto [sa, sb] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}}) {
        glm::dvec3 p = c;
        p[a] += sa * half.x;
        p[b] += sb * half.y;
        m.positions.push_back(glm::vec3(p));
        m.uvs.push_back(glm::vec2(0.5 * (sa + 1.0), 0.5 * (sb + 1.0)));
    }
    if (withNormals) {
        glm::vec3 n(0.0f);
        n[normalAxis] = 1.0f;
        m.normals.assign(4, n);
    }
    m.indices = {0, 1, 2, 0, 2, 3};
    m.material = material;
    return m;
}

inline scene::Camera lookCamera(glm::dvec3 position, glm::dvec3 target, double zfar) {
    scene::Camera cam;
    cam.position = position;
    cam.forward = glm::normalize(target - position);
    const glm::dvec3 right = glm::normalize(glm::cross(cam.forward, glm::dvec3(0, 1, 0)));
    cam.up = glm::cross(right, cam.forward);
    cam.yfov = 0.8;
    cam.znear = 0.05;
    cam.zfar = zfar;
    return cam;
}

// Distance along the ray to the floor quad y = y0, |x - cx| <= s, |z - cz| <= s, or nothing.
inline std::optional<double> hitFloor(const glm::dvec3& o, const glm::dvec3& d, double y0, double cx, double cz, double s) {
    if (d.y >= 0.0) return std::nullopt;
    const double t = (y0 - o.y) / d.y;
    const glm::dvec3 p = o + t * d;
    if (std::abs(p.x - cx) > s || std::abs(p.z - cz) > s) return std::nullopt;
    return t;
}

struct Frame {
    Image distance, radiance;
};

inline Frame renderSurface(const scene::Scene& s, int width, int height, int shadowSize = 256) {
    GpuScene gpuScene(s);
    GpuLights lights(s, s.camera.position, 2);
    ShadowMaps shadows;
    shadows.build(gpuScene, lights, shadowSize, 64);
    SurfacePass pass;
    pass.run(gpuScene, lights, shadows, s, width, height);
    return {gl::readTexture(pass.distance()), gl::readTexture(pass.surfaceRadiance())};
}

// Evaluates shadowVisibility for light `index` at world points with shaders/render/probe_lights.comp.
inline std::vector<float> visibility(const scene::Scene& s, const glm::dvec3& eye, int index,
                              const std::vector<glm::dvec3>& world, int size = 256) {
    GpuScene gpuScene(s);
    GpuLights lights(s, eye, 1);
    ShadowMaps shadows;
    shadows.build(gpuScene, lights, size, size);
    auto program = gl::Program::compile({.stages = {"render/probe_lights.comp"}, .label = "test.probe"});
    std::vector<glm::vec4> points;
    for (const auto& p : world) points.push_back(glm::vec4(glm::vec3(p - eye), 1.0f));
    auto in = gl::Buffer::create({.bytes = points.size() * sizeof(glm::vec4), .data = points.data()});
    auto out = gl::Buffer::create({.bytes = 4 * points.size() * sizeof(glm::vec4)});
    in.bindBase(GL_SHADER_STORAGE_BUFFER, hd::kFirstFreeSsboBinding);
    out.bindBase(GL_SHADER_STORAGE_BUFFER, hd::kFirstFreeSsboBinding + 1);
    lights.bind();
    shadows.bind();
    gpuScene.bindMaterials();
    program.use();
    program.set("uMode", 1);
    program.set("uLight", index);
    program.set("uCount", int(points.size()));
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    const auto o = out.download<glm::vec4>();
    std::vector<float> v;
    for (std::size_t i = 0; i < world.size(); ++i) v.push_back(o[4 * i + 2].x);
    return v;
}

// Floor y = 0 and an occluder at y = 2, off-centre toward +x +z, so a flipped map shadows the wrong side.
inline scene::Scene occluderScene() {
    scene::Scene s;
    s.meshes.push_back(quad({0.0, 0.0, 0.0}, 1, {5.0, 5.0}));
    s.meshes.push_back(quad({0.25, 2.0, 0.25}, 1, {0.15, 0.15}));
    s.camera = lookCamera({0.0, 3.0, 6.0}, {0.0, 0.0, 0.0}, 50.0);
    return s;
}

// A spot 3 above the floor pointing straight down over the occluder (cone half-angle 1 rad).
inline scene::Light spotAboveOccluder() {
    scene::Light spot{.type = scene::LightType::Spot,
                      .position = {0.0, 3.0, 0.0},
                      .direction = {0.0, -1.0, 0.0},
                      .outerConeAngle = 1.0};
    return spot;
}

}  // namespace viz::render::test
