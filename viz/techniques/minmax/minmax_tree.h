// The 1D min-max mipmap of one row of the rectified shadow map and its stackless traversal (Chen et al.
// 2011, section 3.3, Figure 5, with both section 3.5 optimisations). Mirrored by shaders/minmax/mipmap.comp
// (construction) and shaders/minmax/traverse.comp (traversal), with the same integer steps and comparisons.
//
// Layout (Ahnentafel): a row of n = 2^L leaves is stored in 2n nodes; node 1 is the root, the children of
// node k are 2k and 2k + 1, the leaves are nodes n .. 2n - 1 (leaf j = node n + j), index 0 is unused.
// Node k at level l = floor(log2 k) covers columns [(k - 2^l) n / 2^l, (k - 2^l + 1) n / 2^l).
// A camera ray at height beta is lit over column j when beta < S[j]; a node is lit when beta < min,
// shadowed when beta >= max, mixed otherwise.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <vector>

#include <glm/glm.hpp>

#include "core/error.h"

namespace viz::minmax {

// Columns covered by node k of a tree over n leaves.
struct NodeRange {
    int lo = 0, hi = 0;
};
inline NodeRange nodeRange(int node, int leaves) {
    const int level = std::bit_width(unsigned(node)) - 1;
    const int width = leaves >> level;
    const int first = node - (1 << level);
    return {first * width, (first + 1) * width};
}

// All 2n nodes (x = min, y = max) of a row of n = 2^L values, built bottom-up one level at a time (the
// GPU builds level l from level l + 1 in one pass).
inline std::vector<glm::vec2> buildTree(const std::vector<float>& row) {
    const int n = int(row.size());
    VIZ_CHECK(n > 0 && std::has_single_bit(unsigned(n)), "a min-max tree needs a power-of-two row");
    std::vector<glm::vec2> tree(std::size_t(2 * n), glm::vec2(0.0f));
    for (int j = 0; j < n; ++j) tree[std::size_t(n + j)] = glm::vec2(row[std::size_t(j)]);
    for (int k = n - 1; k >= 1; --k) {
        const glm::vec2 a = tree[std::size_t(2 * k)], b = tree[std::size_t(2 * k + 1)];
        tree[std::size_t(k)] = glm::vec2(std::min(a.x, b.x), std::max(a.y, b.y));
    }
    return tree;
}

// A lit run of columns [begin, end) (end may be fractional: the ray ends inside a texel).
struct LitRun {
    float begin = 0.0f, end = 0.0f;
    bool operator==(const LitRun&) const = default;
};

enum class NodeState { Lit = 0, Shadowed = 1, Mixed = 2 };
struct VisitedNode {
    int node = 0;
    NodeState state = NodeState::Mixed;
};

// Stackless traversal of Figure 5 over columns [0, end) of a ray at height beta. `onRun` receives each lit
// run once, in order (section 3.5: the update is delayed until the next unlit node or the end, so runs
// spanning several nodes are merged). `onVisit` sees every node processed. Returns the nodes processed.
// Section 3.5's other change: after moving to the next node, climb at most one level ("if" for "while");
// the walk then ends when advancing yields a power of two (the first node of a level: it walked off the
// row's end), or when the next node starts at or beyond `end`.
template <typename OnRun, typename OnVisit>
int traverse(const std::vector<glm::vec2>& tree, float beta, float end, OnRun&& onRun, OnVisit&& onVisit) {
    const int leaves = int(tree.size() / 2);
    int node = 1;
    int visited = 0;
    float runBegin = -1.0f, runEnd = -1.0f;
    NodeRange range = nodeRange(node, leaves);
    do {
        ++visited;
        const glm::vec2 mm = tree[std::size_t(node)];
        if (mm.x <= beta && beta < mm.y) {
            onVisit(VisitedNode{node, NodeState::Mixed});
            node = node * 2;
        } else {
            if (beta < mm.x) {
                onVisit(VisitedNode{node, NodeState::Lit});
                if (runBegin < 0.0f) runBegin = float(range.lo);
                runEnd = std::min(end, float(range.hi));
            } else {
                onVisit(VisitedNode{node, NodeState::Shadowed});
                if (runBegin >= 0.0f) {
                    onRun(LitRun{runBegin, runEnd});
                    runBegin = -1.0f;
                }
            }
            node = node + 1;
            if ((node & 1) == 0) node = node / 2;
            if (std::has_single_bit(unsigned(node))) break;  // first node of a level: past the row's end
        }
        range = nodeRange(node, leaves);
    } while (end > float(range.lo));
    if (runBegin >= 0.0f) onRun(LitRun{runBegin, runEnd});
    return visited;
}

template <typename OnRun>
int traverse(const std::vector<glm::vec2>& tree, float beta, float end, OnRun&& onRun) {
    return traverse(tree, beta, end, onRun, [](const VisitedNode&) {});
}

// The lit runs of columns [0, end) by a linear scan of the leaves (the ground truth for the tree).
inline std::vector<LitRun> linearScan(const std::vector<float>& row, float beta, float end) {
    std::vector<LitRun> runs;
    float runBegin = -1.0f, runEnd = -1.0f;
    for (int j = 0; j < int(row.size()) && float(j) < end; ++j) {
        if (beta < row[std::size_t(j)]) {
            if (runBegin < 0.0f) runBegin = float(j);
            runEnd = std::min(end, float(j + 1));
        } else if (runBegin >= 0.0f) {
            runs.push_back({runBegin, runEnd});
            runBegin = -1.0f;
        }
    }
    if (runBegin >= 0.0f) runs.push_back({runBegin, runEnd});
    return runs;
}

}  // namespace viz::minmax
