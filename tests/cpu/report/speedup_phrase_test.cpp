// The report's headline words: a ratio below 1 is "slower" by its inverse (the page once printed
// "polyvol 0.17x faster" for 5.9x slower).
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "report/text_output.h"

namespace viz::report {
namespace {

TEST(SpeedupPhrase, SaysFasterOrSlowerByTheRatioOrItsInverse) {
    EXPECT_EQ(speedupPhrase(5.9), "5.90x faster");
    EXPECT_EQ(speedupPhrase(1.0 / 5.9), "5.90x slower");
    EXPECT_EQ(speedupPhrase(0.17), "5.88x slower");
    EXPECT_EQ(speedupPhrase(12.4), "12x faster");
    EXPECT_EQ(speedupPhrase(1.0 / 150.0), "150x slower");
    EXPECT_EQ(speedupPhrase(1.004), "as fast");
    EXPECT_EQ(speedupPhrase(0.996), "as fast");
    EXPECT_EQ(speedupPhrase(0.0), "-");
    EXPECT_EQ(speedupPhrase(-2.0), "-");
    EXPECT_EQ(speedupPhrase(std::numeric_limits<double>::quiet_NaN()), "-");
    EXPECT_EQ(speedupPhrase(std::numeric_limits<double>::infinity()), "-");
}

TEST(SpeedupPhrase, ARangeNamesItsEndsOnceAndInOrder) {
    EXPECT_EQ(speedupRangePhrase(6.51, 4.9), "between 4.90x and 6.51x faster");
    EXPECT_EQ(speedupRangePhrase(0.5, 0.8), "between 1.25x and 2.00x slower");
    EXPECT_EQ(speedupRangePhrase(1.3, 1.0 / 1.2), "between 1.20x slower and 1.30x faster");
    EXPECT_EQ(speedupRangePhrase(1.0, 2.0), "between as fast and 2.00x faster");
}

}  // namespace
}  // namespace viz::report
