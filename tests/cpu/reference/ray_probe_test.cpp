// The ray inspector's ground truth for one pixel agrees with the full-frame reference at that pixel,
// and its integrand curve integrates to the same L_air.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/builtin_scenes.h"
#include "technique_run.h"
#include "techniques/reference/ray_probe.h"
#include "techniques/reference/reference.h"

namespace viz::reference {
namespace {

TEST(RayProbe, MatchesTheFullFrameReferenceAtThePixel) {
    const scene::Scene scene = scene::makeBuiltinScene("grate");
    auto reference = makeReferenceTechnique();
    const FrameOutput frame = testing::runTechnique(*reference, scene, {{"cache", 0}}, 40, 30);
    for (const glm::ivec2 p : {glm::ivec2(20, 8), glm::ivec2(12, 20), glm::ivec2(33, 26), glm::ivec2(0, 0)}) {
        const RayProbe probe = probePixel(scene, 40, 30, p.x, p.y);
        for (int c = 0; c < 3; ++c) {
            const double full = frame.airlight.at(p.x, p.y, c);
            EXPECT_NEAR(probe.airlight[c], full, 1e-6 * std::abs(full) + 1e-12) << p.x << "," << p.y;
        }
        // Per-light shares add up; intervals are sorted and inside [0, d].
        glm::dvec3 shares(0.0);
        for (const ProbeLight& l : probe.lights) {
            shares += l.airlight;
            for (std::size_t i = 0; i < l.lit.size(); ++i) {
                EXPECT_GE(l.lit[i].a, 0.0);
                EXPECT_LE(l.lit[i].b, probe.d * (1.0 + 1e-12));
                if (i > 0) {
                    EXPECT_GT(l.lit[i].a, l.lit[i - 1].b);
                }
            }
        }
        EXPECT_NEAR(shares.x, probe.airlight.x, 1e-12 + 1e-9 * probe.airlight.x);
    }
}

TEST(RayProbe, TheIntegrandCurveIntegratesToTheSameAirlight) {
    const scene::Scene scene = scene::makeBuiltinScene("colonnade");  // a sun: a smooth, bounded integrand
    ProbeOptions options;
    options.curvePoints = 20000;
    const RayProbe probe = probePixel(scene, 40, 30, 14, 10, options);
    ASSERT_GT(probe.airlight.y, 0.0);
    double sum = 0.0;
    for (const glm::dvec3& v : probe.integrand) sum += v.y * probe.d / double(probe.integrand.size());
    EXPECT_NEAR(sum / probe.airlight.y, 1.0, 0.01);
    ASSERT_EQ(probe.lights.size(), 1u);
    EXPECT_FALSE(probe.lights[0].lit.empty());
}

}  // namespace
}  // namespace viz::reference
