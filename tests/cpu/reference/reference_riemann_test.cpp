// The reference against an independent dense Riemann sum of the definition of L_air, at pixels of
// `grate` whose rays cross shadow boundaries.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <thread>

#include "reference_test_util.h"
#include "scene/builtin_scenes.h"
#include "scene/camera.h"
#include "techniques/reference/reference.h"
#include "techniques/reference/ray_tracer.h"

namespace viz {
namespace {

using reference_test::hg;
using reference_test::spotA;

struct RiemannResult {
    glm::dvec3 value{0.0};
    int jumps = 0;            // visibility changes between consecutive steps
    double jumpBound = 0.0;   // sum over jumps of max(f) * (refined step): bound on their midpoint error
};

// Sub-steps of the two steps on either side of a visibility jump (see the comment in the test).
constexpr int kJumpRefinement = 10'000;

// Midpoint rule in t with n steps over [0, d] of
//   sigma_s p(cos) I colour A_spot exp(-sigma_t r) / r^2 V exp(-sigma_t t)   (point and spot lights),
//   sigma_s p(cos) I colour V exp(-sigma_t t)                                 (directional lights),
// every factor written from the definition (no airlight.h), V by an Embree occlusion ray per step.
// Where V differs between two consecutive steps, those two steps are recomputed with kJumpRefinement
// midpoint sub-steps each.
RiemannResult riemann(const scene::Scene& s, const reference::RayTracer& tracer, const glm::dvec3& o,
                      const glm::dvec3& w, double d, std::int64_t n) {
    const double dt = d / double(n);
    const double sigma_s = s.medium.sigma_s, sigma_t = s.medium.sigma_t(), g = s.medium.g;
    const int threads = 2;
    std::vector<RiemannResult> parts(threads);
    std::vector<std::thread> pool;
    for (int k = 0; k < threads; ++k) {
        pool.emplace_back([&, k] {
            const std::int64_t begin = n * k / threads, end = n * (k + 1) / threads;
            for (const scene::Light& l : s.lights) {
                const glm::dvec3 P = l.position;
                const glm::dvec3 travel = glm::normalize(l.direction);
                // f(t) V(t) for one light: the integrand of the definition.
                auto integrand = [&](double t, int& V) {
                    const glm::dvec3 x = o + t * w;
                    if (l.type == scene::LightType::Directional) {
                        // E = I colour, no attenuation on the light side; p from the travel direction.
                        V = tracer.occludedRay(x, -travel) ? 0 : 1;
                        return sigma_s * hg(glm::dot(travel, -w), g) * l.intensity * std::exp(-sigma_t * t);
                    }
                    const double r = glm::length(x - P);
                    const glm::dvec3 dir = (x - P) / r;
                    const double A = l.type == scene::LightType::Spot ? spotA(l, dir) : 1.0;
                    V = tracer.occludedSegment(x, P) ? 0 : 1;
                    return sigma_s * hg(glm::dot(dir, -w), g) * l.intensity * A * std::exp(-sigma_t * r) /
                           (r * r) * std::exp(-sigma_t * t);
                };
                // Midpoint sum of one step [t - dt/2, t + dt/2] with kJumpRefinement sub-steps.
                auto refinedStep = [&](double t) {
                    const double h = dt / kJumpRefinement;
                    double sum = 0.0;
                    int V = 0;
                    for (int j = 0; j < kJumpRefinement; ++j) {
                        const double f = integrand(t - 0.5 * dt + (j + 0.5) * h, V);
                        sum += V * f;
                    }
                    return sum * h;
                };
                // Sums of 1000 terms are added to the total, so rounding stays near 1e-13.
                double total = 0.0, block = 0.0;
                int previousV = -1;
                double previousF = 0.0, previousTerm = 0.0;
                bool previousRefined = false;
                for (std::int64_t i = begin; i < end; ++i) {
                    const double t = (double(i) + 0.5) * dt;
                    int V = 0;
                    const double f = integrand(t, V);
                    double term = V * f * dt;
                    if (previousV >= 0 && V != previousV) {
                        ++parts[std::size_t(k)].jumps;
                        parts[std::size_t(k)].jumpBound += std::max(f, previousF) * l.colour.x * dt / kJumpRefinement;
                        // Replace the previous step's term by its refined value (unless already refined),
                        // and refine this one.
                        if (!previousRefined) block += refinedStep(t - dt) - previousTerm;
                        term = refinedStep(t);
                        previousRefined = true;
                    } else {
                        previousRefined = false;
                    }
                    previousV = V;
                    previousF = f;
                    previousTerm = term;
                    block += term;
                    if ((i - begin) % 1000 == 999) {
                        total += block;
                        block = 0.0;
                    }
                }
                parts[std::size_t(k)].value += (total + block) * l.colour;
            }
        });
    }
    for (auto& t : pool) t.join();
    RiemannResult sum;
    for (const auto& p : parts) {
        sum.value += p.value;
        sum.jumps += p.jumps;
        sum.jumpBound += p.jumpBound;
    }
    return sum;
}

// Runs the reference on `s` at 32x24 and compares L_air with the Riemann sum at the `count` pixels of
// the left half whose rays cross the most shadow boundaries.
void compareWithRiemann(const scene::Scene& s, int count) {
    for (const auto& l : s.lights) {
        ASSERT_NE(l.type, scene::LightType::Area) << "the Riemann sum below has no emitter integral";
    }
    const int W = 32, H = 24;
    auto tech = makeReferenceTechnique();
    FrameInput in;
    in.scene = &s;
    in.width = W;
    in.height = H;
    setRunSettings(in, completeSettings(*tech, {{"cache", 0}, {"threads", 2}}));
    const FrameOutput out = tech->run(in);
    ASSERT_FALSE(out.airlight.empty());
    const Image* transitions = nullptr;
    for (const auto& im : out.intermediates)
        if (im.id == "reference.transitions") transitions = im.image.get();
    ASSERT_NE(transitions, nullptr);

    // The three pixels whose rays cross the most shadow boundaries (row-major order breaks ties), from
    // the left half only: grate is mirror-symmetric about the image centre.
    std::vector<std::pair<float, int>> ranked;
    for (int i = 0; i < W * H; ++i)
        if (i % W < W / 2) ranked.emplace_back(-transitions->pixels[std::size_t(i)], i);
    std::stable_sort(ranked.begin(), ranked.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    ASSERT_GE(-ranked[std::size_t(count - 1)].first, 2.0f) << "the scene should have rays crossing several shadow boundaries";

    const reference::RayTracer tracer(s);
    // Why this reaches 1e-6. The midpoint rule is O(dt^2) on the smooth pieces: with dt = d / 1e7 that
    // is far below 1e-12 relative. The error comes from the steps containing a visibility jump: such a
    // step is counted wholly lit or wholly dark, an error of up to f(jump) dt / 2 each. Near the grate
    // the integrand is ~10x its mean along the ray, so with ~10 jumps per ray plain 1e7 steps leave
    // errors of a few 1e-6 (measured: 1.2e-6 to 2.6e-6 on grate). The two steps around each jump are
    // therefore redone with 1e4 sub-steps, which bounds the jump error by sum f dt / 1e4, ~1e-9
    // relative. The bound is computed (jumpBound) and checked below.
    const std::int64_t steps = 10'000'000;
    for (int k = 0; k < count; ++k) {
        const int x = ranked[std::size_t(k)].second % W, y = ranked[std::size_t(k)].second / W;
        const glm::dvec3 o = s.camera.position;
        const glm::dvec3 w = scene::pixelRay(s.camera, W, H, x, y);
        const reference::Hit hit = tracer.intersect(o, w, s.camera.zfar);
        const double d = hit.found ? std::min(hit.t, s.camera.zfar) : s.camera.zfar;
        const RiemannResult r = riemann(s, tracer, o, w, d, steps);
        SCOPED_TRACE("pixel (" + std::to_string(x) + ", " + std::to_string(y) + "), jumps " +
                     std::to_string(r.jumps));
        EXPECT_GE(r.jumps, 2);
        EXPECT_LT(r.jumpBound, 1e-7 * r.value.x) << "the steps do not resolve the jumps to 1e-7";
        std::printf("pixel (%d, %d): %d jumps, L_air %.9g, relative difference %.2e, jump bound %.1e\n", x, y,
                    r.jumps, r.value.x, std::abs(out.airlight.at(x, y, 0) - r.value.x) / r.value.x,
                    r.jumpBound / r.value.x);
        for (int c = 0; c < 3; ++c) {
            const double ref = out.airlight.at(x, y, c);
            ASSERT_GT(r.value[c], 0.0);
            EXPECT_NEAR(ref, r.value[c], 1e-6 * r.value[c]) << "channel " << c;
        }
    }
}

TEST(ReferenceRiemann, GrateSpotMatchesDenseMidpointSumAtShadowBoundaries) {
    compareWithRiemann(scene::makeBuiltinScene("grate"), 3);
}

TEST(ReferenceRiemann, ColonnadeSunMatchesDenseMidpointSumAtShadowBoundaries) {
    compareWithRiemann(scene::makeBuiltinScene("colonnade"), 1);
}

}  // namespace
}  // namespace viz
