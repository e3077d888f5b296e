// The frame view's progress band: every case of its text and bar written out.
#include <gtest/gtest.h>

#include "progress_band.h"

namespace airlight {
namespace {

CpuProgress pass(int pass, double elapsed, double estimate) {
    CpuProgress p;
    p.busy = true;
    p.pass = pass;
    p.passCount = 3;
    p.size = {80, 60};
    p.elapsed = elapsed;
    p.estimate = estimate;
    return p;
}

TEST(ProgressBand, RenderingQuotesTheLastRunOnlyWhenThereWasOne) {
    EXPECT_EQ(renderingText(false, 2.5), "rendering...");
    EXPECT_EQ(renderingText(true, 2.54), "rendering... (last run 2.5 s)");
}

TEST(ProgressBand, ARequestNotTakenYetIsStartingWithoutABar) {
    const ProgressBand b = cpuProgressBand(pass(0, 0.0, 0.0));
    EXPECT_EQ(b.text, "computing... starting");
    EXPECT_LT(b.fraction, 0.0f);
}

TEST(ProgressBand, APassWithAnEstimateShowsHowFarAlongItIs) {
    ProgressBand b = cpuProgressBand(pass(2, 1.0, 4.0));
    EXPECT_EQ(b.text, "computing... pass 2/3 (80x60)  1.0 s of ~4.0 s");
    EXPECT_FLOAT_EQ(b.fraction, 0.25f);
    // Past the estimate but within 1.5 times it: the bar stops short of full.
    b = cpuProgressBand(pass(2, 5.9, 4.0));
    EXPECT_FLOAT_EQ(b.fraction, 0.99f);
    EXPECT_EQ(b.text, "computing... pass 2/3 (80x60)  5.9 s of ~4.0 s");
}

TEST(ProgressBand, AnEstimateThePassHasOutrunOrNoEstimateGivesNoBar) {
    ProgressBand b = cpuProgressBand(pass(3, 6.0, 4.0));
    EXPECT_EQ(b.text, "computing... pass 3/3 (80x60)  6.0 s");
    EXPECT_LT(b.fraction, 0.0f);
    b = cpuProgressBand(pass(1, 0.5, 0.0));
    EXPECT_EQ(b.text, "computing... pass 1/3 (80x60)  0.5 s");
    EXPECT_LT(b.fraction, 0.0f);
}

}  // namespace
}  // namespace airlight
