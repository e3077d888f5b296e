// minmax's pyramid chart (charts.h) on a 2048-column row: at most kChartWidth wide, about 3:1, and each
// pixel of each level shows the min and max of the leaves under it, computed here from the leaves by an
// exhaustive loop (not from the tree the chart reads).
#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>
#include <random>
#include <vector>

#include "techniques/minmax/charts.h"

namespace viz::minmax {
namespace {

TEST(MinmaxCharts, AWideRowsPyramidShowsEveryLevelsMinAndMaxAtAReadableSize) {
    const int n = 2048, levels = 12;
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> beta(0.0f, std::numbers::pi_v<float>);
    std::vector<float> leaves(n);
    for (float& v : leaves) v = beta(rng);
    // The tree as the mipmap builds it: node k of level l covers leaves [k n / 2^l, (k + 1) n / 2^l).
    std::vector<glm::vec2> tree(2 * n);
    for (int l = 0; l < levels; ++l)
        for (int k = 0; k < (1 << l); ++k) {
            const int span = n >> l;
            const auto [lo, hi] = std::minmax_element(leaves.begin() + k * span, leaves.begin() + (k + 1) * span);
            tree[std::size_t((1 << l) + k)] = {*lo, *hi};
        }
    const Image img = pyramidView(tree, levels);
    ASSERT_EQ(img.width, kChartWidth);
    ASSERT_EQ(img.height % levels, 0);
    const int band = img.height / levels;
    EXPECT_GE(band, 4);
    EXPECT_LE(float(img.width) / float(img.height), 4.0f) << "not a strip";
    EXPECT_GE(float(img.width) / float(img.height), 2.0f);
    const float pi = std::numbers::pi_v<float>;
    for (int l = 0; l < levels; ++l) {
        const int nodes = 1 << l, span = n >> l;
        for (int x = 0; x < img.width; ++x) {
            // The leaves under pixel x on this level: those of the nodes the pixel covers.
            const int first = x * nodes / img.width, last = std::max(first, (x + 1) * nodes / img.width - 1);
            float lo = pi, hi = 0.0f;
            for (int i = first * span; i < (last + 1) * span; ++i) lo = std::min(lo, leaves[std::size_t(i)]), hi = std::max(hi, leaves[std::size_t(i)]);
            ASSERT_FLOAT_EQ(img.at(x, l * band, 0), lo / pi) << "level " << l << " x " << x;
            ASSERT_FLOAT_EQ(img.at(x, l * band + band - 1, 0), hi / pi) << "level " << l << " x " << x;
        }
    }
}

}  // namespace
}  // namespace viz::minmax
