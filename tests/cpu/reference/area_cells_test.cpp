// Area lights as cells (viz/techniques/reference/area_cells.h): the cell-averaged kernels against an
// independent high-order integral over the cell, near and far, and the convergence of a tv-room pixel
// whose ray passes close to the emitter.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "scene/builtin_scenes.h"
#include "scene/texture_sampling.h"
#include "shared/gauss_legendre.h"
#include "techniques/reference/area_cells.h"
#include "techniques/reference/emitters.h"
#include "techniques/reference/ray_integrals.h"
#include "techniques/reference/ray_probe.h"

namespace viz::reference {
namespace {

const MediumParams kMedium{0.3, 0.32, 0.3};

double hg(double c, double g) {
    return (1.0 - g * g) / (4.0 * std::numbers::pi * std::pow(1.0 + g * g - 2.0 * g * c, 1.5));
}

double relDiff(const glm::dvec3& a, const glm::dvec3& b) {
    return glm::length(a - b) / std::max(glm::length(b), 1e-300);
}

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// A 1.6 x 0.9 panel facing +z with a 5 x 3 texture of sharp colour steps (its bilinear kinks fall inside
// the cells), like the tv-room screen.
scene::Scene panelScene() {
    scene::Scene s;
    scene::Texture tex;
    tex.width = 5;
    tex.height = 3;
    const unsigned char rgb[15][3] = {
        {255, 40, 40},   {40, 255, 40}, {40, 40, 255},   {255, 255, 40}, {250, 250, 250},
        {10, 10, 10},    {255, 128, 0}, {0, 128, 255},   {200, 0, 200},  {90, 90, 90},
        {255, 255, 255}, {0, 0, 0},     {30, 200, 120},  {180, 60, 20},  {60, 60, 200}};
    for (const auto& c : rgb) tex.rgba8.insert(tex.rgba8.end(), {c[0], c[1], c[2], 255});
    s.textures.push_back(tex);
    scene::Light l{.type = scene::LightType::Area,
                   .position = {0.0, 1.3, -2.9},
                   .direction = {0.0, 0.0, 1.0},
                   .halfU = {0.8, 0.0, 0.0},
                   .halfV = {0.0, -0.45, 0.0},
                   .radiance = {12.0, 12.0, 12.0},
                   .emissionTexture = 0};
    s.lights.push_back(l);
    return s;
}

// Cuts of [lo, hi] for the independent rule below: the texel-centre lines (i + 0.5) / texels (kinks of
// the bilinear texture) and a geometric sequence towards the foot point q of x, down to pieces of a
// quarter of x's height z (a geometric mesh: every piece near q is about as large as its distance to q).
std::vector<double> independentCuts(double lo, double hi, int texels, double q, double scale) {
    std::vector<double> cuts{lo, hi};
    for (int i = 0; i < texels; ++i) {
        const double c = (i + 0.5) / texels;
        if (c > lo && c < hi) cuts.push_back(c);
    }
    for (double d = scale; d < hi - lo; d *= 1.5) {
        for (double c : {q - d, q + d})
            if (c > lo && c < hi) cuts.push_back(c);
    }
    if (q > lo && q < hi) cuts.push_back(q);
    std::sort(cuts.begin(), cuts.end());
    return cuts;
}

// Independent integral over the uv rectangle [uv0, uv1] of f(y) L_e(y) dA, f a function of the world
// point y: a tensor composite 16-point Gauss-Legendre rule over the cuts above, in uv. Unlike the
// product rule under test it samples L_e directly and is refined towards x, not towards a segment.
template <class F>
glm::dvec3 bruteForce(const AreaEmitter& e, glm::dvec2 uv0, glm::dvec2 uv1, const glm::dvec3& x, F f) {
    const QuadratureRule gl = gaussLegendreRuleUnit(16);
    const double lu = glm::length(e.edgeU), lv = glm::length(e.edgeV);
    const double z = std::max(std::abs(glm::dot(x - e.corner, e.normal)), 1e-6);
    const glm::dvec2 q(glm::dot(x - e.corner, e.edgeU) / (lu * lu), glm::dot(x - e.corner, e.edgeV) / (lv * lv));
    const int tw = e.texture ? e.texture->width() : 1, th = e.texture ? e.texture->height() : 1;
    const std::vector<double> cu = independentCuts(uv0.x, uv1.x, tw, q.x, 0.25 * z / lu);
    const std::vector<double> cv = independentCuts(uv0.y, uv1.y, th, q.y, 0.25 * z / lv);
    auto points = [&](const std::vector<double>& cuts, std::vector<double>& s, std::vector<double>& wt) {
        for (std::size_t p = 0; p + 1 < cuts.size(); ++p)
            for (std::size_t k = 0; k < gl.nodes.size(); ++k) {
                s.push_back(cuts[p] + (cuts[p + 1] - cuts[p]) * gl.nodes[k]);
                wt.push_back((cuts[p + 1] - cuts[p]) * gl.weights[k]);
            }
    };
    std::vector<double> su, wu, sv, wv;
    points(cu, su, wu);
    points(cv, sv, wv);
    glm::dvec3 sum(0.0);
    for (std::size_t j = 0; j < sv.size(); ++j)
        for (std::size_t i = 0; i < su.size(); ++i) {
            const glm::dvec2 uv(su[i], sv[j]);
            sum += f(e.position(uv)) * e.emitted(uv) * (wu[i] * wv[j]);
        }
    return sum * e.area;
}

TEST(AreaCells, KernelsMatchABruteForceIntegralNearAndFar) {
    const scene::Scene s = panelScene();
    const PreparedLights lights = PreparedLights::build(s, 4);
    ASSERT_EQ(lights.cells.size(), 16u);
    const AreaCell& cell = lights.cells[5];  // an inner cell: uv [0.25, 0.5]^2
    const AreaEmitter& e = *cell.emitter;
    const glm::dvec3 centre = e.position(0.5 * (cell.uv0 + cell.uv1));
    const glm::dvec3 w = glm::normalize(glm::dvec3(-0.6, -0.2, -1.0));  // eye ray direction (for the phase)
    const glm::dvec3 n = glm::normalize(glm::dvec3(0.3, 0.2, -1.0));    // surface normal, facing the panel
    struct Case {
        const char* name;
        glm::dvec3 x;
        double tol;
    };
    const Case cases[] = {
        // The tolerances are the measured accuracy of the product rule per leaf with a margin of about 2
        // (see the printout); far from the cell it is the 2 x 2 rule, nearer the 3 x 3 rule.
        {"far (6 m, 2 x 2 rule)", centre + glm::dvec3(1.5, -1.0, 5.7), 2e-4},
        {"far (2.5 m, 3 x 3 rule)", centre + glm::dvec3(0.7, -0.4, 2.4), 4e-5},
        {"near (5 cm above the centre)", centre + glm::dvec3(0.02, 0.01, 0.05), 1e-5},
        {"1e-4 above the surface", centre + glm::dvec3(0.031, -0.017, 1e-4), 1e-6},
        {"1 mm above, beside the cell's edge",
         e.position(glm::dvec2(cell.uv1.x, 0.4)) + glm::dvec3(0.002, 0.0, 1e-3), 1e-4},
        {"in the plane, just outside", e.position(glm::dvec2(cell.uv1.x, 0.4)) + glm::dvec3(1e-4, 0.0, 0.0), 0.0},
    };
    for (const Case& c : cases) {
        const glm::dvec3 inScatter = cellInScatter(cell, c.x, w, kMedium);
        const glm::dvec3 irradiance = cellIrradiance(cell, c.x, n, kMedium.sigma_t);
        auto inScatterKernel = [&](const glm::dvec3& y) {
            const glm::dvec3 d = c.x - y;
            const double r = glm::length(d);
            const double cosE = std::max(0.0, glm::dot(e.normal, d) / r);
            return cosE * hg(glm::dot(d / r, -w), kMedium.g) * std::exp(-kMedium.sigma_t * r) / (r * r);
        };
        auto irradianceKernel = [&](const glm::dvec3& y) {
            const glm::dvec3 d = c.x - y;
            const double r = glm::length(d);
            const double cosE = std::max(0.0, glm::dot(e.normal, d) / r);
            const double cosS = std::max(0.0, -glm::dot(n, d) / r);
            return cosE * cosS * std::exp(-kMedium.sigma_t * r) / (r * r);
        };
        const glm::dvec3 bfScatter = bruteForce(e, cell.uv0, cell.uv1, c.x, inScatterKernel);
        const glm::dvec3 bfIrradiance = bruteForce(e, cell.uv0, cell.uv1, c.x, irradianceKernel);
        std::printf("%-36s in-scatter %.6e (brute force %.6e, rel %.2e), irradiance %.6e (rel %.2e)\n", c.name,
                    inScatter.y, bfScatter.y, relDiff(inScatter, bfScatter), irradiance.y,
                    relDiff(irradiance, bfIrradiance));
        EXPECT_TRUE(finite(inScatter) && finite(irradiance)) << c.name;
        if (c.tol == 0.0) {
            // In the emitter's plane cos(theta_e) = 0 for every point of the cell.
            EXPECT_EQ(inScatter, glm::dvec3(0.0));
            EXPECT_EQ(bfScatter, glm::dvec3(0.0));
            continue;
        }
        EXPECT_LT(relDiff(inScatter, bfScatter), c.tol) << c.name;
        EXPECT_LT(relDiff(irradiance, bfIrradiance), c.tol) << c.name;
    }
}

// The t-integral of a cell (each leaf node integrated exactly in t, leaves fixed per segment) against a
// composite Gauss sum in t of the cell's kernel at each point (leaves refined towards each point),
// graded towards the segment's end: for segments ending 1e-4 above the cell and in its plane just
// beside it, where a point node's 1/r^2 spike would dominate.
TEST(AreaCells, SegmentIntegralMatchesTheKernelIntegratedAlongTheRay) {
    const scene::Scene s = panelScene();
    const PreparedLights lights = PreparedLights::build(s, 4);
    const AreaCell& cell = lights.cells[5];
    const AreaEmitter& e = *cell.emitter;
    const QuadratureRule gl = gaussLegendreRuleUnit(10);
    struct Case {
        const char* name;
        glm::dvec3 end;
    };
    const Case cases[] = {
        {"ending 1e-4 above the cell", e.position(glm::dvec2(0.37, 0.41)) + 1e-4 * e.normal},
        {"ending in the plane beside the cell", e.position(glm::dvec2(0.5 + 1e-4, 0.4))},
    };
    for (const Case& c : cases) {
        const glm::dvec3 o = c.end + glm::dvec3(1.1, 0.4, 1.3);
        const double d = glm::length(c.end - o);
        const glm::dvec3 w = (c.end - o) / d;
        const glm::dvec3 exact = cellSegment(cell, o, w, 0.0, d, kMedium);
        // Pieces [d - 2^(k+1) h, d - 2^k h] from h = 1e-6 d, then [d - h, d] (the kernel is bounded there).
        std::vector<double> cuts{d};
        for (double h = 1e-6 * d; h < d; h *= 2.0) cuts.push_back(d - h);
        cuts.push_back(0.0);
        glm::dvec3 sum(0.0);
        for (std::size_t p = 0; p + 1 < cuts.size(); ++p) {
            const double lo = cuts[p + 1], hi = cuts[p];
            for (std::size_t k = 0; k < gl.nodes.size(); ++k) {
                const double t = lo + (hi - lo) * gl.nodes[k];
                sum += cellInScatter(cell, o + t * w, w, kMedium) *
                       (kMedium.sigma_s * std::exp(-kMedium.sigma_t * t) * (hi - lo) * gl.weights[k]);
            }
        }
        std::printf("%-36s cellSegment %.6e, kernel along the ray %.6e, rel %.2e\n", c.name, exact.y, sum.y,
                    relDiff(exact, sum));
        EXPECT_TRUE(finite(exact));
        EXPECT_GT(exact.y, 0.0);
        // Measured 1.8e-6 and 5.4e-6 (16-point pieces graded by 1.5, down to 1e-7 d, agree as well).
        EXPECT_LT(relDiff(exact, sum), 2e-5) << c.name;
    }
}

// tv-room at 80x60, pixel (56, 26): its ray passes close to the screen, where a point node's 1/r^2
// spike dominated the old rule (area_samples 8 and 16 differed by 0.1 in radiance).
TEST(AreaCells, TvRoomPixelNearTheScreenConverges) {
    const scene::Scene s = scene::makeBuiltinScene("tv-room");
    ProbeOptions options;
    options.curvePoints = 2;
    options.areaSamples = 8;
    const RayProbe p8 = probePixel(s, 80, 60, 56, 26, options);
    options.areaSamples = 32;
    const RayProbe p32 = probePixel(s, 80, 60, 56, 26, options);
    std::printf("pixel (56,26): L_air %.6f %.6f %.6f (8) vs %.6f %.6f %.6f (32), rel %.3e\n", p8.airlight.x,
                p8.airlight.y, p8.airlight.z, p32.airlight.x, p32.airlight.y, p32.airlight.z,
                relDiff(p8.airlight, p32.airlight));
    EXPECT_TRUE(finite(p8.airlight) && finite(p32.airlight));
    EXPECT_GT(p32.airlight.y, 0.0);
    EXPECT_LT(relDiff(p8.airlight, p32.airlight), 0.01);
}

}  // namespace
}  // namespace viz::reference
