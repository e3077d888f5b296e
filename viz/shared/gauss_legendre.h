// Gauss-Legendre rules of any order, computed at run time (the fixed-order tables of the airlight kernel
// are in airlight.h). Used wherever an area light is replaced by point nodes, so the reference and the
// GPU techniques place their nodes by the same rule.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include "core/error.h"

namespace viz {

struct QuadratureRule {
    std::vector<double> nodes;    // ascending
    std::vector<double> weights;  // sum to the interval's length
};

// n-point rule on [-1, 1] (weights sum to 2), exact for polynomials of degree 2n - 1.
inline QuadratureRule gaussLegendreRule(int n) {
    VIZ_CHECK(n >= 1, "Gauss-Legendre needs at least one node");
    QuadratureRule rule;
    rule.nodes.resize(std::size_t(n));
    rule.weights.resize(std::size_t(n));
    // Newton's method on P_n from the guess cos(pi (i + 3/4) / (n + 1/2)) (i = 0: the largest root);
    // P_n and P_{n-1} from the recurrence k P_k = (2k - 1) x P_{k-1} - (k - 1) P_{k-2};
    // P_n'(x) = n (x P_n - P_{n-1}) / (x^2 - 1); weight 2 / ((1 - x^2) P_n'(x)^2).
    for (int i = 0; i < n; ++i) {
        double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
        double dp = 1.0;
        for (int iter = 0; iter < 100; ++iter) {
            double pPrev = 1.0, p = x;
            for (int k = 2; k <= n; ++k) {
                const double next = ((2.0 * k - 1.0) * x * p - (k - 1.0) * pPrev) / k;
                pPrev = p;
                p = next;
            }
            dp = n * (x * p - pPrev) / (x * x - 1.0);
            const double dx = p / dp;
            x -= dx;
            if (std::abs(dx) < 1e-16) break;
        }
        rule.nodes[std::size_t(n - 1 - i)] = x;
        rule.weights[std::size_t(n - 1 - i)] = 2.0 / ((1.0 - x * x) * dp * dp);
    }
    return rule;
}

// The same rule mapped to [0, 1] (weights sum to 1).
inline QuadratureRule gaussLegendreRuleUnit(int n) {
    QuadratureRule rule = gaussLegendreRule(n);
    for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
        rule.nodes[i] = 0.5 * (1.0 + rule.nodes[i]);
        rule.weights[i] *= 0.5;
    }
    return rule;
}

}  // namespace viz
