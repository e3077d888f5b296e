#include "core/blue_noise.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

#include "core/error.h"

namespace viz {
namespace {

// Energy field of a binary pattern under a toroidal Gaussian: energy[p] = sum over set q of K(p - q).
class EnergyField {
public:
    explicit EnergyField(int size) : mSize(size), mKernel(std::size_t(size * size)), mEnergy(mKernel.size(), 0.0) {
        const double sigma = 1.5;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const int dx = std::min(x, size - x), dy = std::min(y, size - y);
                mKernel[std::size_t(y * size + x)] = std::exp(-double(dx * dx + dy * dy) / (2.0 * sigma * sigma));
            }
    }
    void add(int index, double sign) {
        const int qx = index % mSize, qy = index / mSize;
        for (int y = 0; y < mSize; ++y) {
            const int ky = ((y - qy) % mSize + mSize) % mSize;
            for (int x = 0; x < mSize; ++x) {
                const int kx = ((x - qx) % mSize + mSize) % mSize;
                mEnergy[std::size_t(y * mSize + x)] += sign * mKernel[std::size_t(ky * mSize + kx)];
            }
        }
    }
    // The set pixel of highest energy (tightest cluster) or the unset pixel of lowest energy (largest
    // void); ties go to the lowest index.
    int tightestCluster(const std::vector<std::uint8_t>& set) const { return extreme(set, 1, +1.0); }
    int largestVoid(const std::vector<std::uint8_t>& set) const { return extreme(set, 0, -1.0); }

private:
    int extreme(const std::vector<std::uint8_t>& set, std::uint8_t want, double sign) const {
        int best = -1;
        double bestValue = 0.0;
        for (std::size_t i = 0; i < set.size(); ++i)
            if (set[i] == want && (best < 0 || sign * mEnergy[i] > bestValue)) {
                best = int(i);
                bestValue = sign * mEnergy[i];
            }
        return best;
    }
    int mSize;
    std::vector<double> mKernel, mEnergy;
};

}  // namespace

std::vector<float> blueNoise(int size) {
    VIZ_CHECK(size >= 4 && size <= 256 && (size & (size - 1)) == 0, "blueNoise: size must be a power of two in [4, 256]");
    const int n = size * size;
    // Initial binary pattern: a tenth of the pixels, at random (the engine's raw output: the same
    // sequence on every standard library).
    std::mt19937 random(20231127u);
    std::vector<std::uint8_t> pattern(std::size_t(n), 0);
    EnergyField energy(size);
    int ones = 0;
    while (ones < std::max(1, n / 10)) {
        const int i = int(random() % std::uint32_t(n));
        if (pattern[std::size_t(i)]) continue;
        pattern[std::size_t(i)] = 1;
        energy.add(i, 1.0);
        ++ones;
    }
    // Even it out: move the tightest cluster's point to the largest void until that moves nothing.
    for (int guard = 0; guard < 16 * n; ++guard) {
        const int cluster = energy.tightestCluster(pattern);
        pattern[std::size_t(cluster)] = 0;
        energy.add(cluster, -1.0);
        const int gap = energy.largestVoid(pattern);
        pattern[std::size_t(gap)] = 1;
        energy.add(gap, 1.0);
        if (gap == cluster) break;
    }
    std::vector<int> rank(std::size_t(n), -1);
    // Ranks below the prototype's count: remove tightest clusters one by one, highest rank first.
    {
        std::vector<std::uint8_t> p = pattern;
        EnergyField e = energy;
        for (int r = ones - 1; r >= 0; --r) {
            const int cluster = e.tightestCluster(p);
            p[std::size_t(cluster)] = 0;
            e.add(cluster, -1.0);
            rank[std::size_t(cluster)] = r;
        }
    }
    // Ranks from the prototype's count up: fill the largest void one by one. (Past half, the tightest
    // cluster of unset pixels under the same toroidal kernel is the same pixel: its energy over the unset
    // pixels is the kernel's total minus its energy over the set ones.)
    for (int r = ones; r < n; ++r) {
        const int gap = energy.largestVoid(pattern);
        pattern[std::size_t(gap)] = 1;
        energy.add(gap, 1.0);
        rank[std::size_t(gap)] = r;
    }
    std::vector<float> out(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) out[std::size_t(i)] = float((double(rank[std::size_t(i)]) + 0.5) / double(n));
    return out;
}

}  // namespace viz
