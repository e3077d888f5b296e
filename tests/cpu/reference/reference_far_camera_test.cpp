// The reference under a camera whose zfar is far beyond the scene (public files carry zfar 1e4 to 1e6):
// its visibility search must still find the shafts. The air past a few hundred units passes on almost
// nothing (colonnade: exp(-0.11 t), 1.7e-5 past 100 units), so L_air converges as zfar grows; zfar 100
// and 1e6 must agree.
// Before the search was bounded (reference version 3) a pixel of colonnade looking out through the hall
// read 0.423, 0.428, 0.428, 0.361 and 0.595 at zfar 50, 1e2, 1e3, 1e4 and 1e6: its V samples, spread over
// [0, zfar], stepped over the hall.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "scene/builtin_scenes.h"
#include "techniques/reference/reference.h"
#include "technique_run.h"

namespace viz {
namespace {

Image airlightAt(scene::Scene s, double zfar) {
    s.camera.zfar = zfar;
    auto tech = makeReferenceTechnique();
    return viz::testing::runTechnique(*tech, s, {{"cache", 0}}, 60, 45).airlight;
}

double relativeDifference(const Image& a, const Image& b) {
    double diff = 0.0, norm = 0.0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        diff += (double(a.pixels[i]) - b.pixels[i]) * (double(a.pixels[i]) - b.pixels[i]);
        norm += double(b.pixels[i]) * b.pixels[i];
    }
    return norm > 0.0 ? std::sqrt(diff / norm) : 0.0;
}

TEST(ReferenceFarCamera, AirlightConvergesAsZfarGrowsPastTheScene) {
    scene::Scene pointGrate = scene::makeBuiltinScene("grate");
    pointGrate.lights[0].type = scene::LightType::Point;
    const std::pair<std::string, scene::Scene> cases[] = {
        {"colonnade (sun)", scene::makeBuiltinScene("colonnade")},
        {"grate (spot)", scene::makeBuiltinScene("grate")},
        {"grate (point light)", pointGrate},
    };
    for (const auto& [name, s] : cases) {
        const Image nearer = airlightAt(s, 100.0), farther = airlightAt(s, 1e6);
        double sum = 0.0;
        for (float v : nearer.pixels) sum += v;
        ASSERT_GT(sum, 0.0) << name;
        const double e = relativeDifference(farther, nearer);
        std::printf("%-20s L_air at zfar 1e6 against 100: relative L2 %.2e\n", name.c_str(), e);
        // Measured: 4.9e-5 (colonnade), 3.1e-5 (spot), 2.0e-4 (point light: the two searches sample V at
        // different points and find slightly different slivers); the version 3 search: 0.22 on colonnade.
        EXPECT_LT(e, 1e-3) << name;
    }
}

}  // namespace
}  // namespace viz
