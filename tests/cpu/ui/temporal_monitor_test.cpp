// The window's temporal view (app/temporal_monitor.h) on constructed sequences with known answers.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <utility>

#include "temporal_monitor.h"

namespace {

viz::Image filled(int w, int h, float r, float g, float b) {
    viz::Image image(w, h, 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            image.at(x, y, 0) = r;
            image.at(x, y, 1) = g;
            image.at(x, y, 2) = b;
        }
    return image;
}

TEST(TemporalMonitor, AStillSequenceScoresZero) {
    airlight::TemporalMonitor m;
    EXPECT_FALSE(m.add(filled(4, 3, 1, 2, 3)));  // nothing to compare with yet
    EXPECT_TRUE(std::isnan(m.score()));
    for (int i = 0; i < 4; ++i) EXPECT_TRUE(m.add(filled(4, 3, 1, 2, 3)));
    EXPECT_EQ(m.pairs(), 4);
    EXPECT_EQ(m.score(), 0.0);
    const viz::Intermediate v = m.view();
    EXPECT_EQ(v.id, airlight::kTemporalChangeId);
    ASSERT_TRUE(v.image);
    for (float x : v.image->pixels) EXPECT_EQ(x, 0.0f);
}

// L alternating between m + e and m - e in every channel: d = +-2e, so the score is e / m; the change
// image holds the signed luminance change (+-2e, luminance weights summing to 1).
TEST(TemporalMonitor, AnAlternatingSequenceScoresItsAmplitudeOverItsMean) {
    airlight::TemporalMonitor m;
    const float mean = 2.0f, e = 0.25f;
    for (int i = 0; i < 7; ++i) {
        const float v = i % 2 == 0 ? mean + e : mean - e;
        m.add(filled(5, 4, v, v, v));
    }
    EXPECT_EQ(m.pairs(), 6);
    // mean(L) over 7 frames: (4 (m + e) + 3 (m - e)) / 7.
    const double meanL = (4.0 * (mean + e) + 3.0 * (mean - e)) / 7.0;
    EXPECT_NEAR(m.score(), e / meanL, 1e-12);
    const viz::Intermediate v = m.view();
    EXPECT_NEAR(v.image->at(2, 1, 0), 2.0 * e, 1e-6);  // frame 6 (m + e) after frame 5 (m - e)
    EXPECT_EQ(v.kind, viz::ViewKind::Signed);
    EXPECT_NEAR(v.rangeMax, 2.0 * e, 1e-6);
    EXPECT_EQ(v.rangeMin, -v.rangeMax);
}

TEST(TemporalMonitor, ASizeChangeStartsAgainAndNaNIsLeftOut) {
    airlight::TemporalMonitor m;
    m.add(filled(4, 3, 1, 1, 1));
    EXPECT_TRUE(m.add(filled(4, 3, 2, 2, 2)));
    EXPECT_FALSE(m.add(filled(8, 6, 2, 2, 2)));  // the window's reduced size while dragging, say
    EXPECT_EQ(m.pairs(), 0);
    viz::Image withNaN = filled(8, 6, 3, 3, 3);
    withNaN.at(1, 1, 0) = std::numeric_limits<float>::quiet_NaN();
    EXPECT_TRUE(m.add(withNaN));
    EXPECT_TRUE(std::isnan(m.view().image->at(1, 1, 0)));
    EXPECT_NEAR(m.view().image->at(0, 0, 0), 1.0, 1e-6);
    EXPECT_TRUE(std::isfinite(m.score()));
    EXPECT_GT(m.score(), 0.0);
}

// Against the reference: a reference that moves (R alternating between 1 and 3) and L = R + error with
// the error alternating +e, -e. The change of L includes the motion (score far above e); the error's
// change is d = +-2e, so its flicker is e / mean(R) with mean(R) = 2 over the frames added. A frame whose
// reference is not known (null) takes no difference on either side, and its error change is not counted.
TEST(TemporalMonitor, AgainstTheReferenceTheMotionIsGoneAndAFrameWithoutOneIsSkipped) {
    airlight::TemporalMonitor m;
    const float e = 0.125f;
    const auto frame = [&](int i) {
        const float r = i % 2 == 0 ? 1.0f : 3.0f, err = i % 2 == 0 ? e : -e;
        return std::pair{filled(4, 3, r + err, r + err, r + err), std::make_shared<const viz::Image>(filled(4, 3, r, r, r))};
    };
    for (int i = 0; i < 4; ++i) {
        auto [l, r] = frame(i);
        m.add(l, r);
    }
    EXPECT_EQ(m.errorPairs(), 3);
    EXPECT_NEAR(m.errorScore(), e / 2.0, 1e-12);
    EXPECT_GT(m.score(), 4.0 * m.errorScore()) << "the change of L holds the reference's own motion";
    const viz::Intermediate v = m.errorView();
    EXPECT_EQ(v.id, airlight::kTemporalErrorChangeId);
    EXPECT_NEAR(v.image->at(1, 1, 0), -2.0 * e, 1e-6);  // frame 3 (error -e) after frame 2 (+e): d = -2e
    // A frame without its reference, then two with: only the last pair counts, and across the gap the
    // error jumps (to 10e) without being counted.
    m.add(frame(4).first, nullptr);
    EXPECT_EQ(m.errorPairs(), 3);
    auto [l5, r5] = frame(5);
    for (float& x : l5.pixels) x += 10.0f * e;  // a large error, but constant from here on
    m.add(l5, r5);
    EXPECT_EQ(m.errorPairs(), 3) << "no difference across the frame without a reference";
    auto [l7, r7] = frame(7);
    for (float& x : l7.pixels) x += 10.0f * e;
    m.add(l7, r7);
    EXPECT_EQ(m.errorPairs(), 4);
    // Frames 5 and 7 have the same error (10e - e): their pair adds d = 0, so sqrt(mean d^2) / 2 is
    // sqrt(3 (2e)^2 / 4) / 2; mean(R) is over the six frames with a reference, R = 1, 3, 1, 3, 3, 3.
    EXPECT_NEAR(m.errorScore(), std::sqrt(3.0 * 4.0 * e * e / 4.0) / 2.0 / (14.0 / 6.0), 1e-12);
}

}  // namespace
