// VPLs by Halton points and by grid cells, and the point cloud of the imperfect shadow maps.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "scene/builtin_scenes.h"
#include "cpu/scene/texture_mean_oracle.h"
#include "techniques/vsv/vpl_sampling.h"

namespace viz::vsv {
namespace {

TEST(VplSampling, HaltonPointsAreTheRadicalInverses) {
    EXPECT_DOUBLE_EQ(radicalInverse(1, 2), 0.5);
    EXPECT_DOUBLE_EQ(radicalInverse(6, 2), 0.375);  // 110 -> 0.011
    EXPECT_NEAR(radicalInverse(5, 3), 7.0 / 9.0, 1e-15);  // 12 -> 0.21
}

// VPLs lie on the emitter, face its normal, and their weights sum to the emitted power per steradian
// along the normal: the integral of L_e over the rectangle (estimated on a fine grid of the texture).
TEST(VplSampling, VplsCoverTheEmitterAndCarryItsIntensity) {
    const scene::Scene scene = scene::makeBuiltinScene("tv-room");
    const scene::Light& light = scene.lights[0];
    const double area = 4.0 * glm::length(glm::cross(light.halfU, light.halfV));
    const std::vector<Vpl> vpls = sampleVpls(scene, light, 256);
    ASSERT_EQ(vpls.size(), 256u);
    glm::dvec3 sum(0.0);
    for (const Vpl& v : vpls) {
        const glm::dvec3 d = v.position - light.position;
        EXPECT_NEAR(glm::dot(d, glm::normalize(light.direction)), 0.0, 1e-9);
        EXPECT_LE(std::abs(glm::dot(d, light.halfU)) / glm::dot(light.halfU, light.halfU), 1.0 + 1e-9);
        EXPECT_LE(std::abs(glm::dot(d, light.halfV)) / glm::dot(light.halfV, light.halfV), 1.0 + 1e-9);
        EXPECT_NEAR(glm::length(v.normal - glm::normalize(light.direction)), 0.0, 1e-12);
        sum += v.weight;
    }
    const scene::Texture& tex = scene.textures[std::size_t(light.emissionTexture)];
    glm::dvec3 integral(0.0);
    const int n = 512;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            integral += light.radiance * glm::dvec3(scene::sampleLinearRgb(tex, {(i + 0.5) / n, (j + 0.5) / n}));
    integral *= area / (double(n) * n);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sum[c], integral[c], 0.05 * integral[c]) << c;
}

// The grid's cells are as close to square as a factor pair of the count allows: tv-room's screen is
// 1.6 x 0.9 (half-extents 0.8, 0.45).
TEST(VplSampling, TheGridTakesTheFactorPairClosestToSquareCells) {
    const scene::Scene scene = scene::makeBuiltinScene("tv-room");
    const scene::Light& light = scene.lights[0];
    const double aspect = glm::length(light.halfU) / glm::length(light.halfV);
    for (int count : {1, 7, 12, 16, 64, 100, 128, 256}) {
        const glm::ivec2 n = vplGridSize(light, count);
        EXPECT_EQ(n.x * n.y, count);
        // Exhaustively: no other factor pair gives a cell aspect nearer 1.
        const double mine = std::abs(std::log(aspect * n.y / n.x));
        for (int nx = 1; nx <= count; ++nx)
            if (count % nx == 0) {
                EXPECT_LE(mine, std::abs(std::log(aspect * (count / nx) / nx)) + 1e-12) << count;
            }
    }
    EXPECT_EQ(vplGridSize(light, 7), glm::ivec2(7, 1));  // a prime: one row
}

// Grid VPLs: the cells tile the emitter exactly once (every point of a fine grid of the uv square lies in
// one cell), each VPL sits at its cell's centre, and its weight is the cell's area times the brute-force
// mean of L_e over the cell (tests/cpu/scene/texture_mean_oracle.h); all of them carry the emitter's power
// per steradian along the normal.
TEST(VplSampling, GridVplsTileTheEmitterAndCarryEachCellsMeanRadiance) {
    const scene::Scene scene = scene::makeBuiltinScene("tv-room");
    const scene::Light& light = scene.lights[0];
    const scene::Texture& tex = scene.textures[std::size_t(light.emissionTexture)];
    const double area = 4.0 * glm::length(glm::cross(light.halfU, light.halfV));
    for (int count : {7, 64, 100}) {
        SCOPED_TRACE(count);
        const std::vector<Vpl> vpls = gridVpls(scene, light, count);
        ASSERT_EQ(int(vpls.size()), count);
        glm::dvec3 sum(0.0);
        std::set<std::pair<int, int>> corners;
        for (const Vpl& v : vpls) {
            EXPECT_NEAR(glm::length(v.position - (v.corner + 0.5 * (v.edgeU + v.edgeV))), 0.0, 1e-12);
            EXPECT_NEAR(glm::length(glm::cross(v.edgeU, v.edgeV)), area / count, 1e-12 * area);
            // The cell's uv rectangle, from its corner.
            const glm::dvec3 c = v.corner - (light.position - light.halfU - light.halfV);
            const glm::dvec2 uv0{glm::dot(c, light.halfU) / (2.0 * glm::dot(light.halfU, light.halfU)),
                                 glm::dot(c, light.halfV) / (2.0 * glm::dot(light.halfV, light.halfV))};
            const glm::dvec2 size{glm::length(v.edgeU) / (2.0 * glm::length(light.halfU)),
                                  glm::length(v.edgeV) / (2.0 * glm::length(light.halfV))};
            corners.insert({int(std::lround(uv0.x / size.x)), int(std::lround(uv0.y / size.y))});
            // The midpoint grid's own error on the bilinear filter's kinks at the colour bars' edges is
            // up to 1.8e-4 of a cell's mean here (400^2 nodes); sampling the cell's centre instead of its
            // mean is off by up to tens of per cent.
            const glm::dvec3 mean = testing::gridMeanLinearRgb(tex, uv0, uv0 + size, 400);
            for (int k = 0; k < 3; ++k)
                EXPECT_NEAR(v.weight[k], light.radiance[k] * mean[k] * area / count, 5e-4 * v.weight[k] + 1e-12) << k;
            sum += v.weight;
        }
        EXPECT_EQ(int(corners.size()), count) << "two VPLs share a cell";
        // Every point of a 97 x 97 grid of the emitter (offset so that none falls on a cell's edge) lies in
        // exactly one cell.
        for (int j = 0; j < 97; ++j)
            for (int i = 0; i < 97; ++i) {
                const glm::dvec3 p = light.position + (2.0 * (i + 0.37) / 97 - 1.0) * light.halfU +
                                     (2.0 * (j + 0.37) / 97 - 1.0) * light.halfV;
                int inside = 0;
                for (const Vpl& v : vpls) {
                    const glm::dvec3 d = p - v.corner;
                    const double a = glm::dot(d, v.edgeU) / glm::dot(v.edgeU, v.edgeU);
                    const double b = glm::dot(d, v.edgeV) / glm::dot(v.edgeV, v.edgeV);
                    inside += a >= 0.0 && a < 1.0 && b >= 0.0 && b < 1.0 ? 1 : 0;
                }
                ASSERT_EQ(inside, 1) << i << "," << j;
            }
        const glm::dvec3 total = light.radiance * testing::gridMeanLinearRgb(tex, {0, 0}, {1, 1}, 1024) * area;
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(sum[k], total[k], 1e-4 * total[k]) << k;
    }
}

TEST(VplSampling, PointCloudLiesOnTheSceneButNotOnTheEmitter) {
    const scene::Scene scene = scene::makeBuiltinScene("tv-room");
    const int emitter = scene.lights[0].mesh;
    const std::vector<glm::dvec3> points = samplePointCloud(scene, 5000, emitter);
    ASSERT_EQ(points.size(), 5000u);
    // The room is the box [-3, 3] x [0, 2.8] x [-3, 3]; the screen is the plane z = -2.9 within the TV.
    int onScreen = 0;
    for (const glm::dvec3& p : points) {
        EXPECT_LE(std::abs(p.x), 3.0 + 1e-6);
        EXPECT_GE(p.y, -1e-6);
        EXPECT_LE(p.y, 2.8 + 1e-6);
        onScreen += std::abs(p.z + 2.9) < 1e-6 && std::abs(p.x) < 0.8 && p.y > 0.85 && p.y < 1.75 ? 1 : 0;
    }
    EXPECT_EQ(onScreen, 0);
    EXPECT_EQ(samplePointCloud(scene, 100, emitter, 3), samplePointCloud(scene, 100, emitter, 3));
}

TEST(VplSampling, ParaboloidMapsTheHemisphereOntoTheUnitDisc) {
    EXPECT_NEAR(glm::length(paraboloid({0, 0, 1})), 0.0, 1e-15);
    EXPECT_NEAR(glm::length(paraboloid({1, 0, 0})), 1.0, 1e-15);
    const glm::dvec3 d = glm::normalize(glm::dvec3(0.3, -0.4, 0.5));
    EXPECT_LT(glm::length(paraboloid(d)), 1.0);
}

}  // namespace
}  // namespace viz::vsv
