// Temporal error (report/temporal_error.h) on constructed sequences whose answers are known: constant
// error scores exactly zero, an error alternating +e/-e scores e, the reference scores zero against
// itself, and NaN or Inf frames are counted and left out, never propagated.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "report/error_images.h"
#include "report/temporal_error.h"

namespace viz::report {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// A reference sequence that changes from frame to frame (a moving shaft): dyadic values, so that
// reference + error is exact in float and the error of every frame is exactly the one added.
std::vector<Image> movingReference(int w, int h, int frames, int channels = 3) {
    std::vector<Image> out;
    for (int t = 0; t < frames; ++t) {
        Image image(w, h, channels);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                for (int c = 0; c < channels; ++c)
                    image.at(x, y, c) = 0.5f + 0.125f * float((x + 2 * y + 3 * t + c) % 8);
        out.push_back(image);
    }
    return out;
}

// reference[t] + error(x, y, t) in every channel.
template <typename F>
std::vector<Image> withError(const std::vector<Image>& reference, F error) {
    std::vector<Image> out = reference;
    for (std::size_t t = 0; t < out.size(); ++t)
        for (int y = 0; y < out[t].height; ++y)
            for (int x = 0; x < out[t].width; ++x)
                for (int c = 0; c < out[t].channels; ++c) out[t].at(x, y, c) += error(x, y, int(t));
    return out;
}

double referenceMean(const std::vector<Image>& reference) {
    double sum = 0.0, count = 0.0;
    for (const Image& image : reference)
        for (float v : image.pixels) sum += v, count += 1.0;
    return sum / count;
}

TEST(TemporalError, ConstantErrorScoresExactlyZero) {
    const std::vector<Image> reference = movingReference(16, 12, 6);
    // Large and different per pixel, but the same in every frame: wrong but stable.
    const std::vector<Image> test = withError(reference, [](int x, int y, int) { return 0.25f * float((x * y) % 5) - 0.5f; });
    const TemporalMetrics m = temporalMetrics(test, reference);
    EXPECT_EQ(m.frames, 6);
    EXPECT_EQ(m.temporalRms, 0.0);
    EXPECT_EQ(m.worstFlicker, 0.0);
    for (float f : m.flicker.pixels) ASSERT_EQ(f, 0.0f);
    for (std::size_t t = 1; t < m.frameTemporal.size(); ++t) EXPECT_EQ(m.frameTemporal[t], 0.0) << t;
    EXPECT_GT(m.meanFrameError, 0.1);  // the error itself is large
    EXPECT_TRUE(m.complete());
}

TEST(TemporalError, AlternatingErrorScoresE) {
    const float e = 0.125f;
    const std::vector<Image> reference = movingReference(10, 10, 7);
    const std::vector<Image> test = withError(reference, [e](int, int, int t) { return t % 2 == 0 ? e : -e; });
    const TemporalMetrics m = temporalMetrics(test, reference);
    // Per pixel, in the images' units: e exactly (d = +-2e, halved).
    for (float f : m.flicker.pixels) ASSERT_FLOAT_EQ(f, e);
    // The figures are relative to the reference's mean.
    const double mean = referenceMean(reference);
    EXPECT_NEAR(m.referenceMean, mean, 1e-12);
    EXPECT_NEAR(m.temporalRms, e / mean, 1e-12);
    EXPECT_NEAR(m.worstFlicker, e / mean, 1e-12);
    EXPECT_TRUE(std::isnan(m.frameTemporal[0]));
    for (std::size_t t = 1; t < m.frameTemporal.size(); ++t) EXPECT_NEAR(m.frameTemporal[t], e / mean, 1e-12);
}

TEST(TemporalError, AlternatingErrorScoresEAgainstAUnitReference) {
    // With mean(R) = 1 the relative figures are e itself.
    std::vector<Image> reference(4, Image(5, 3, 1));
    for (Image& image : reference)
        for (float& v : image.pixels) v = 1.0f;
    const float e = 0.03125f;
    const TemporalMetrics m = temporalMetrics(withError(reference, [e](int, int, int t) { return t % 2 ? -e : e; }), reference);
    EXPECT_DOUBLE_EQ(m.temporalRms, e);
    EXPECT_DOUBLE_EQ(m.worstFlicker, e);
}

TEST(TemporalError, SmallJumpingErrorScoresAboveLargeStableError) {
    const std::vector<Image> reference = movingReference(12, 8, 8);
    const TemporalMetrics stable = temporalMetrics(withError(reference, [](int, int, int) { return 0.5f; }), reference);
    const TemporalMetrics jumping =
        temporalMetrics(withError(reference, [](int x, int, int t) { return (x + t) % 2 ? 0.015625f : -0.015625f; }), reference);
    EXPECT_GT(stable.meanFrameError, 10.0 * jumping.meanFrameError);
    EXPECT_EQ(stable.temporalRms, 0.0);
    EXPECT_GT(jumping.temporalRms, 0.01);
}

TEST(TemporalError, ReferenceAgainstItselfScoresZero) {
    const std::vector<Image> reference = movingReference(9, 7, 5);
    const TemporalMetrics m = temporalMetrics(reference, reference);
    EXPECT_EQ(m.meanFrameError, 0.0);
    EXPECT_EQ(m.temporalRms, 0.0);
    EXPECT_EQ(m.worstFlicker, 0.0);
    for (float f : m.flicker.pixels) ASSERT_EQ(f, 0.0f);
}

TEST(TemporalError, WorstFlickerIsThe99thPercentileOverPixels) {
    // 100 pixels, two of which flicker by e: the RMS is diluted, the percentile finds them.
    std::vector<Image> reference(6, Image(10, 10, 1));
    for (Image& image : reference)
        for (float& v : image.pixels) v = 1.0f;
    const float e = 0.25f;
    const TemporalMetrics m = temporalMetrics(
        withError(reference, [e](int x, int y, int t) { return (y == 0 && x < 2) ? (t % 2 ? -e : e) : 0.0f; }), reference);
    EXPECT_DOUBLE_EQ(m.worstFlicker, e);
    EXPECT_NEAR(m.temporalRms, e * std::sqrt(2.0 / 100.0), 1e-12);
    EXPECT_FLOAT_EQ(m.flicker.at(0, 0), e);
    EXPECT_EQ(m.flicker.at(5, 5), 0.0f);
}

TEST(TemporalError, NanFramesAreCountedNotPropagated) {
    const std::vector<Image> reference0 = movingReference(6, 4, 5);
    std::vector<Image> test = withError(reference0, [](int, int, int t) { return t % 2 ? 0.0625f : -0.0625f; });
    std::vector<Image> reference = reference0;
    test[2].at(1, 1, 0) = kNaN;   // the technique's frame 2
    test[2].at(2, 0, 2) = kInf;
    reference[3].at(0, 0, 1) = kNaN;  // the reference's frame 3
    const TemporalMetrics m = temporalMetrics(test, reference);
    EXPECT_EQ(m.nonFiniteTestPixels, 2u);
    EXPECT_EQ(m.nonFiniteReferencePixels, 1u);
    EXPECT_EQ(m.framesWithoutError, 2u);  // frames 2 and 3 have no relative L2
    EXPECT_EQ(m.frameError.size(), 5u);
    EXPECT_TRUE(std::isnan(m.frameError[2]));
    EXPECT_TRUE(std::isfinite(m.frameError[1]));
    // Each bad pixel-frame removes the differences on either side of it: 3 x 2.
    EXPECT_EQ(m.excludedDifferences, 6u);
    EXPECT_FALSE(m.complete());
    // Every figure stays finite and the remaining differences still score the alternating error.
    const double mean = m.referenceMean;
    EXPECT_TRUE(std::isfinite(mean));
    EXPECT_NEAR(m.temporalRms, 0.0625 / mean, 1e-12);
    EXPECT_NEAR(m.worstFlicker, 0.0625 / mean, 1e-12);
    EXPECT_TRUE(std::isfinite(m.meanFrameError));
    for (float f : m.flicker.pixels) EXPECT_FLOAT_EQ(f, 0.0625f);
    EXPECT_EQ(m.pixelsWithoutDifference, 0u);
}

TEST(TemporalError, APixelNeverFiniteIsNaNInTheFlickerImageOnlyAndCounted) {
    const std::vector<Image> reference = movingReference(4, 4, 4);
    std::vector<Image> test = reference;
    for (Image& frame : test) frame.at(3, 3, 0) = kNaN;
    const TemporalMetrics m = temporalMetrics(test, reference);
    EXPECT_EQ(m.pixelsWithoutDifference, 1u);
    EXPECT_TRUE(std::isnan(m.flicker.at(3, 3)));
    EXPECT_EQ(m.flicker.at(0, 0), 0.0f);
    EXPECT_EQ(m.temporalRms, 0.0);
    EXPECT_EQ(m.worstFlicker, 0.0);
    EXPECT_TRUE(std::isnan(m.meanFrameError));  // every frame holds a NaN
    EXPECT_EQ(m.framesWithoutError, 4u);
    EXPECT_EQ(m.nonFiniteTestPixels, 4u);
    // The heat map shows it in magenta, the rest on the ramp (0: black).
    const Image heat = heatMap(m.flicker, 1.0f);
    EXPECT_EQ(heat.at(3, 3, 0), 1.0f);
    EXPECT_EQ(heat.at(3, 3, 1), 0.0f);
    EXPECT_EQ(heat.at(3, 3, 2), 1.0f);
    EXPECT_EQ(heat.at(0, 0, 0), 0.0f);
}

TEST(TemporalError, OneFrameHasNoTemporalFigure) {
    const std::vector<Image> reference = movingReference(4, 4, 1);
    const TemporalMetrics m = temporalMetrics(reference, reference);
    EXPECT_EQ(m.frames, 1);
    EXPECT_TRUE(std::isnan(m.temporalRms));
    EXPECT_TRUE(std::isnan(m.worstFlicker));
    EXPECT_EQ(m.meanFrameError, 0.0);
    EXPECT_EQ(m.pixelsWithoutDifference, 16u);
}

TEST(TemporalError, TheAccumulatorTakesFramesOneAtATime) {
    const std::vector<Image> reference = movingReference(8, 6, 5);
    const std::vector<Image> test = withError(reference, [](int x, int, int t) { return 0.0625f * float((x * t) % 3); });
    TemporalAccumulator accumulator;
    for (std::size_t t = 0; t < test.size(); ++t) accumulator.add(test[t], reference[t]);
    const TemporalMetrics streamed = accumulator.finish(), whole = temporalMetrics(test, reference);
    EXPECT_EQ(accumulator.frames(), 5);
    EXPECT_EQ(streamed.temporalRms, whole.temporalRms);
    EXPECT_EQ(streamed.worstFlicker, whole.worstFlicker);
    EXPECT_EQ(streamed.flicker.pixels, whole.flicker.pixels);
    EXPECT_GT(whole.temporalRms, 0.0);
}

// A gap (frames between two added ones had no reference) takes no difference across it: errors +a, -a,
// then after the gap 100a and 98a. The jump of 101a across the gap is not counted; the two differences
// taken are both of size 2a, so the temporal RMS is a / mean(R) as for +a/-a alone.
TEST(TemporalError, AGapTakesNoDifferenceAcrossIt) {
    const std::vector<Image> reference = movingReference(8, 6, 4);
    const float a = 0.0625f;
    const float errors[4] = {a, -a, 100.0f * a, 98.0f * a};
    const std::vector<Image> test = withError(reference, [&](int, int, int t) { return errors[t]; });
    TemporalAccumulator accumulator;
    accumulator.add(test[0], reference[0]);
    accumulator.add(test[1], reference[1]);
    accumulator.gap();
    accumulator.add(test[2], reference[2]);
    accumulator.add(test[3], reference[3]);
    const TemporalMetrics m = accumulator.finish();
    EXPECT_NEAR(m.temporalRms, double(a) / referenceMean(reference), 1e-12);
    EXPECT_EQ(m.excludedDifferences, std::size_t(8 * 6)) << "frame 2's difference, every pixel";
    EXPECT_TRUE(std::isnan(m.frameTemporal[2]));
    // Without the gap the jump counts and the score is far larger.
    EXPECT_GT(temporalMetrics(test, reference).temporalRms, 10.0 * m.temporalRms);
}

}  // namespace
}  // namespace viz::report
