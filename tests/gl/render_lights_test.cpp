// Tests of render::GpuLights and shaders/common/lights.glsl: the GpuLight/GpuMaterial layout agrees
// between C++ and GLSL, spot cookies sample as scene::sampleLinearRgb does, area lights become VPLs
// at the centres of equal cells, whose weights integrate the emitter.
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
#include "cpu/scene/texture_mean_oracle.h"
#include "solid_angle_oracle.h"

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

// A VPL's E stands for its cell (shaders/common/lights.glsl, vplHasCell): L_e Omega_cell(p) exp(-sigma_t r),
// r to the node; as a point (vpl_kernel=point) L_e dA n.(p - D) exp(-sigma_t r) / r^3. One node: the cell is
// the whole rectangle. Points far below show the two agree; 0.01 below the centre the point's 1/r^2 is
// 70 times the cell's, which stays under 2 pi L_e.
TEST_F(RenderLights, VplIrradianceIsTheCellsSolidAngleOrThePointsCosineLobe) {
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
    const float sigma_t = 0.1f;
    const std::vector<glm::dvec3> world = {{0.0, 0.0, 0.0}, {1.5, 0.5, -0.7}, {0.3, 2.5, 0.0}, {0.0, 1.9, 0.0},
                                           {0.05, 1.75, 0.02}, {0.09, 1.999, -0.03}, {0.0, 1.99, 0.0}};
    std::vector<glm::vec4> points;
    for (const auto& p : world) points.push_back(glm::vec4(glm::vec3(p), 1.0f));
    const double dA = 0.2 * 0.2;
    // The expectations take the float inputs the shader sees (a point 1e-3 from the plane has its height
    // to 6e-5 only).
    const auto asFloat = [](glm::dvec3 v) { return glm::dvec3(glm::vec3(v)); };
    const glm::dvec3 corner = asFloat(area.position - area.halfU - area.halfV);
    std::vector<glm::vec4> cellOut, pointOut;
    {
        GpuLights lights(s, glm::dvec3(0.0), 1, VplKernel::Cell);
        ASSERT_EQ(lights.count(), 1);
        cellOut = probe(gpuScene, lights, 1, 0, points, 4 * int(points.size()), sigma_t);
    }
    {
        GpuLights lights(s, glm::dvec3(0.0), 1, VplKernel::Point);
        pointOut = probe(gpuScene, lights, 1, 0, points, 4 * int(points.size()), sigma_t);
    }
    for (std::size_t i = 0; i < world.size(); ++i) {
        SCOPED_TRACE(i);
        const glm::dvec3 d = asFloat(world[i]) - area.position;
        const double r = glm::length(d);
        const double omega = testing::rectangleSolidAngle(corner, asFloat(2.0 * area.halfU),
                                                          asFloat(2.0 * area.halfV), area.direction, asFloat(world[i]));
        const glm::dvec3 cell = area.radiance * omega * std::exp(-double(sigma_t) * r);
        const double normal = std::max(0.0, glm::dot(area.direction, d));
        const glm::dvec3 point = area.radiance * dA * normal * std::exp(-double(sigma_t) * r) / (r * r * r);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(cellOut[4 * i + 1][c], cell[c], 1e-5 * cell[c] + 1e-7);
            EXPECT_NEAR(pointOut[4 * i + 1][c], point[c], 1e-5 * glm::length(area.radiance * dA) + 1e-6 * point[c]);
        }
        EXPECT_NEAR(cellOut[4 * i + 3].w, r, 1e-5 * r);
        EXPECT_LE(cellOut[4 * i + 1].z, 2.0 * std::numbers::pi * area.radiance.z);
    }
    // Far below, the cell is the point within (size / r)^2.
    EXPECT_NEAR(cellOut[1].y, pointOut[1].y, 0.01 * pointOut[1].y);
    // The point above the emitter is behind it: no emission either way.
    EXPECT_EQ(glm::vec3(cellOut[4 * 2 + 1]), glm::vec3(0.0f));
    EXPECT_EQ(glm::vec3(pointOut[4 * 2 + 1]), glm::vec3(0.0f));
    // 0.01 below the centre the point's E is dA / r^2 = 400 L_e, the cell's under 2 pi L_e.
    EXPECT_GT(pointOut[4 * 6 + 1].x, 50.0f * cellOut[4 * 6 + 1].x);
}

// A textured emitter's VPLs sit at the centres of equal cells and carry the texture's mean over their
// cells: together the emitter's mean colour times its area (checked against a fine grid of bilinear
// samples, not the exact cell means), and each the mean over the cell that holds its node.
TEST_F(RenderLights, VplsCarryTheirCellsMeanColour) {
    scene::Scene s;
    s.meshes.push_back(floorQuad(3.0));
    scene::Texture bars;
    bars.width = 7;
    bars.height = 3;
    const std::uint8_t colours[7][3] = {{255, 255, 255}, {255, 255, 0}, {0, 255, 255}, {0, 255, 0},
                                        {255, 0, 255},   {255, 0, 0},   {0, 0, 255}};
    for (int y = 0; y < bars.height; ++y)
        for (int x = 0; x < bars.width; ++x) {
            const std::uint8_t* c = colours[x];
            const std::uint8_t shade = std::uint8_t(255 - 80 * y);
            for (int k = 0; k < 3; ++k) bars.rgba8.push_back(std::uint8_t(c[k] * shade / 255));
            bars.rgba8.push_back(255);
        }
    s.textures.push_back(bars);
    scene::Light area{.type = scene::LightType::Area,
                      .position = {0.0, 2.0, 0.0},
                      .direction = {0.0, -1.0, 0.0},
                      .halfU = {0.8, 0.0, 0.0},
                      .halfV = {0.0, 0.0, 0.45},
                      .radiance = {3.0, 3.0, 3.0}};
    area.emissionTexture = 0;
    s.lights = {area};
    const glm::dvec3 mean = testing::gridMeanLinearRgb(bars, {0.0, 0.0}, {1.0, 1.0}, 1400);
    const double areaSize = 4.0 * 0.8 * 0.45;
    for (int n : {1, 2, 4, 7}) {
        const LightDescription d = describeLights(s, glm::dvec3(0.0), n);
        ASSERT_EQ(int(d.lights.size()), n * n);
        glm::dvec3 sum(0.0);
        for (const GpuLightCpu& L : d.lights) {
            sum += glm::dvec3(L.radiant);
            // The node lies in its cell (corner spot.xyz, edges frameX, frameY), whose area is spot.w.
            const glm::dvec3 rel = glm::dvec3(L.position) - glm::dvec3(L.spot);
            const glm::dvec3 eU(L.frameX), eV(L.frameY);
            EXPECT_GE(glm::dot(rel, eU), 0.0);
            EXPECT_LE(glm::dot(rel, eU), glm::dot(eU, eU) * (1.0 + 1e-6));
            EXPECT_GE(glm::dot(rel, eV), 0.0);
            EXPECT_LE(glm::dot(rel, eV), glm::dot(eV, eV) * (1.0 + 1e-6));
            EXPECT_NEAR(double(L.spot.w), glm::length(glm::cross(eU, eV)), 1e-6);
            // Equal cells, each node at its cell's centre.
            EXPECT_NEAR(double(L.spot.w), areaSize / (n * n), 1e-6 * areaSize);
            EXPECT_NEAR(glm::length(rel - 0.5 * (eU + eV)), 0.0, 1e-6);
        }
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(sum[c], area.radiance[c] * areaSize * mean[c], 2e-4 * area.radiance[c] * areaSize)
                << "n = " << n;
    }
    // Four VPLs across seven bars (the nodes fall in bars 0, 2, 4 and 6): most VPLs' colours differ from
    // the texture at their nodes, which is what they carried before.
    const LightDescription four = describeLights(s, glm::dvec3(0.0), 4);
    int differ = 0;
    for (const GpuLightCpu& L : four.lights) {
        const glm::dvec3 rel = glm::dvec3(L.position) - (area.position - area.halfU - area.halfV);
        const glm::dvec2 uv(rel.x / 1.6, rel.z / 0.9);
        const glm::dvec3 atNode = area.radiance * glm::dvec3(scene::sampleLinearRgb(bars, uv)) * double(L.spot.w);
        if (glm::length(glm::dvec3(L.radiant) - atNode) > 0.05 * glm::length(atNode)) ++differ;
    }
    EXPECT_GT(differ, 8);
}

}  // namespace
}  // namespace viz::render
