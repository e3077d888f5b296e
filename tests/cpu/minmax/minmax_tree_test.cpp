// The min-max tree walk (Figure 5 with the section 3.5 changes) finds the same lit runs as a linear scan.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "techniques/minmax/minmax_tree.h"

namespace {

using viz::minmax::LitRun;

// Rows of runs of equal heights (like rectified shadow maps) and of white noise, random beta and ends
// (fractional, inside and beyond the row).
TEST(MinmaxTree, TreeRunsEqualLinearScanForRandomRowsAndBetas) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    int checked = 0;
    for (int n : {1, 2, 16, 256, 1024}) {
        for (int rowIndex = 0; rowIndex < 20; ++rowIndex) {
            std::vector<float> row(static_cast<std::size_t>(n), 0.0f);
            const bool noise = rowIndex % 3 == 0;
            float value = unit(rng);
            for (int j = 0; j < n; ++j) {
                if (noise || unit(rng) < 0.05f) value = unit(rng) < 0.1f ? -1.0f : unit(rng);
                row[std::size_t(j)] = value;
            }
            const auto tree = viz::minmax::buildTree(row);
            for (int k = 0; k < 50; ++k) {
                const float beta = unit(rng) * 1.1f - 0.05f;
                const float end = k % 5 == 0 ? float(n) * 1.5f : unit(rng) * float(n);
                std::vector<LitRun> runs;
                const int visited = viz::minmax::traverse(tree, beta, end, [&](const LitRun& r) { runs.push_back(r); });
                EXPECT_EQ(runs, viz::minmax::linearScan(row, beta, std::min(end, float(n))))
                    << "n " << n << " row " << rowIndex << " beta " << beta << " end " << end;
                // The walk's cost, from the runs alone: per level, only nodes holding a run boundary
                // (each run has two) or the ray's end are undecided, and each of those visits its two
                // children; everything else is decided where it is met. A walk that opens decided nodes
                // (or visits the whole tree, 2n - 1 nodes) breaks this for n >= 16.
                int levels = 0;
                while ((1 << levels) < n) ++levels;
                EXPECT_LE(visited, 1 + 2 * levels * (2 * int(runs.size()) + 1))
                    << "n " << n << " row " << rowIndex << " runs " << runs.size();
                ++checked;
            }
        }
    }
    EXPECT_EQ(checked, 5 * 20 * 50);
}

// A row that is lit everywhere is one node (the root); an empty ray visits nothing but the root.
TEST(MinmaxTree, UniformRowsAreDecidedAtTheRoot) {
    const std::vector<float> row(64, 0.5f);
    const auto tree = viz::minmax::buildTree(row);
    std::vector<LitRun> runs;
    EXPECT_EQ(viz::minmax::traverse(tree, 0.2f, 40.5f, [&](const LitRun& r) { runs.push_back(r); }), 1);
    ASSERT_EQ(runs.size(), 1u);
    EXPECT_EQ(runs[0], (LitRun{0.0f, 40.5f}));
    runs.clear();
    EXPECT_EQ(viz::minmax::traverse(tree, 0.7f, 64.0f, [&](const LitRun& r) { runs.push_back(r); }), 1);
    EXPECT_TRUE(runs.empty());
}

// Node ranges partition each level.
TEST(MinmaxTree, NodeRangesTileEveryLevel) {
    const int n = 32;
    for (int level = 0; (1 << level) <= n; ++level) {
        int next = 0;
        for (int k = 1 << level; k < (2 << level); ++k) {
            const auto r = viz::minmax::nodeRange(k, n);
            EXPECT_EQ(r.lo, next);
            EXPECT_EQ(r.hi - r.lo, n >> level);
            next = r.hi;
        }
        EXPECT_EQ(next, n);
    }
}

}  // namespace
