// The per-interval integrals of the reference (spot cones, cookies, area emitters) against
// independent evaluations written from the definition, and the quadrature rules they use.
#include <gtest/gtest.h>

#include <cstdio>

#include "reference_test_util.h"
#include "techniques/reference/emitters.h"
#include "techniques/reference/quadrature.h"
#include "techniques/reference/ray_integrals.h"

namespace viz {
namespace {

using reference_test::hg;
using reference_test::relDiff;
using reference_test::spotA;

const reference::MediumParams kMedium{0.3, 0.45, 0.5};

scene::Light makeSpot(double inner, double outer) {
    scene::Light l{.type = scene::LightType::Spot,
                   .position = {0.0, 3.0, 0.0},
                   .direction = glm::normalize(glm::dvec3(0.2, -1.0, 0.1)),
                   .colour = {1.0, 0.8, 0.6},
                   .intensity = 25.0,
                   .innerConeAngle = inner,
                   .outerConeAngle = outer};
    return l;
}

// Midpoint rule in t of sigma_s p I(dir) exp(-sigma_t (t + r)) / r^2, I(dir) supplied by the caller.
template <class Profile>
glm::dvec3 midpointAlongRay(const glm::dvec3& o, const glm::dvec3& w, const glm::dvec3& P, double a, double b,
                            std::int64_t n, Profile profile) {
    const double dt = (b - a) / double(n);
    glm::dvec3 total(0.0), block(0.0);
    for (std::int64_t i = 0; i < n; ++i) {
        const double t = a + (double(i) + 0.5) * dt;
        const glm::dvec3 x = o + t * w;
        const double r = glm::length(x - P);
        const glm::dvec3 dir = (x - P) / r;
        block += profile(dir) * (kMedium.sigma_s * hg(glm::dot(dir, -w), kMedium.g) *
                                 std::exp(-kMedium.sigma_t * (t + r)) / (r * r));
        if (i % 1000 == 999) {
            total += block;
            block = glm::dvec3(0.0);
        }
    }
    return (total + block) * dt;
}

TEST(ReferencePieces, AdaptiveKronrodReachesToleranceAcrossAKink) {
    // int_0^2 |x - 0.7|^0.5 dx has an integrable singular derivative at 0.7; split there it is exact.
    auto f = [](double x) { return glm::dvec3(std::sqrt(std::abs(x - 0.7))); };
    const double exact = (2.0 / 3.0) * (std::pow(0.7, 1.5) + std::pow(1.3, 1.5));
    const auto left = reference::integrateAdaptive(f, 0.0, 0.7, 1e-12, 0.0, 2000);
    const auto right = reference::integrateAdaptive(f, 0.7, 2.0, 1e-12, 0.0, 2000);
    EXPECT_NEAR(left.value.x + right.value.x, exact, 1e-11 * exact);
}

TEST(ReferencePieces, SpotInsideInnerConeEqualsPointSegment) {
    // A wide spot whose inner cone contains the whole segment: A = 1, so the adaptive quadrature in
    // theta must agree with airlight::pointSegment (isotropic emitter) to ~1e-10.
    const scene::Light l = makeSpot(1.2, 1.3);
    const reference::SpotProfile profile = reference::SpotProfile::fromLight(l, nullptr);
    reference::PointEmitter spot{l.position, l.intensity * l.colour, reference::ProfileKind::Spot, &profile};
    reference::PointEmitter point{l.position, l.intensity * l.colour, reference::ProfileKind::Isotropic};
    const glm::dvec3 o(-1.0, 0.5, 3.0);
    const glm::dvec3 w = glm::normalize(glm::dvec3(0.3, 0.05, -1.0));
    for (auto [a, b] : {std::pair{0.0, 6.0}, std::pair{0.5, 2.5}, std::pair{3.1, 3.2}}) {
        // Every point of the segment is inside the inner cone.
        for (double t : {a, 0.5 * (a + b), b})
            ASSERT_EQ(spotA(l, glm::normalize(o + t * w - l.position)), 1.0);
        const glm::dvec3 viaSpot = reference::pointEmitterSegment(spot, o, w, a, b, kMedium);
        const glm::dvec3 viaPoint = reference::pointEmitterSegment(point, o, w, a, b, kMedium);
        ASSERT_GT(viaPoint.x, 0.0);
        EXPECT_LT(relDiff(viaSpot, viaPoint), 1e-10) << a << ".." << b;
    }
}

TEST(ReferencePieces, SpotAcrossBothConesMatchesMidpointSum) {
    const scene::Light l = makeSpot(0.25, 0.5);
    const reference::SpotProfile profile = reference::SpotProfile::fromLight(l, nullptr);
    reference::PointEmitter spot{l.position, l.intensity * l.colour, reference::ProfileKind::Spot, &profile};
    // A ray through the cone below the light: it enters the outer cone, the inner cone, and leaves both.
    const glm::dvec3 o(-4.0, 1.0, 2.0);
    const glm::dvec3 w = glm::normalize(glm::dvec3(1.0, -0.05, -0.4));
    const double a = 0.0, b = 9.0;
    int inner = 0;
    for (double t = a; t <= b; t += 0.01) inner += spotA(l, glm::normalize(o + t * w - l.position)) == 1.0;
    ASSERT_GT(inner, 0) << "the ray should cross the inner cone";
    reference::SegmentStats stats;
    const glm::dvec3 ref = reference::pointEmitterSegment(spot, o, w, a, b, kMedium, &stats);
    // Midpoint, 2e6 steps: O(dt^2) ~ 1e-11 relative on the smooth pieces; the kinks at the cones (a jump
    // of A' at the inner cone only; A is C1 at the outer one) add O(dt^2) each.
    const glm::dvec3 indep = midpointAlongRay(o, w, l.position, a, b, 2'000'000,
                                              [&](const glm::dvec3& dir) { return spotA(l, dir) * l.intensity * l.colour; });
    EXPECT_GE(stats.pieces, 3);
    EXPECT_LT(relDiff(ref, indep), 1e-9);
    EXPECT_LT(stats.relError, 1e-10);
}

// Bilinear sampling written from the definition: sRGB-decode the four texels around uv, then mix.
glm::dvec3 cookieLookup(const scene::Texture& t, glm::dvec2 uv) {
    auto decode = [](std::uint8_t v) {
        const double c = v / 255.0;
        return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
    };
    auto texel = [&](int i, int j) {
        i = std::clamp(i, 0, t.width - 1);
        j = std::clamp(j, 0, t.height - 1);
        const std::size_t k = (std::size_t(j) * std::size_t(t.width) + std::size_t(i)) * 4;
        return glm::dvec3(decode(t.rgba8[k]), decode(t.rgba8[k + 1]), decode(t.rgba8[k + 2]));
    };
    const double fx = std::clamp(uv.x, 0.0, 1.0) * t.width - 0.5, fy = std::clamp(uv.y, 0.0, 1.0) * t.height - 0.5;
    const int i = int(std::floor(fx)), j = int(std::floor(fy));
    const double ax = fx - i, ay = fy - j;
    return (1 - ay) * ((1 - ax) * texel(i, j) + ax * texel(i + 1, j)) +
           ay * ((1 - ax) * texel(i, j + 1) + ax * texel(i + 1, j + 1));
}

TEST(ReferencePieces, CookieMatchesMidpointSum) {
    scene::Texture tex;
    tex.width = 5;
    tex.height = 4;
    // Deterministic pattern with strong contrast between neighbours (and one black texel).
    for (int i = 0; i < tex.width * tex.height; ++i) {
        tex.rgba8.push_back(std::uint8_t((i * 97 + 13) % 256));
        tex.rgba8.push_back(std::uint8_t((i * 57 + 200) % 256));
        tex.rgba8.push_back(std::uint8_t(i == 7 ? 0 : (i * 31 + 90) % 256));
        tex.rgba8.push_back(255);
    }
    const scene::Light l = makeSpot(0.3, 0.55);
    const reference::LinearTexture linear(tex);
    const reference::SpotProfile profile = reference::SpotProfile::fromLight(l, &linear);
    reference::PointEmitter spot{l.position, l.intensity * l.colour, reference::ProfileKind::Spot, &profile};

    // The light frame from the definition: z = spot direction, x = right (from world up), y = up.
    const glm::dvec3 z = glm::normalize(l.direction);
    const glm::dvec3 xAxis = glm::normalize(glm::cross(z, glm::dvec3(0, 1, 0)));
    const glm::dvec3 yAxis = glm::cross(xAxis, z);
    const double tanOuter = std::tan(l.outerConeAngle);
    auto profileOf = [&](const glm::dvec3& dir) {
        const double A = spotA(l, dir);
        if (A == 0.0) return glm::dvec3(0.0);
        const glm::dvec2 uv = 0.5 + 0.5 * glm::dvec2(glm::dot(dir, xAxis), glm::dot(dir, yAxis)) /
                                         (glm::dot(dir, z) * tanOuter);
        return A * cookieLookup(tex, uv) * l.intensity * l.colour;
    };
    const glm::dvec3 o(-3.0, 0.6, 1.5);
    const glm::dvec3 w = glm::normalize(glm::dvec3(1.0, 0.08, -0.6));
    const double a = 0.0, b = 8.0;
    reference::SegmentStats stats;
    const glm::dvec3 ref = reference::pointEmitterSegment(spot, o, w, a, b, kMedium, &stats);
    // Midpoint, 4e6 steps: the bilinear cookie has kinks on texel-centre lines, each costing O(dt^2).
    const glm::dvec3 indep = midpointAlongRay(o, w, l.position, a, b, 4'000'000, profileOf);
    std::printf("cookie: %d pieces, %d evaluations, estimated rel error %.2e, vs midpoint %.2e\n", stats.pieces,
                stats.evaluations, stats.relError, relDiff(ref, indep));
    EXPECT_GE(stats.pieces, 4) << "the ray should cross several texel-centre lines";
    EXPECT_LT(relDiff(ref, indep), 1e-9);
    EXPECT_LT(stats.relError, 1e-10);
}

// Independent emitter integral: midpoint rule over the rectangle (n x n cells) and along t (m steps) of
// sigma_s p L_e max(0, cos theta_e) exp(-sigma_t (t + r)) / r^2.
glm::dvec3 areaMidpoint(const scene::Light& l, const scene::Texture& tex, const glm::dvec3& o, const glm::dvec3& w,
                        double a, double b, int n, int m) {
    const double area = 4.0 * glm::length(glm::cross(l.halfU, l.halfV));
    const double dA = area / (double(n) * n), dt = (b - a) / m;
    glm::dvec3 total(0.0);
    std::vector<glm::dvec3> cellPos, cellLe;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const glm::dvec2 uv((i + 0.5) / n, (j + 0.5) / n);
            cellPos.push_back(l.position + (2 * uv.x - 1) * l.halfU + (2 * uv.y - 1) * l.halfV);
            cellLe.push_back(l.radiance * cookieLookup(tex, uv));
        }
    for (int k = 0; k < m; ++k) {
        const double t = a + (k + 0.5) * dt;
        const glm::dvec3 x = o + t * w;
        glm::dvec3 inner(0.0);
        for (std::size_t c = 0; c < cellPos.size(); ++c) {
            const double r = glm::length(x - cellPos[c]);
            const glm::dvec3 dir = (x - cellPos[c]) / r;
            const double cosE = std::max(0.0, glm::dot(l.direction, dir));
            inner += cellLe[c] * (cosE * hg(glm::dot(dir, -w), kMedium.g) * std::exp(-kMedium.sigma_t * (t + r)) / (r * r));
        }
        total += inner;
    }
    return total * (kMedium.sigma_s * dA * dt);
}

TEST(ReferencePieces, AreaLightMatchesMidpointAndConverges) {
    scene::Scene s;
    scene::Texture tex;
    tex.width = 2;
    tex.height = 2;
    tex.rgba8 = {255, 200, 120, 255, 180, 255, 90, 255, 120, 160, 255, 255, 255, 255, 255, 255};
    s.textures.push_back(tex);
    scene::Light l{.type = scene::LightType::Area,
                   .position = {0.0, 3.0, 0.0},
                   .direction = {0.0, -1.0, 0.0},
                   .halfU = {0.4, 0.0, 0.0},
                   .halfV = {0.0, 0.0, 0.3},
                   .radiance = {2.0, 1.5, 1.0},
                   .emissionTexture = 0};
    s.lights.push_back(l);
    // The ray climbs through the emitter's plane (y = 3) beside the rectangle: behind it cos theta_e < 0.
    const glm::dvec3 o(-2.0, 1.0, 4.0);
    const glm::dvec3 w = glm::normalize(glm::dvec3(1.5, 2.8, -3.0) - o);
    const double a = 0.0, b = 9.0;
    auto referenceWith = [&](int n) {
        const auto lights = reference::PreparedLights::build(s, n);
        glm::dvec3 sum(0.0);
        for (const auto& e : lights.points) sum += reference::emitterSegment(e, o, w, a, b, kMedium);
        return sum;
    };
    // Midpoint over 96 x 96 emitter cells and 2000 steps in t: O(h^2) errors of about 1e-5 relative
    // (the ray stays > 0.5 from the emitter, so the integrand varies on that scale).
    const glm::dvec3 indep = areaMidpoint(l, tex, o, w, a, b, 96, 2000);
    const glm::dvec3 ref8 = referenceWith(8);
    const glm::dvec3 ref32 = referenceWith(32);
    for (int n : {2, 4, 8, 16}) {
        std::printf("area_samples %2d: rel. difference to 32 = %.3e\n", n, relDiff(referenceWith(n), ref32));
    }
    std::printf("area_samples 8 vs midpoint: %.3e, 32 vs midpoint: %.3e\n", relDiff(ref8, indep), relDiff(ref32, indep));
    // Without the texture the emitter integrand is smooth and the product rule converges fast.
    s.lights[0].emissionTexture = -1;
    const glm::dvec3 plain32 = referenceWith(32);
    for (int n : {2, 4, 8, 16})
        std::printf("untextured, area_samples %2d: rel. difference to 32 = %.3e\n", n, relDiff(referenceWith(n), plain32));
    EXPECT_LT(relDiff(referenceWith(8), plain32), 1e-6);
    EXPECT_LT(relDiff(ref32, indep), 1e-4);
    EXPECT_LT(relDiff(ref8, indep), 1e-3);
}

TEST(ReferencePieces, DirectionalMatchesMidpointSum) {
    reference::DirectionalEmitter sun{glm::normalize(glm::dvec3(0.3, -1.0, 0.2)), glm::dvec3(3.0, 2.5, 2.0), 0};
    const glm::dvec3 w = glm::normalize(glm::dvec3(0.2, -0.1, -1.0));
    const double a = 1.5, b = 12.0;
    const glm::dvec3 ref = reference::directionalSegment(sun, w, a, b, kMedium);
    // Midpoint, 1e6 steps, of sigma_s p E exp(-sigma_t t): O(dt^2) ~ 1e-12 relative.
    const std::int64_t n = 1'000'000;
    const double dt = (b - a) / double(n);
    double sum = 0.0;
    for (std::int64_t i = 0; i < n; ++i) sum += std::exp(-kMedium.sigma_t * (a + (double(i) + 0.5) * dt));
    const glm::dvec3 indep = sun.irradiance * (kMedium.sigma_s * hg(glm::dot(sun.direction, -w), kMedium.g) * sum * dt);
    EXPECT_LT(relDiff(ref, indep), 1e-9);
}

}  // namespace
}  // namespace viz
