// polyvol under a spot's cookie: pieces whose cookie colour agrees are integrated as one run, and in the
// penumbra the segment integral carries A_spot (its lobe) under a cookie as it does without one. A cookie
// of one colour must then leave the image and the number of segment integrals as they are without a
// cookie: a property that needs no second implementation to check it. The coloured cookie against the
// reference is MatchesTheReferenceUnderAColouredCookie (polyvol_test.cpp).
#include <gtest/gtest.h>

#include <cstdio>
#include <optional>

#include "gl/work_counters.h"
#include "polyvol_test_util.h"
#include "render/host_device.h"
#include "scene/builtin_scenes.h"

namespace viz::testing {
namespace {

class PolyvolCookieTest : public PolyvolTest {
protected:
    void TearDown() override {
        gl::WorkCounters::setEnabled(false);
        PolyvolTest::TearDown();
    }
};

std::uint64_t segmentIntegrals(const FrameOutput& out) {
    for (const StageTiming& s : out.timing.stages)
        if (s.stage == "polyvol.volume" && s.work.size() == std::size_t(gl::kWorkCounts))
            return s.work[render::hd::kWorkClosedFormSegments];
    ADD_FAILURE() << "no counts for polyvol.volume";
    return 0;
}

// grate's spot (an inner and an outer cone: a penumbra between them) with a white cookie: every texel
// decodes to 1, so every piece of a part has the light's own colour.
TEST_F(PolyvolCookieTest, ACookieOfOneColourIsOneRunAndChangesNothing) {
    const scene::Scene plain = scene::makeBuiltinScene("grate");
    scene::Scene white = plain;
    scene::Texture cookie;
    cookie.name = "white";
    cookie.width = cookie.height = 16;
    cookie.rgba8.assign(std::size_t(16 * 16 * 4), 255);
    white.textures.push_back(cookie);
    int spots = 0;
    for (scene::Light& light : white.lights)
        if (light.type == scene::LightType::Spot) {
            light.cookie = int(white.textures.size()) - 1;
            ++spots;
        }
    ASSERT_EQ(spots, 1);

    const Settings settings{{"shadow_map", 256}};
    gl::WorkCounters::setEnabled(true);
    const FrameOutput without = render(plain, "polyvol", settings, 80, 60);
    const FrameOutput with = render(white, "polyvol", settings, 80, 60);
    ASSERT_TRUE(allFinite(with.airlight));
    const double e = relativeL2(with.airlight, without.airlight);
    const std::uint64_t segmentsWithout = segmentIntegrals(without), segmentsWith = segmentIntegrals(with);
    std::printf("grate, white cookie against none: relative L2 %.3g, segment integrals %llu against %llu\n", e,
                static_cast<unsigned long long>(segmentsWith), static_cast<unsigned long long>(segmentsWithout));
    // The pieces once took A_spot at their middles in the penumbra and were integrated one by one: the
    // image was then 4.4e-4 away and took 8.3 times the segment integrals (126,545 against 15,329).
    EXPECT_LT(e, 1e-5);
    EXPECT_GT(segmentsWithout, 0u);
    EXPECT_EQ(segmentsWith, segmentsWithout);
}

}  // namespace
}  // namespace viz::testing
