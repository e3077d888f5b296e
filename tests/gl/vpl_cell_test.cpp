// An area light's VPL as its cell of the emitter (shaders/common/lights.glsl, vplHasCell; the shared
// parameter vpl_kernel). The GLSL solid angle and segment integral against an independent double
// computation (the rectangle's solid angle by its corner formula, the ray integral by adaptive Simpson),
// and every technique on the shared VPLs against the reference, which integrates the emitter over its
// area and shares no code with the VPLs.
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "case_shader.h"
#include "cpu/reference/reference_test_util.h"
#include "scene/builtin_scenes.h"
#include "cpu/scene/texture_mean_oracle.h"
#include "solid_angle_oracle.h"
#include "technique_test_util.h"

namespace viz::testing {
namespace {

// ---- The independent side, in double (the rectangle's solid angle: solid_angle_oracle.h) -----------------

// A rectangle with corner c, perpendicular edges eU and eV and unit normal n toward its lit side.
struct Rect {
    glm::dvec3 corner, eU, eV, n;
};

double rectSolidAngle(const Rect& r, glm::dvec3 p) { return rectangleSolidAngle(r.corner, r.eU, r.eV, r.n, p); }

double adaptiveSimpson(const std::function<double(double)>& f, double a, double b, double fa, double fm, double fb,
                       double whole, double tolerance, int depth) {
    const double m = 0.5 * (a + b);
    const double lm = f(0.5 * (a + m)), rm = f(0.5 * (m + b));
    const double left = (m - a) / 6.0 * (fa + 4.0 * lm + fm);
    const double right = (b - m) / 6.0 * (fm + 4.0 * rm + fb);
    if (depth <= 0 || std::abs(left + right - whole) <= 15.0 * tolerance) return left + right + (left + right - whole) / 15.0;
    return adaptiveSimpson(f, a, m, fa, lm, fm, left, 0.5 * tolerance, depth - 1) +
           adaptiveSimpson(f, m, b, fm, rm, fb, right, 0.5 * tolerance, depth - 1);
}

// int_a^b f over the given break points (sorted, inside [a, b]), each piece adaptively.
double integrate(const std::function<double(double)>& f, std::vector<double> breaks, double a, double b,
                 double tolerance) {
    breaks.insert(breaks.begin(), a);
    breaks.push_back(b);
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
        const double lo = breaks[i], hi = breaks[i + 1];
        if (!(hi > lo)) continue;
        const double fa = f(lo), fm = f(0.5 * (lo + hi)), fb = f(hi);
        sum += adaptiveSimpson(f, lo, hi, fa, fm, fb, (hi - lo) / 6.0 * (fa + 4.0 * fm + fb), tolerance, 40);
    }
    return sum;
}

struct CellCase {
    std::string name;
    glm::dvec3 node;
    glm::dvec3 w;
    double x0, x1;
    Rect rect;
    double sigmaS, sigmaT, g;
};

// The airlight of the cell with L_e = 1 along [x0, x1] of the ray t w from the eye at the origin:
// int sigma_s p(cos theta) Omega_cell(t w) exp(-sigma_t (t + |t w - D|)) dt, cos theta from the node D.
double cellAirlight(const CellCase& c, double relativeTolerance) {
    const auto f = [&](double t) {
        const glm::dvec3 x = t * c.w;
        const glm::dvec3 toNode = c.node - x;
        const double r = glm::length(toNode);
        const double cosTheta = r > 0.0 ? glm::dot(toNode, c.w) / r : 1.0;
        return c.sigmaS * reference_test::hg(cosTheta, c.g) * rectSolidAngle(c.rect, x) *
               std::exp(-c.sigmaT * (t + r));
    };
    // Break points where the ray is near the cell: around the node's foot point at a ladder of scales.
    const double tP = glm::dot(c.node, c.w);
    const double size = std::sqrt(glm::length(glm::cross(c.rect.eU, c.rect.eV)));
    std::vector<double> breaks;
    for (double k : {-8.0, -2.0, -0.5, -0.1, -0.01, 0.0, 0.01, 0.1, 0.5, 2.0, 8.0}) {
        const double t = tP + k * size;
        if (t > c.x0 && t < c.x1) breaks.push_back(t);
    }
    // A first estimate sets the absolute tolerance.
    const double rough = integrate(f, breaks, c.x0, c.x1, 1e-3 * size);
    return integrate(f, breaks, c.x0, c.x1, relativeTolerance * std::max(rough, 1e-300));
}

CellCase scaled(CellCase c, double s) {
    c.name += " x" + std::to_string(s);
    c.node *= s;
    c.x0 *= s;
    c.x1 *= s;
    c.rect.corner *= s;
    c.rect.eU *= s;
    c.rect.eV *= s;
    c.sigmaS /= s;
    c.sigmaT /= s;
    return c;
}

// A 0.2 x 0.3 cell in the plane z = -2 facing the eye (+z), its node off centre (the kernel takes any node
// in its cell; the shared VPLs put it at the centre), and rays that hit it, pass through its node, graze its plane, pass far from it or behind it.
std::vector<CellCase> cellCases() {
    const Rect rect{{-0.1, -0.15, -2.0}, {0.2, 0.0, 0.0}, {0.0, 0.3, 0.0}, {0.0, 0.0, 1.0}};
    const glm::dvec3 node = rect.corner + glm::dvec3(0.07, 0.2, 0.0);
    const glm::dvec3 centre = rect.corner + 0.5 * (rect.eU + rect.eV);
    const auto ray = [&](const std::string& name, glm::dvec3 target, double x0, double x1Fraction) {
        const double length = glm::length(target);
        return CellCase{name, node, target / length, x0, x1Fraction * length, rect, 0.3, 0.35, 0.3};
    };
    std::vector<CellCase> cases = {
        ray("ends on the cell's centre", centre, 0.0, 1.0),
        ray("ends just short of the node", node, 0.0, 0.9995),
        ray("passes through the node and on behind the plane", node, 0.0, 1.5),
        ray("grazes the plane 1e-3 above, over the cell", glm::dvec3(0.3, 0.0, -2.0 + 1e-3), 0.0, 1.0),
        ray("ends 1e-4 above the plane beside the cell", glm::dvec3(0.15, 0.0, -2.0 + 1e-4), 0.0, 1.0),
        ray("passes far to the side", glm::dvec3(8.0, 1.0, -1.0), 0.0, 2.0),
        ray("crosses the plane beside the cell", glm::dvec3(0.5, 0.2, -2.5), 0.0, 1.2),
        ray("a piece in the middle", centre, 1.0, 0.95),
        ray("far from it, facing away (solid angles 1e-5 to 1e-4)", glm::dvec3(0.3, 0.2, 1.0), 20.0, 60.0),
    };
    // Rays that pass the node at a quarter, a half, one and two cell sizes (c = 0.245), across the cell's
    // face: where the segment integral's extra breaks start (closer than c / 4) and where they do not.
    const glm::dvec3 across = glm::normalize(glm::cross(node, glm::dvec3(0.0, 0.0, 1.0)));
    for (double k : {0.2, 0.3, 0.5, 1.0, 2.0}) {
        const glm::dvec3 target = node + k * 0.245 * across + glm::dvec3(0.0, 0.0, 0.05);
        cases.push_back(ray("passes the node " + std::to_string(k) + " cells away", target, 0.0, 1.3));
    }
    CellCase thick = cases[0];
    thick.name = "thick medium";
    thick.sigmaT = 5.0;
    cases.push_back(thick);
    for (double g : {0.9, -0.7}) {
        for (int i : {0, 3}) {
            CellCase c = cases[std::size_t(i)];
            c.name += " g=" + std::to_string(g);
            c.g = g;
            cases.push_back(c);
        }
    }
    for (double s : {1e-3, 1e3}) {
        cases.push_back(scaled(cases[0], s));
        cases.push_back(scaled(cases[3], s));
    }
    return cases;
}

// ---- The GLSL side -------------------------------------------------------------------------------------

using VplCellGlsl = gl::GlTest;

std::vector<glm::vec4> runCells(const std::vector<CellCase>& cases) {
    std::vector<glm::vec4> inputs;
    for (const CellCase& c : cases) {
        inputs.emplace_back(glm::vec3(c.node), float(c.x0));
        inputs.emplace_back(glm::vec3(c.w), float(c.x1));
        inputs.emplace_back(glm::vec3(c.rect.corner), float(c.sigmaS));
        inputs.emplace_back(glm::vec3(c.rect.eU), float(c.sigmaT));
        inputs.emplace_back(glm::vec3(c.rect.eV), float(c.g));
        inputs.emplace_back(glm::vec3(c.rect.n), 0.0f);
    }
    return runCaseShader<glm::vec4>("vpl_cell_glsl_test.comp", inputs, int(cases.size()));
}

// The double side takes the float-rounded inputs the shader saw.
CellCase roundedToFloat(CellCase c) {
    const auto r = [](glm::dvec3 v) { return glm::dvec3(glm::vec3(v)); };
    c.node = r(c.node);
    c.w = r(c.w);
    c.rect = {r(c.rect.corner), r(c.rect.eU), r(c.rect.eV), r(c.rect.n)};
    c.x0 = double(float(c.x0));
    c.x1 = double(float(c.x1));
    c.sigmaS = double(float(c.sigmaS));
    c.sigmaT = double(float(c.sigmaT));
    c.g = double(float(c.g));
    return c;
}

TEST_F(VplCellGlsl, SolidAngleAndSegmentIntegralMatchAnIndependentDoubleComputation) {
    std::vector<CellCase> cases;
    for (const CellCase& c : cellCases()) cases.push_back(roundedToFloat(c));
    const std::vector<glm::vec4> out = runCells(cases);
    ASSERT_EQ(out.size(), cases.size());
    double worstSegment = 0.0, worstOmega = 0.0;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const CellCase& c = cases[i];
        SCOPED_TRACE(c.name);
        ASSERT_TRUE(std::isfinite(out[i].x) && std::isfinite(out[i].y));
        // The solid angle from the segment's start point (never more than 2 pi from one side).
        const double omega = rectSolidAngle(c.rect, c.x0 * c.w);
        EXPECT_NEAR(out[i].y, omega, 2e-6 * std::max(omega, 1e-3)) << omega;
        EXPECT_LE(out[i].y, 2.0 * std::numbers::pi + 1e-5);
        worstOmega = std::max(worstOmega, std::abs(out[i].y - omega) / std::max(omega, 1e-3));
        // The segment integral, L_e = 1.
        const double expected = cellAirlight(c, 1e-9);
        ASSERT_GT(expected, 0.0);
        const double e = std::abs(double(out[i].x) - expected) / expected;
        std::printf("  %-58s cell %.6e, double %.6e, relative %.1e; as a point %.3e\n", c.name.c_str(), double(out[i].x),
                    expected, e, double(out[i].z));
        EXPECT_LT(e, 2e-5) << "GLSL " << out[i].x << " double " << expected;
        worstSegment = std::max(worstSegment, e);
    }
    std::printf("VPL cell against double: %zu cases, segment worst %.2e, solid angle worst %.2e\n", cases.size(),
                worstSegment, worstOmega);
}

// ---- Every technique on the shared VPLs -----------------------------------------------------------------

class VplCellTest : public TechniqueTest {};

// 80x60, every technique that shades the shared VPLs at its defaults (4x4 VPLs, each its cell), against
// the reference at 4x4 cells (2.3e-3 from 32x32 on tv-room, reference README). With a disc of each
// VPL's area they were 0.235-0.236 and the room came out blue (the texture at 16 points); with points
// raymarch was 0.53, slices 1.39, polyvol 0.63, minmax 0.66.
TEST_F(VplCellTest, EveryTechniqueOnTheSharedVplsComesWithinATenthOfTheAreaLight) {
    const scene::Scene scene = scene::makeBuiltinScene("tv-room");
    const FrameOutput reference = render(scene, "reference", {{"area_samples", 4}}, 80, 60);
    for (const std::string technique : {"raymarch", "slices", "polyvol", "minmax"}) {
        const FrameOutput out = render(scene, technique, {}, 80, 60);
        ASSERT_EQ(out.airlight.pixels.size(), reference.airlight.pixels.size()) << technique;
        EXPECT_TRUE(allFinite(out.airlight)) << technique;
        const double e = relativeL2(out.airlight, reference.airlight);
        std::printf("%s on tv-room against the area light: relative L2 %.4f\n", technique.c_str(), e);
        EXPECT_LT(e, 0.12) << technique;
    }
    // vpl_kernel=point: the point VPLs, whose 1/r^2 peaks next to the screen dominate (0.29: more than
    // three times the cells' 0.085).
    const FrameOutput cells = render(scene, "raymarch", {}, 80, 60);
    const FrameOutput points = render(scene, "raymarch", {{"vpl_kernel", 0}}, 80, 60);
    const double e = relativeL2(points.airlight, reference.airlight);
    std::printf("raymarch with point VPLs (vpl_kernel=point): relative L2 %.4f\n", e);
    EXPECT_GT(e, 2.0 * relativeL2(cells.airlight, reference.airlight));
}

// minmax marches each VPL with vpl_samples (64) samples, not march_samples (512): the cell's integrand is
// bounded and smooth on the cell's scale. Against raymarch at 1024 samples on the same VPLs and maps (a
// march of its own): 0.37 % here, 0.39 % at 160x120 (128 samples 0.17 %, 256 0.04 %), a twentieth of
// the VPLs' own error against the area light (8.5 %); raymarch at its default 64 samples is as far.
TEST_F(VplCellTest, MinmaxMarchesEachVplWithFewSamplesAndStaysWithinHalfAPercent) {
    const scene::Scene scene = scene::makeBuiltinScene("tv-room");
    const FrameOutput converged = render(scene, "raymarch", {{"samples", 1024}}, 80, 60);
    const FrameOutput out = render(scene, "minmax", {}, 80, 60);
    const double e = relativeL2(out.airlight, converged.airlight);
    std::printf("minmax (vpl_samples=64) against raymarch at 1024 samples on tv-room's VPLs: relative L2 %.5f\n", e);
    EXPECT_LT(e, 0.006);
}

// The VPL cells view (render/vpl_cells_view.h): on tv-room every technique on the shared VPLs shows the
// screen at its aspect ratio, each cell in the picture's mean colour over that cell (against a fine grid
// of bilinear samples over the cell, one of n x n equal cells, normalised like the view); grate, without
// an area light, has none.
TEST_F(VplCellTest, TheCellsViewShowsEachCellInItsMeanColour) {
    const scene::Scene tv = scene::makeBuiltinScene("tv-room");
    const scene::Light& screen = tv.lights.front();
    const scene::Texture& picture = tv.textures[std::size_t(screen.emissionTexture)];
    const int n = 4;
    // uv at fraction f of the way across cell i (the same edges along u and v).
    const auto within = [&](int i, double f) { return (i + f) / n; };
    std::vector<glm::dvec3> means;
    double peak = 0.0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const glm::dvec2 lo(within(i, 0.0), within(j, 0.0)), hi(within(i, 1.0), within(j, 1.0));
            means.push_back(screen.radiance * gridMeanLinearRgb(picture, lo, hi, 200));
            peak = std::max({peak, means.back().r, means.back().g, means.back().b});
        }
    for (const std::string technique : {"raymarch", "slices", "polyvol", "minmax"}) {
        SCOPED_TRACE(technique);
        const FrameOutput out = render(tv, technique, {{"area_samples", double(n)}}, 32, 24, 0);
        const Intermediate* view = find(out, technique + ".vpl_cells");
        ASSERT_NE(view, nullptr);
        ASSERT_TRUE(view->image);
        const Image& im = *view->image;
        EXPECT_NEAR(double(im.width) / double(im.height), 1.6 / 0.9, 0.02);
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                // A point a third of the way into the cell from its low corner: inside, off the node's dot.
                const int x = int(within(i, 0.3) * im.width), y = int(within(j, 0.3) * im.height);
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(im.at(x, y, c), means[std::size_t(j * n + i)][c] / peak, 2e-3) << i << "," << j;
            }
    }
    const FrameOutput grate = render(scene::makeBuiltinScene("grate"), "raymarch", {}, 32, 24, 0);
    EXPECT_EQ(find(grate, "raymarch.vpl_cells"), nullptr);
}

}  // namespace
}  // namespace viz::testing
