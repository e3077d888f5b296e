// The blue-noise threshold map (core/blue_noise.h): every threshold once, the same map every call, and
// its spectrum: far less energy at low frequencies than a random arrangement of the same values, checked
// with a direct discrete Fourier transform.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include "core/blue_noise.h"

namespace {

// Mean power |F(k)|^2 over the frequencies with 0 < |k| <= radius (cycles per tile) of v - mean.
double lowFrequencyPower(const std::vector<float>& v, int size, double radius) {
    double mean = 0.0;
    for (float x : v) mean += x;
    mean /= double(v.size());
    double sum = 0.0;
    int count = 0;
    const int r = int(std::ceil(radius));
    for (int ky = -r; ky <= r; ++ky)
        for (int kx = -r; kx <= r; ++kx) {
            const double k2 = double(kx * kx + ky * ky);
            if (k2 == 0.0 || k2 > radius * radius) continue;
            std::complex<double> f = 0.0;
            for (int y = 0; y < size; ++y)
                for (int x = 0; x < size; ++x) {
                    const double phase = -2.0 * std::numbers::pi * double(kx * x + ky * y) / double(size);
                    f += (double(v[std::size_t(y * size + x)]) - mean) * std::polar(1.0, phase);
                }
            sum += std::norm(f);
            ++count;
        }
    return sum / double(count);
}

TEST(BlueNoise, HoldsEveryThresholdOnceAndIsTheSameEveryCall) {
    for (int size : {4, 16, 64}) {
        const std::vector<float> v = viz::blueNoise(size);
        ASSERT_EQ(v.size(), std::size_t(size * size));
        std::vector<int> seen(v.size(), 0);
        for (float x : v) {
            const long k = std::lround(double(x) * double(v.size()) - 0.5);
            ASSERT_GE(k, 0);
            ASSERT_LT(k, long(v.size()));
            ++seen[std::size_t(k)];
        }
        EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int c) { return c == 1; })) << size;
        EXPECT_EQ(v, viz::blueNoise(size)) << size;
    }
}

TEST(BlueNoise, HasLittleLowFrequencyEnergy) {
    constexpr int kSize = 64;
    const std::vector<float> blue = viz::blueNoise(kSize);
    // The same values shuffled: white noise with the same histogram.
    std::vector<float> white = blue;
    std::mt19937 random(7u);
    std::shuffle(white.begin(), white.end(), random);
    // Up to an eighth of the tile's highest frequency (32 cycles).
    const double blueLow = lowFrequencyPower(blue, kSize, 4.0);
    const double whiteLow = lowFrequencyPower(white, kSize, 4.0);
    std::printf("mean power at 0 < |k| <= 4: blue %.4g, white %.4g (ratio %.3g)\n", blueLow, whiteLow, blueLow / whiteLow);
    EXPECT_LT(blueLow, 0.05 * whiteLow);
}

}  // namespace
