// gl::runThroughputProbe does the work it says it times, checked per pixel against closed forms: both
// arithmetic passes give the exact value of their chains on every pixel (so the fragment pass covers the
// image once and runs the same loop as the compute pass), the blending passes sum every layer on every
// pixel, and the triangle grid covers every pixel exactly once (no gap, no overlap). Odd sizes and a cell
// that does not divide them. Options out of range are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "gl/gl_test_fixture.h"
#include "gl/throughput_probe.h"

namespace viz::testing {
namespace {

class ThroughputProbeTest : public gl::GlTest {};

TEST_F(ThroughputProbeTest, EveryPassDoesItsWorkOnEveryPixel) {
    gl::ProbeOptions o;
    o.width = 67;
    o.height = 45;
    o.iterations = 37;
    o.layers = 5;
    o.cellPixels = 3;
    o.runs = 2;
    const gl::ProbeResult r = gl::runThroughputProbe(o, true);
    ASSERT_EQ(r.passes.size(), 5u);
    ASSERT_EQ(r.images.size(), 5u);
    const char* ids[5] = {"compute_alu", "fragment_alu", "blend_rgba32f", "blend_rgba16f", "triangles"};
    for (int i = 0; i < 5; ++i) {
        const gl::ProbePass& p = r.passes[std::size_t(i)];
        EXPECT_EQ(p.id, ids[i]);
        EXPECT_GE(p.milliseconds, 0.0) << p.id;
        EXPECT_LE(p.minMilliseconds, p.milliseconds) << p.id;
        EXPECT_GE(p.maxMilliseconds, p.milliseconds) << p.id;
        const Image& image = r.images[std::size_t(i)];
        ASSERT_EQ(image.width, o.width) << p.id;
        ASSERT_EQ(image.height, o.height) << p.id;
    }
    int wrong = 0;
    for (int row = 0; row < o.height; ++row)
        for (int x = 0; x < o.width; ++x) {
            const int y = o.height - 1 - row;  // readTexture puts GL's top row first
            for (int c = 0; c < 4; ++c) {
                const float alu = gl::probeAluExpected(x, y, c, o.iterations);
                wrong += r.images[0].at(x, row, c) != alu;  // compute
                wrong += r.images[1].at(x, row, c) != alu;  // fragment
                wrong += r.images[2].at(x, row, c) != float(o.layers) / 256.0f;
                wrong += r.images[3].at(x, row, c) != float(o.layers) / 256.0f;
                wrong += r.images[4].at(x, row, c) != 1.0f;  // covered once
            }
        }
    EXPECT_EQ(wrong, 0);
    // The closed form is not the trivial one: the chains moved (37 steps of 1/1024 on each of four).
    EXPECT_EQ(gl::probeAluExpected(0, 0, 3, 37), (1536.0f + 148.0f) / 1024.0f);
    // The counts the rates divide: the grid's cells round up (23 x 15 cells of 3 px over 67 x 45).
    EXPECT_EQ(r.find("triangles")->work, 2.0 * 23 * 15);
    EXPECT_EQ(r.find("blend_rgba32f")->work, 67.0 * 45 * 5);
}

// The quick ratio a report and a bench measure first: the two arithmetic passes alone (still exact on
// every pixel), their steps raised until the compute pass is long enough to time or the steps reach
// their limit, and a line that explains the ratio only where it handicaps the fragment-shaded passes.
TEST_F(ThroughputProbeTest, TheArithmeticRatioRunsTheTwoArithmeticPassesAndExplainsALargeRatio) {
    gl::ProbeOptions o;
    o.width = 19, o.height = 7, o.iterations = 11, o.runs = 1, o.arithmeticOnly = true;
    const gl::ProbeResult r = gl::runThroughputProbe(o, true);
    ASSERT_EQ(r.passes.size(), 2u);
    ASSERT_EQ(r.images.size(), 2u);
    int wrong = 0;
    for (int row = 0; row < o.height; ++row)
        for (int x = 0; x < o.width; ++x)
            for (int c = 0; c < 4; ++c)
                for (const Image& image : r.images)
                    wrong += image.at(x, row, c) != gl::probeAluExpected(x, o.height - 1 - row, c, o.iterations);
    EXPECT_EQ(wrong, 0);

    const gl::ArithmeticRatio ratio = gl::measureArithmeticRatio();
    EXPECT_TRUE(std::isfinite(ratio.fragmentOverCompute));
    EXPECT_GT(ratio.fragmentOverCompute, 0.0);
    EXPECT_GE(ratio.iterations, 64);
    EXPECT_LE(ratio.iterations, 4096);
    EXPECT_TRUE(ratio.computeMilliseconds >= 0.5 || ratio.iterations == 4096)
        << ratio.computeMilliseconds << " ms at " << ratio.iterations << " steps";
    // Framebuffer and blending as a technique expects them after it.
    GLint drawFramebuffer = -1;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer);
    EXPECT_EQ(drawFramebuffer, 0);
    EXPECT_FALSE(glIsEnabled(GL_BLEND));

    const std::string large = gl::describeArithmeticRatio({32.4, 1.0, 32.4, 4096});
    EXPECT_NE(large.find("32.4x as long in a fragment shader"), std::string::npos) << large;
    EXPECT_NE(large.find("slices' planes, polyvol's volume"), std::string::npos) << large;
    const std::string even = gl::describeArithmeticRatio({0.99, 6.0, 5.94, 64});
    EXPECT_NE(even.find("0.99x as long"), std::string::npos) << even;
    EXPECT_EQ(even.find("slices"), std::string::npos) << even;
}

TEST_F(ThroughputProbeTest, OptionsOutOfRangeAreRefused) {
    gl::ProbeOptions o;
    o.width = 8, o.height = 8, o.runs = 1;
    for (auto change : {+[](gl::ProbeOptions& p) { p.iterations = 4097; }, +[](gl::ProbeOptions& p) { p.layers = 0; },
                        +[](gl::ProbeOptions& p) { p.cellPixels = 65; }, +[](gl::ProbeOptions& p) { p.width = 0; },
                        +[](gl::ProbeOptions& p) { p.runs = 0; }}) {
        gl::ProbeOptions bad = o;
        change(bad);
        EXPECT_THROW(gl::runThroughputProbe(bad), std::invalid_argument);
    }
}

}  // namespace
}  // namespace viz::testing
