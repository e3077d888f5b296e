// Tests of render::GpuLights and shaders/common/lights.glsl: the GpuLight/GpuMaterial layout agrees
// between C++ and GLSL, spot cookies sample as scene::sampleLinearRgb does, area lights become VPLs
// whose weights integrate the emitter, and the Gauss-Legendre rule is exact where it must be.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/gl_test_fixture.h"
#include "render/gpu_lights.h"
#include "render/gpu_scene.h"
#include "render/medium_block.h"
#include "render/shadow_maps.h"
#include "scene/texture_sampling.h"

namespace viz::render {
namespace {

// One headless GL 4.5 context per suite (skips without GL unless VIZ_REQUIRE_GL=1).
class RenderLights : public gl::GlTest {};

// A floor quad (y = 0, [-s, s]^2), so scenes have bounds.
scene::Mesh floorQuad(double s, int material = -1) {
    scene::Mesh m;
    m.name = "floor";
    const float f = float(s);
    m.positions = {{-f, 0, -f}, {f, 0, -f}, {f, 0, f}, {-f, 0, f}};
    m.normals.assign(4, glm::vec3(0, 1, 0));
    m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    m.indices = {0, 2, 1, 0, 3, 2};
    m.material = material;
    return m;
}

// Runs shaders/render/probe_lights.comp and returns uOut.
std::vector<glm::vec4> probe(const GpuScene& gpuScene, const GpuLights& lights, int mode, int light,
                             const std::vector<glm::vec4>& points, int outVec4s, float sigma_t = 0.0f) {
    auto program = gl::Program::compile({.stages = {"render/probe_lights.comp"}, .label = "test.probe"});
    std::vector<glm::vec4> in = points;
    if (in.empty()) in.push_back(glm::vec4(0.0f));
    auto pointBuffer = gl::Buffer::create({.bytes = in.size() * sizeof(glm::vec4), .data = in.data()});
    auto out = gl::Buffer::create({.bytes = size_t(outVec4s) * sizeof(glm::vec4)});
    pointBuffer.bindBase(GL_SHADER_STORAGE_BUFFER, hd::kFirstFreeSsboBinding);
    out.bindBase(GL_SHADER_STORAGE_BUFFER, hd::kFirstFreeSsboBinding + 1);
    lights.bind();
    gpuScene.bindMaterials();
    program.use();
    program.set("uMode", mode);
    program.set("uLight", light);
    program.set("uCount", mode == 0 ? lights.count() : int(points.size()));
    MediumBlock medium;  // alive until the dispatch: deleting a buffer unbinds it
    medium.bind(scene::Medium{.sigma_s = 0.0, .sigma_a = double(sigma_t), .g = 0.0});
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    return out.download<glm::vec4>();
}

// The medium block as the GLSL compiler lays it out: three floats at the offsets of GpuMedium's x, y, z
// (std140), in a block no larger than GpuMedium, at the binding host_device.glsl declares.
TEST_F(RenderLights, MediumBlockLayoutMatchesGpuMedium) {
    auto program = gl::Program::compile({.stages = {"render/probe_lights.comp"}, .label = "test.medium_layout"});
    const GLuint block = glGetProgramResourceIndex(program.id(), GL_UNIFORM_BLOCK, "GpuMediumBlock");
    ASSERT_NE(block, GL_INVALID_INDEX);
    const GLenum blockProps[] = {GL_BUFFER_BINDING, GL_BUFFER_DATA_SIZE};
    GLint blockValues[2] = {-1, -1};
    glGetProgramResourceiv(program.id(), GL_UNIFORM_BLOCK, block, 2, blockProps, 2, nullptr, blockValues);
    EXPECT_EQ(blockValues[0], hd::kBindingMedium);
    EXPECT_GE(blockValues[1], 12);
    EXPECT_LE(blockValues[1], GLint(sizeof(hd::GpuMedium)));
    const char* names[] = {"uSigmaS", "uSigmaT", "uG"};
    for (int i = 0; i < 3; ++i) {
        const GLuint index = glGetProgramResourceIndex(program.id(), GL_UNIFORM, names[i]);
        ASSERT_NE(index, GL_INVALID_INDEX) << names[i];
        const GLenum props[] = {GL_OFFSET, GL_BLOCK_INDEX};
        GLint values[2] = {-1, -1};
        glGetProgramResourceiv(program.id(), GL_UNIFORM, index, 2, props, 2, nullptr, values);
        EXPECT_EQ(values[0], GLint(i * sizeof(float))) << names[i];
        EXPECT_EQ(values[1], GLint(block)) << names[i];
    }
}

TEST_F(RenderLights, GpuLightAndMaterialLayoutsMatchGlsl) {
    scene::Scene s;
    s.meshes.push_back(floorQuad(2.0, 0));
    scene::Material mat;
    mat.baseColorFactor = {0.25f, 0.5f, 0.75f, 1.0f};
    mat.emissiveFactor = {1.5f, 2.5f, 3.5f};
    mat.emissiveStrength = 2.0f;
    s.materials.push_back(mat);
    scene::Light point{.type = scene::LightType::Point,
                       .position = {1.0, 2.0, 3.0},
                       .colour = {0.5, 0.25, 1.0},
                       .intensity = 7.0};
    scene::Light spot = point;
    spot.type = scene::LightType::Spot;
    spot.direction = glm::normalize(glm::dvec3(0.2, -1.0, 0.1));
    spot.innerConeAngle = 0.2;
    spot.outerConeAngle = 0.5;
    s.lights = {point, spot};
    const glm::dvec3 eye(0.5, 1.0, 4.0);
    GpuScene gpuScene(s);
    GpuLights lights(s, eye, 1);
    ASSERT_EQ(lights.count(), 2);
    // Make every float distinct so a shifted member cannot match by accident.
    std::vector<GpuLightCpu> known = lights.lights();
    float v = 1.0f;
    for (auto& L : known) {
        for (glm::vec4* f : {&L.position, &L.direction, &L.radiant, &L.spot, &L.frameX, &L.frameY, &L.shadow}) {
            *f = glm::vec4(v, v + 0.25f, v + 0.5f, v + 0.75f);
            v += 1.0f;
        }
        L.info = glm::ivec4(int(v), int(v) + 1, int(v) + 2, int(v) + 3);
        v += 4.0f;
        for (int c = 0; c < 4; ++c) {
            L.shadowMatrix[c] = glm::vec4(v, v + 0.125f, v + 0.375f, v + 0.625f);
            v += 1.0f;
        }
    }
    const_cast<gl::Buffer&>(lights.buffer()).upload(0, known.size() * sizeof(GpuLightCpu), known.data());

    const int materials = gpuScene.materialCount();
    ASSERT_EQ(materials, 2);  // the scene's and the default white
    const auto out = probe(gpuScene, lights, 0, 0, {}, 12 * 2 + 4 * materials);
    for (std::size_t i = 0; i < known.size(); ++i) {
        const GpuLightCpu& L = known[i];
        const glm::vec4* o = &out[12 * i];
        EXPECT_EQ(o[0], L.position);
        EXPECT_EQ(o[1], L.direction);
        EXPECT_EQ(o[2], L.radiant);
        EXPECT_EQ(o[3], L.spot);
        EXPECT_EQ(o[4], L.frameX);
        EXPECT_EQ(o[5], L.frameY);
        EXPECT_EQ(o[6], glm::vec4(L.info));
        EXPECT_EQ(o[7], L.shadow);
        for (int c = 0; c < 4; ++c) EXPECT_EQ(o[8 + c], L.shadowMatrix[c]);
    }
    // Material 0 as the scene defines it (linear factors, emissive = factor * strength).
    const glm::vec4* m = &out[12 * 2];
    EXPECT_EQ(m[0], mat.baseColorFactor);
    EXPECT_EQ(glm::vec3(m[1]), mat.emissiveFactor * mat.emissiveStrength);
    EXPECT_EQ(m[2], glm::vec4(-1, -1, 0, 0));
    // The default material is white and dark.
    EXPECT_EQ(out[12 * 2 + 4], glm::vec4(1.0f));
    EXPECT_EQ(glm::vec3(out[12 * 2 + 5]), glm::vec3(0.0f));
}

// Independent CPU spot evaluation from the definition (double): I colour A_spot cookie.
glm::dvec3 spotIntensityCpu(const scene::Light& L, const scene::Texture* cookie, const glm::dvec3& p) {
    const glm::dvec3 d = glm::normalize(p - L.position);
    const glm::dvec3 z = glm::normalize(L.direction);
    const glm::dvec3 up = std::abs(z.y) > 0.999 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 x = glm::normalize(glm::cross(z, up));
    const glm::dvec3 y = glm::cross(x, z);
    const double scale = 1.0 / std::max(0.001, std::cos(L.innerConeAngle) - std::cos(L.outerConeAngle));
    const double offset = -std::cos(L.outerConeAngle) * scale;
    const double a = std::clamp(glm::dot(z, d) * scale + offset, 0.0, 1.0);
    glm::dvec3 c(1.0);
    if (cookie) {
        const double t = std::tan(L.outerConeAngle), dz = glm::dot(z, d);
        const glm::dvec2 uv(0.5 + 0.5 * glm::dot(x, d) / (dz * t), 0.5 + 0.5 * glm::dot(y, d) / (dz * t));
        c = glm::dvec3(scene::sampleLinearRgb(*cookie, uv));
    }
    return L.intensity * L.colour * a * a * c;
}

TEST_F(RenderLights, SpotCookieAndAttenuationMatchTheDefinition) {
    scene::Scene s;
    s.meshes.push_back(floorQuad(3.0));
    scene::Texture cookie;
    cookie.name = "cookie";
    cookie.width = 5;
    cookie.height = 3;
    std::srand(7);
    for (int i = 0; i < cookie.width * cookie.height; ++i) {
        for (int c = 0; c < 3; ++c) cookie.rgba8.push_back(std::uint8_t(std::rand() % 256));
        cookie.rgba8.push_back(255);
    }
    // A second, larger texture first, so the cookie uses only a corner of its array layer.
    scene::Texture big;
    big.name = "big";
    big.width = 9;
    big.height = 7;
    big.rgba8.assign(9 * 7 * 4, 200);
    s.textures = {big, cookie};
    scene::Light spot{.type = scene::LightType::Spot,
                      .position = {0.3, 3.0, -0.2},
                      .direction = glm::normalize(glm::dvec3(0.15, -1.0, 0.1)),
                      .colour = {1.0, 0.8, 0.6},
                      .intensity = 12.0,
                      .innerConeAngle = 0.25,
                      .outerConeAngle = 0.6,
                      .cookie = 1};
    scene::Light spot2 = spot;  // same light using the big texture: forces a 9x7 array
    spot2.cookie = 0;
    s.lights = {spot, spot2};
    const glm::dvec3 eye(1.0, 2.0, 5.0);
    GpuScene gpuScene(s);
    GpuLights lights(s, eye, 1);
    ASSERT_EQ(lights.cookies().size().x, 9);

    // Points on the floor inside the inner cone, between the cones, near the edge, and outside.
    std::vector<glm::dvec3> world;
    for (double x = -1.8; x <= 2.5; x += 0.37) {
        for (double z = -1.9; z <= 2.0; z += 0.41) world.push_back({x, 0.0, z});
    }
    std::vector<glm::vec4> points;
    for (const auto& p : world) points.push_back(glm::vec4(glm::vec3(p - eye), 1.0f));
    const auto out = probe(gpuScene, lights, 1, 0, points, 4 * int(points.size()));
    int inCone = 0;
    for (std::size_t i = 0; i < world.size(); ++i) {
        const glm::dvec3 expected = spotIntensityCpu(spot, &s.textures[1], world[i]);
        const glm::vec3 got(out[4 * i]);
        if (glm::length(expected) > 0.0) ++inCone;
        for (int c = 0; c < 3; ++c) {
            // fp32 evaluation of attenuation and bilinear weights: a few ulps of the largest term.
            EXPECT_NEAR(got[c], expected[c], 2e-5 * spot.intensity) << "point " << i << " channel " << c;
        }
    }
    EXPECT_GT(inCone, 20);  // the grid does sample the cone
}

TEST_F(RenderLights, AreaLightBecomesVplsThatIntegrateTheEmitter) {
    scene::Scene s;
    s.meshes.push_back(floorQuad(3.0));
    scene::Light area{.type = scene::LightType::Area,
                      .position = {0.0, 2.0, 0.0},
                      .direction = {0.0, -1.0, 0.0},
                      .halfU = {0.5, 0.0, 0.0},
                      .halfV = {0.0, 0.0, -0.25},  // cross(halfU, halfV) = (0, 0.125, 0)... any orientation works for weights
                      .radiance = {2.0, 3.0, 4.0}};
    s.lights = {area};
    GpuScene gpuScene(s);
    for (int n : {1, 3, 4}) {
        GpuLights lights(s, glm::dvec3(0.0), n);
        ASSERT_EQ(lights.count(), n * n);
        glm::dvec3 sum(0.0);
        for (const auto& L : lights.lights()) {
            EXPECT_EQ(L.info.x, hd::kLightVpl);
            // Every node lies on the rectangle.
            EXPECT_NEAR(L.position.y, 2.0f, 1e-6f);
            EXPECT_LE(std::abs(L.position.x), 0.5f);
            EXPECT_LE(std::abs(L.position.z), 0.25f);
            sum += glm::dvec3(L.radiant);
        }
        // Sum of weights = radiance * area, area = 4 |halfU| |halfV| = 0.5.
        const glm::dvec3 expected = area.radiance * 0.5;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(sum[c], expected[c], 1e-6 * expected[c]) << "n = " << n;
    }
    EXPECT_THROW(GpuLights(s, glm::dvec3(0.0), 0), InputError);
    // 17^2 = 289 VPLs exceed the 256 lights of the uniform block.
    EXPECT_THROW(GpuLights(s, glm::dvec3(0.0), 17), InputError);
    EXPECT_NO_THROW(GpuLights(s, glm::dvec3(0.0), 16));
}

// A VPL's E: its weight L_e dA times the emitter's cosine, softened by the disc of area dA it stands for
// (shaders/common/lights.glsl, vplDiscRadius): L_e dA n.(p - D) exp(-sigma_t r') / r'^3, r' = hypot(r, rho),
// rho^2 = dA / pi. The points on the emitter's axis at a few rho show the softening; the far ones the point.
TEST_F(RenderLights, VplIrradianceHasTheCosineLobe) {
    scene::Scene s;
    s.meshes.push_back(floorQuad(3.0));
    scene::Light area{.type = scene::LightType::Area,
                      .position = {0.0, 2.0, 0.0},
                      .direction = {0.0, -1.0, 0.0},
                      .halfU = {0.1, 0.0, 0.0},
                      .halfV = {0.0, 0.0, 0.1},
                      .radiance = {1.0, 2.0, 3.0}};
    s.lights = {area};
    GpuScene gpuScene(s);
    GpuLights lights(s, glm::dvec3(0.0), 1);
    ASSERT_EQ(lights.count(), 1);
    const float sigma_t = 0.1f;
    const std::vector<glm::dvec3> world = {{0.0, 0.0, 0.0}, {1.5, 0.5, -0.7}, {0.3, 2.5, 0.0}, {0.0, 1.9, 0.0},
                                           {0.05, 1.75, 0.02}};
    std::vector<glm::vec4> points;
    for (const auto& p : world) points.push_back(glm::vec4(glm::vec3(p), 1.0f));
    const auto out = probe(gpuScene, lights, 1, 0, points, 4 * int(points.size()), sigma_t);
    const double dA = 0.2 * 0.2;  // one node: the whole rectangle
    const double rho2 = dA / std::numbers::pi;
    for (std::size_t i = 0; i < world.size(); ++i) {
        const glm::dvec3 d = world[i] - area.position;
        const double r = glm::length(d);
        const double soft = std::sqrt(r * r + rho2);
        const double normal = std::max(0.0, glm::dot(area.direction, d));
        const glm::dvec3 expected =
            area.radiance * dA * normal * std::exp(-double(sigma_t) * soft) / (soft * soft * soft);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(out[4 * i + 1][c], expected[c], 1e-5 * glm::length(area.radiance * dA) + 1e-6 * expected[c]);
        }
        EXPECT_NEAR(out[4 * i + 3].w, r, 1e-5 * r);
    }
    // The point above the emitter is behind it: no emission.
    EXPECT_EQ(glm::vec3(out[4 * 2 + 1]), glm::vec3(0.0f));
    // 0.1 below the emitter (rho = 0.113) a point light's E would be (1 + rho^2 / r^2)^(3/2) = 3.4 times higher.
    EXPECT_LT(out[4 * 3 + 1].x, 0.5 * float(area.radiance.x * dA / 0.01));
}

}  // namespace
}  // namespace viz::render
