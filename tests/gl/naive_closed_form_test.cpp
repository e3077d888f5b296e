// raymarch's closed_form=naive (lesson 1): Sun et al.'s closed form evaluated as printed is right in a
// thin medium and fails in the stiff cases, where the stable form of airlight.glsl matches the reference.
// The failure is what the teaching mode exists to show, so it is asserted, not tolerated.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "scene/builtin_scenes.h"
#include "scene/stiff_scenes.h"
#include "technique_test_util.h"
#include "techniques/registry.h"

namespace {

class NaiveClosedFormTest : public viz::testing::TechniqueTest {
protected:
    static viz::scene::Scene stiff(const std::string& id) {
        const viz::scene::StiffCase* c = viz::scene::findStiffCase(id);
        if (!c) throw std::runtime_error("no stiff case " + id);
        return viz::scene::buildStiffScene(*c);
    }
    // 64 samples, each interval integrated with the closed form: stable (0) or naive (1).
    static viz::Settings exactSegments(bool naive) {
        return {{"samples", 64}, {"exact", 1}, {"closed_form", naive ? 1.0 : 0.0}};
    }
};

using viz::testing::relativeL2;

int nonFinite(const viz::Image& image) {
    return int(std::count_if(image.pixels.begin(), image.pixels.end(), [](float v) { return !std::isfinite(v); }));
}

}  // namespace

// sigma_t = 50 with the light 0.5 above the camera: the bracket F(A1, xi1) - F(A1, xi0) has lost every
// digit (its true value carries e^{-sigma_t (|D| - tP)}, up to e^-50), and A0 multiplies the rounding
// noise by up to e^{+25}. The reference's values are ~1e-10; the naive ones are noise of either sign.
TEST_F(NaiveClosedFormTest, FailsInAThickMediumWhereTheStableFormMatchesTheReference) {
    const viz::scene::Scene scene = stiff("extinction-50");
    const viz::FrameOutput reference = render(scene, "reference", {}, 40, 30);
    const viz::FrameOutput stable = render(scene, "raymarch", exactSegments(false), 40, 30);
    const viz::FrameOutput naive = render(scene, "raymarch", exactSegments(true), 40, 30);
    ASSERT_FALSE(reference.airlight.empty());
    ASSERT_EQ(naive.airlight.pixels.size(), reference.airlight.pixels.size());

    const double eStable = relativeL2(stable.airlight, reference.airlight);
    EXPECT_EQ(nonFinite(stable.airlight), 0);
    EXPECT_LT(eStable, 0.02);  // raymarch's stiff bound for the medium class

    // Badly wrong: most pixels more than a factor 2 off (or not finite), and the image's error huge.
    int wrong = 0;
    for (std::size_t i = 0; i < naive.airlight.pixels.size(); ++i) {
        const double n = naive.airlight.pixels[i], r = reference.airlight.pixels[i];
        if (!std::isfinite(n) || !(std::abs(n - r) <= r)) ++wrong;
    }
    const double eNaive = relativeL2(naive.airlight, reference.airlight);
    std::printf("extinction-50 relative L2: stable %.3g, naive %.3g (%d of %zu values off by more than 100%%)\n",
                eStable, eNaive, wrong, naive.airlight.pixels.size());
    EXPECT_GT(wrong, int(naive.airlight.pixels.size() / 2));
    EXPECT_TRUE(!std::isfinite(eNaive) || eNaive > 1e3);
}

// A ray exactly through the light (odd image size: the centre pixel's ray is the camera's forward axis,
// which passes through the point light): gamma = acos(1) = 0 makes A0 infinite and the bracket zero.
TEST_F(NaiveClosedFormTest, GivesNaNOnARayThroughTheLight) {
    const viz::scene::Scene scene = stiff("ray-through-light");
    const viz::FrameOutput stable = render(scene, "raymarch", exactSegments(false), 33, 25);
    const viz::FrameOutput naive = render(scene, "raymarch", exactSegments(true), 33, 25);
    EXPECT_EQ(nonFinite(stable.airlight), 0);
    const int channels = naive.airlight.channels;
    for (int c = 0; c < channels; ++c) EXPECT_FALSE(std::isfinite(naive.airlight.at(16, 12, c))) << "channel " << c;
}

// The failure is numerical, not a wrong formula: in a thin isotropic medium (grate with g = 0, sigma_t
// 0.13) the naive evaluation agrees with the stable one.
TEST_F(NaiveClosedFormTest, AgreesWithTheStableFormInAThinIsotropicMedium) {
    viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    scene.medium.g = 0.0;
    const viz::FrameOutput stable = render(scene, "raymarch", exactSegments(false), 40, 30);
    const viz::FrameOutput naive = render(scene, "raymarch", exactSegments(true), 40, 30);
    EXPECT_EQ(nonFinite(naive.airlight), 0);
    const double e = relativeL2(naive.airlight, stable.airlight);
    std::printf("grate (g = 0) naive vs stable: relative L2 %.3g\n", e);
    EXPECT_LT(e, 1e-3);
}

// Off by default, never in the quality sweep or the stiff settings, and plan() calls it a teaching mode.
TEST_F(NaiveClosedFormTest, IsAnOptInTeachingMode) {
    const auto technique = viz::makeTechnique("raymarch");
    const viz::scene::Scene scene = viz::scene::makeBuiltinScene("grate");
    viz::Settings settings = viz::completeSettings(*technique, {});
    EXPECT_EQ(settings.at("closed_form"), 0.0);
    for (const auto& q : technique->qualitySweep(false)) EXPECT_EQ(q.settings.count("closed_form"), 0u) << q.label;
    for (const auto& q : technique->qualitySweep(true)) EXPECT_EQ(q.settings.count("closed_form"), 0u) << q.label;
    EXPECT_EQ(technique->stiffSettings().count("closed_form"), 0u);

    const auto feature = [&](const viz::Settings& s) -> viz::FeaturePlan {
        for (const auto& f : technique->plan(scene, s).features)
            if (f.feature == "NAIVE_CLOSED_FORM") return f;
        ADD_FAILURE() << "no NAIVE_CLOSED_FORM feature";
        return {};
    };
    settings["exact"] = 1.0;
    EXPECT_FALSE(feature(settings).enabled);
    settings["closed_form"] = 1.0;
    const viz::FeaturePlan naive = feature(settings);
    EXPECT_TRUE(naive.enabled);
    EXPECT_NE(naive.why.find("TEACHING"), std::string::npos) << naive.why;
}
