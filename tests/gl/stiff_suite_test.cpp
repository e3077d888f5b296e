// The stiff and extreme cases (scene/stiff_scenes.h) against every GPU technique at the suite's small
// size: finite, non-negative output and an error within each technique's declared bound. Also checks
// that the suite itself catches a technique that writes NaN, and judges refusals by the declarations.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

#include "gl/gl_test_fixture.h"
#include "report/stiff_suite.h"
#include "scene/stiff_scenes.h"
#include "technique_run.h"
#include "techniques/registry.h"

namespace viz {
namespace {

// The reference's L_air per case, computed once per test process.
const Image& referenceFor(const scene::StiffCase& c, const scene::Scene& s) {
    static std::map<std::string, Image> cache;
    auto it = cache.find(c.id);
    if (it == cache.end()) {
        auto reference = makeTechnique("reference");
        it = cache.emplace(c.id, testing::runTechnique(*reference, s, {}, c.width, c.height).airlight).first;
    }
    return it->second;
}

class StiffSuite : public gl::GlTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(StiffSuite, EveryTechniqueStaysFiniteAndWithinItsDeclaredBound) {
    const scene::StiffCase& c = *scene::findStiffCase(GetParam());
    const scene::Scene s = scene::buildStiffScene(c);
    const Image& reference = referenceFor(c, s);
    for (const std::string& id : techniqueIds()) {
        if (id == "reference") continue;
        auto technique = makeTechnique(id);
        const report::StiffOutcome o = report::runStiffCase(*technique, c, s, reference);
        EXPECT_TRUE(o.passed) << id << " on " << c.id << ": " << o.verdict;
        std::printf("  %-22s %-9s %s\n", c.id.c_str(), id.c_str(), o.verdict.c_str());
        if (o.ran) {
            EXPECT_EQ(o.error.nanPixels + o.error.infPixels + o.error.negativePixels, 0u) << id;
        }
    }
}

// A low sun grazing the hall's one-sided ceiling leaves the interior dark in the reference. A dense march
// and the slices' planes sample the air just under the ceiling, where the nearest shadow-map texel's
// depth (stored at the texel's centre) and the surface bias of two texels used to read as lit: a band of
// light under the ceiling. Measured as the L_air these techniques add on the pixels the reference has
// dark (below 1e-3 of its brightest), against the reference's total.
class GrazingSun : public gl::GlTest {};

TEST_F(GrazingSun, LeaksNoLightUnderTheCeiling) {
    const scene::StiffCase& c = *scene::findStiffCase("sun-grazing-ceiling");
    const scene::Scene s = scene::buildStiffScene(c);
    const int w = 160, h = 120;
    auto reference = makeTechnique("reference");
    const Image ref = testing::runTechnique(*reference, s, {}, w, h).airlight;
    double brightest = 0.0, total = 0.0;
    for (std::size_t i = 0; i < ref.pixels.size(); i += ref.channels) {
        brightest = std::max(brightest, double(ref.pixels[i]));
        total += ref.pixels[i];
    }
    ASSERT_GT(total, 0.0);
    const std::vector<std::pair<std::string, Settings>> runs = {{"raymarch", {{"samples", 1024}}}, {"slices", {}}};
    for (const auto& [id, settings] : runs) {
        auto technique = makeTechnique(id);
        const Image img = testing::runTechnique(*technique, s, settings, w, h).airlight;
        double leaked = 0.0;
        int dark = 0, lit = 0;
        for (std::size_t i = 0; i < ref.pixels.size(); i += ref.channels) {
            if (ref.pixels[i] > 1e-3 * brightest) continue;
            ++dark;
            const double extra = double(img.pixels[i]) - ref.pixels[i];
            leaked += std::max(0.0, extra);
            lit += extra > 1e-3 * brightest;
        }
        std::printf("%s: %d of %d dark pixels lit, leaked L_air %.3g of the reference's total\n", id.c_str(), lit,
                    dark, leaked / total);
        EXPECT_GT(dark, int(ref.pixels.size() / ref.channels / 3)) << id;
        EXPECT_LT(leaked / total, 1e-3) << id;
        EXPECT_LT(lit, dark / 200) << id;
    }
}

std::vector<std::string> caseIds() {
    std::vector<std::string> ids;
    for (const scene::StiffCase& c : scene::stiffCases()) ids.push_back(c.id);
    return ids;
}

INSTANTIATE_TEST_SUITE_P(Cases, StiffSuite, ::testing::ValuesIn(caseIds()),
                         [](const ::testing::TestParamInfo<std::string>& caseParam) {
                             std::string name;
                             for (char ch : caseParam.param) name += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
                             return name;
                         });

// A test double: wraps raymarch and writes one NaN pixel (or refuses, or declares nothing).
class BrokenTechnique final : public Technique {
public:
    enum class Fault { WritesNaN, WritesNegative, Refuses, DeclaresNothing };
    explicit BrokenTechnique(Fault fault) : mFault(fault), mInner(makeTechnique("raymarch")) {}
    std::string id() const override { return "broken"; }
    std::string description() const override { return "raymarch with a fault injected"; }
    const std::vector<StageInfo>& stages() const override { return mInner->stages(); }
    const std::vector<ParamInfo>& params() const override { return mInner->params(); }
    bool needsGl() const override { return true; }
    Plan plan(const scene::Scene& s, const Settings& settings) const override { return mInner->plan(s, settings); }
    FrameOutput run(const FrameInput& input) override {
        if (mFault == Fault::Refuses) throw InputError("broken: this case class is not handled");
        FrameOutput out = mInner->run(input);
        if (mFault == Fault::WritesNaN) out.airlight.at(3, 2, 1) = std::numeric_limits<float>::quiet_NaN();
        if (mFault == Fault::WritesNegative) out.airlight.at(4, 4, 0) = -1e-3f;
        return out;
    }
    Settings stiffSettings() const override { return mInner->stiffSettings(); }
    std::optional<StiffBound> stiffBound(const std::string& caseClass) const override {
        if (mFault == Fault::DeclaresNothing || mFault == Fault::Refuses) return std::nullopt;
        return mInner->stiffBound(caseClass);
    }

private:
    Fault mFault;
    std::unique_ptr<Technique> mInner;
};

class StiffSuiteJudging : public gl::GlTest {};

TEST_F(StiffSuiteJudging, CatchesATechniqueThatWritesNaNOrNegativeValues) {
    const scene::StiffCase& c = *scene::findStiffCase("intensity-1e7");
    const scene::Scene s = scene::buildStiffScene(c);
    BrokenTechnique nan(BrokenTechnique::Fault::WritesNaN);
    const report::StiffOutcome o = report::runStiffCase(nan, c, s, referenceFor(c, s));
    EXPECT_FALSE(o.passed);
    EXPECT_EQ(o.error.nanPixels, 1u);
    EXPECT_NE(o.verdict.find("1 NaN"), std::string::npos) << o.verdict;
    BrokenTechnique negative(BrokenTechnique::Fault::WritesNegative);
    const report::StiffOutcome n = report::runStiffCase(negative, c, s, referenceFor(c, s));
    EXPECT_FALSE(n.passed);
    EXPECT_EQ(n.error.negativePixels, 1u);
}

TEST_F(StiffSuiteJudging, RefusalsPassOnlyWhereNoBoundIsDeclared) {
    const scene::StiffCase& c = *scene::findStiffCase("hg-0.99");
    const scene::Scene s = scene::buildStiffScene(c);
    BrokenTechnique refuses(BrokenTechnique::Fault::Refuses);
    const report::StiffOutcome r = report::runStiffCase(refuses, c, s, referenceFor(c, s));
    EXPECT_FALSE(r.ran);
    EXPECT_TRUE(r.passed) << r.verdict;
    // Running without declaring a bound is not a pass: the technique must refuse or promise something.
    BrokenTechnique silent(BrokenTechnique::Fault::DeclaresNothing);
    const report::StiffOutcome q = report::runStiffCase(silent, c, s, referenceFor(c, s));
    EXPECT_TRUE(q.ran);
    EXPECT_FALSE(q.passed);
}

TEST_F(StiffSuiteJudging, TheRayThroughTheLightLeavesOutOnlyTheLightsPixel) {
    const scene::StiffCase& c = *scene::findStiffCase("ray-through-light");
    const scene::Scene s = scene::buildStiffScene(c);
    const Image mask = report::stiffExclusionMask(c, s);
    // The light projects onto the centre pixel of the odd-sized image: it and its 8 neighbours within
    // 1.5 pixels are excluded, nothing else.
    int excluded = 0;
    for (int y = 0; y < mask.height; ++y)
        for (int x = 0; x < mask.width; ++x) excluded += mask.at(x, y) != 0.0f;
    EXPECT_EQ(excluded, 9);
    EXPECT_NE(mask.at(c.width / 2, c.height / 2), 0.0f);
}

}  // namespace
}  // namespace viz
