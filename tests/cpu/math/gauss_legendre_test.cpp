// The run-time Gauss-Legendre rule shared by the reference and the GPU area-light nodes.
#include <gtest/gtest.h>

#include <cmath>

#include "shared/gauss_legendre.h"

namespace {

TEST(GaussLegendreRule, IntegratesPolynomialsUpToDegree2nMinus1) {
    for (int n = 1; n <= 16; ++n) {
        const viz::QuadratureRule rule = viz::gaussLegendreRule(n);
        ASSERT_EQ(rule.nodes.size(), std::size_t(n));
        for (int k = 0; k <= 2 * n - 1; ++k) {
            double sum = 0.0;
            for (int i = 0; i < n; ++i) sum += rule.weights[std::size_t(i)] * std::pow(rule.nodes[std::size_t(i)], k);
            const double exact = k % 2 == 0 ? 2.0 / (k + 1) : 0.0;
            EXPECT_NEAR(sum, exact, 1e-13) << "n = " << n << ", x^" << k;
        }
        for (int i = 1; i < n; ++i) EXPECT_LT(rule.nodes[std::size_t(i - 1)], rule.nodes[std::size_t(i)]);
    }
}

TEST(GaussLegendreRule, UnitIntervalVersionIntegratesPolynomialsOnZeroOne) {
    for (int n : {1, 2, 5, 8, 13}) {
        const viz::QuadratureRule rule = viz::gaussLegendreRuleUnit(n);
        for (int k = 0; k <= 2 * n - 1; ++k) {
            double sum = 0.0;
            for (std::size_t i = 0; i < rule.nodes.size(); ++i) sum += rule.weights[i] * std::pow(rule.nodes[i], k);
            EXPECT_NEAR(sum, 1.0 / (k + 1), 1e-14) << "n " << n << " k " << k;
        }
        for (double x : rule.nodes) {
            EXPECT_GT(x, 0.0);
            EXPECT_LT(x, 1.0);
        }
    }
}

}  // namespace
