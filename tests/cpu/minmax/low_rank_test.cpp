// The low-rank integrand (low_rank.h): I(beta, gamma) integrates to the closed-form airlight of the same
// ray, and its rank-N approximation converges with N.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include "shared/airlight.h"
#include "techniques/minmax/low_rank.h"
#include "techniques/minmax/charts.h"

namespace {

using viz::minmax::LightKind;

// int_0^gamma(d) I dgamma (I = scaledIntegrand / sin(beta)) equals the unshadowed airlight over [0, d] of a
// unit-intensity isotropic light (pointSegment / directionalSegment), so the Jacobian and the falloff
// are right. Composite Simpson over gamma, 4000 intervals.
TEST(MinmaxLowRank, IntegrandIntegratesToTheClosedForm) {
    const double sigmaS = 0.12, sigmaT = 0.13, g = 0.2;
    for (LightKind kind : {LightKind::Spot, LightKind::Directional}) {
        const auto f = viz::minmax::makeFrame<double>(kind, glm::dvec3(0.5, 5.0, -3.0), glm::dvec3(-0.2, -1.0, 0.4));
        for (double beta : {0.2, 0.7, 1.5, 2.4}) {
            for (double d : {2.0, 9.0, 30.0}) {
                const double gammaEnd = viz::minmax::gammaAlongRay(f, beta, d);
                const int n = 4000;
                const double hstep = gammaEnd / n;
                double sum = 0.0;
                for (int i = 0; i <= n; ++i) {
                    const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
                    sum += w * viz::minmax::scaledIntegrand(f, beta, i * hstep, sigmaS, sigmaT, g);
                }
                const double integral = sum * hstep / 3.0 / std::sin(beta);
                double expected;
                if (kind == LightKind::Directional) {
                    expected = viz::airlight::directionalSegment(std::cos(beta), 0.0, d, sigmaS, sigmaT, g, 1.0);
                } else {
                    // A ray at angle beta from the axis (any alpha): tP and h relative to the light.
                    const glm::dvec3 w = std::cos(beta) * f.axis + std::sin(beta) * f.u;
                    const auto geo = viz::airlight::rayLightGeometry(f.lightDistance * f.axis, w);
                    expected = viz::airlight::pointSegment<double>(geo.tP, geo.h, 0.0, d, sigmaS, sigmaT, g, 1.0);
                }
                EXPECT_NEAR(integral, expected, 1e-6 * expected) << "kind " << int(kind) << " beta " << beta << " d " << d;
            }
        }
    }
}

// The tables the shader reads (float B_i and Gamma_i) reach the best possible rank-N error: the test
// samples the integrand on the grid itself (scaledIntegrand, checked above against the closed form),
// reconstructs from the tables, and compares with the Eckart-Young optimum sqrt(sum_{i>=N} s_i^2 / sum s_i^2)
// of independent singular values (the code uses Eigen's JacobiSVD; these are the positive eigenvalues of
// the symmetric [[0, M], [M^T, 0]], from Eigen's tridiagonal QR solver, accurate to rounding in ||M||
// (a third of the compile time of a second SVD, BDCSVD: 17 s against 52 s at -O2)). Wrong, swapped or
// unscaled vectors, or a truncation at the wrong rank, leave the reconstruction above the optimum. The
// reported error and singular values must equal the test's own.
TEST(MinmaxLowRank, TablesReachTheOptimalRankNError) {
    for (LightKind kind : {LightKind::Spot, LightKind::Directional}) {
        auto f = viz::minmax::makeFrame<double>(kind, glm::dvec3(0.0, 6.0, -7.0), glm::dvec3(0.1, -1.0, 0.0));
        f.gammaLo = kind == LightKind::Spot ? 0.3 : 0.0;
        f.gammaHi = kind == LightKind::Spot ? 1.4 : 12.0;
        const double betaLo = 0.3, betaHi = 1.9, sigmaS = 0.12, sigmaT = 0.13, g = 0.2;
        const int n = viz::minmax::kGrid;
        Eigen::MatrixXd m(n, n);
        for (int k = 0; k < n; ++k)
            for (int j = 0; j < n; ++j)
                m(k, j) = viz::minmax::scaledIntegrand(f, betaLo + k * (betaHi - betaLo) / (n - 1),
                                                       f.gammaLo + j * (f.gammaHi - f.gammaLo) / (n - 1), sigmaS, sigmaT, g);
        Eigen::MatrixXd h = Eigen::MatrixXd::Zero(2 * n, 2 * n);
        h.topRightCorner(n, n) = m;
        h.bottomLeftCorner(n, n) = m.transpose();
        const Eigen::VectorXd ascending = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(h, Eigen::EigenvaluesOnly).eigenvalues();
        const Eigen::VectorXd sv = ascending.tail(n).reverse();
        const double all = sv.squaredNorm();
        double last = 2.0;
        for (int rank = 1; rank <= viz::minmax::kMaxRank; ++rank) {
            const auto lr = viz::minmax::lowRankIntegrand(f, betaLo, betaHi, sigmaS, sigmaT, g, rank);
            double residual = 0.0;
            for (int k = 0; k < n; ++k) {
                for (int j = 0; j < n; ++j) {
                    double r = 0.0;
                    for (int i = 0; i < viz::minmax::kMaxRank; ++i)
                        r += double(lr.basisB[std::size_t(i * n + k)]) * double(lr.basisGamma[std::size_t(i * n + j)]);
                    residual += (m(k, j) - r) * (m(k, j) - r);
                }
            }
            const double error = std::sqrt(residual / all);
            const double optimum = std::sqrt(sv.tail(n - rank).squaredNorm() / all);
            // float tables add ~1e-7 of the matrix's norm
            EXPECT_LE(error, optimum + 2e-6) << "kind " << int(kind) << " rank " << rank;
            EXPECT_NEAR(lr.reconstructionError, error, 2e-6) << "rank " << rank;
            for (int i = 0; i < n; ++i) EXPECT_NEAR(lr.singularValues[std::size_t(i)], sv(i), 1e-9 * sv(0)) << i;
            last = error;
        }
        EXPECT_LT(last, 1e-3) << "kind " << int(kind);
        std::printf("kind %d: rank-8 reconstruction error %.2e (optimum %.2e)\n", int(kind), last,
                    std::sqrt(sv.tail(n - viz::minmax::kMaxRank).squaredNorm() / all));
    }
}

// rowIntegralError (what integrand=auto decides on) sees what the grid's own reconstruction error cannot:
// on a moderate medium both are small and the row error falls with rank and table resolution; a thick
// medium (sigma_t = 50: the integrand changes within a grid step) leaves the row error over ten times the
// grid's, and a sun whose gamma range is 1e6 long (its light lives in the first of 64 grid steps) leaves
// the factorisation exact on the grid and the tables wholly wrong on the rays.
TEST(MinmaxLowRank, RowIntegralErrorSeesWhatTheGridCannot) {
    using viz::minmax::lowRankIntegrand;
    using viz::minmax::rowIntegralError;
    auto spot = viz::minmax::makeFrame<double>(LightKind::Spot, glm::dvec3(0.0, 6.0, -7.0), glm::dvec3(0.1, -1.0, 0.0));
    spot.gammaLo = 0.3;
    spot.gammaHi = 1.4;
    const double betaLo = 0.3, betaHi = 1.9;
    const auto coarse = lowRankIntegrand(spot, betaLo, betaHi, 0.12, 0.13, 0.2, 2);
    const auto fine = lowRankIntegrand(spot, betaLo, betaHi, 0.12, 0.13, 0.2, 8);
    const double eCoarse = rowIntegralError(spot, coarse, 0.12, 0.13, 0.2, 16);
    const double eFine = rowIntegralError(spot, fine, 0.12, 0.13, 0.2, 1024);
    EXPECT_LT(eFine, 1e-3);
    EXPECT_LT(eFine, eCoarse);

    // The thick medium seen from 0.5 units beside the light (as in the stiff case extinction-50).
    auto close = viz::minmax::makeFrame<double>(LightKind::Spot, glm::dvec3(0.0, 0.3, -0.4), glm::dvec3(0.1, -1.0, 0.0));
    close.gammaLo = 0.3;
    close.gammaHi = 1.4;
    const auto thick = lowRankIntegrand(close, betaLo, betaHi, 25.0, 50.0, 0.2, 4);
    const double eThick = rowIntegralError(close, thick, 25.0, 50.0, 0.2, 256);
    EXPECT_GT(eThick, 10.0 * thick.reconstructionError);

    auto sun = viz::minmax::makeFrame<double>(LightKind::Directional, glm::dvec3(0.0), glm::dvec3(0.3, -1.0, 0.2));
    sun.gammaLo = 0.0;
    sun.gammaHi = 1e6;
    const auto huge = lowRankIntegrand(sun, betaLo, betaHi, 0.05, 0.1, 0.0, 4);
    EXPECT_LT(huge.reconstructionError, 1e-3);
    EXPECT_GT(rowIntegralError(sun, huge, 0.05, 0.1, 0.0, 256), 0.5);
    sun.gammaHi = 30.0;  // the same sun over the 30 units its light reaches: resolved
    const auto near = lowRankIntegrand(sun, betaLo, betaHi, 0.05, 0.1, 0.0, 4);
    EXPECT_LT(rowIntegralError(sun, near, 0.05, 0.1, 0.0, 256), 0.01);
    std::printf("row integral error: spot rank 2 / 16 texels %.2e, rank 8 / 1024 texels %.2e, sigma_t 50 %.2e "
                "(grid %.2e), sun over 1e6 %.2e (grid %.2e)\n",
                eCoarse, eFine, eThick, thick.reconstructionError, rowIntegralError(sun, huge, 0.05, 0.1, 0.0, 256),
                huge.reconstructionError);
}

}  // namespace

// The plots the window shows for the low-rank integrand (charts.h) carry its numbers: every positive
// singular value once (kept ones first, the dropped curve starting at the last kept value), and each
// kept B_i / Gamma_i at its grid abscissa, in degrees, or for a directional light gamma = rho in scene units.
TEST(MinmaxLowRank, ThePlotsCarryTheSingularValuesAndBasisFunctions) {
    for (LightKind kind : {LightKind::Spot, LightKind::Directional}) {
        auto f = viz::minmax::makeFrame<double>(kind, glm::dvec3(0.0, 6.0, -7.0), glm::dvec3(0.1, -1.0, 0.0));
        f.gammaLo = kind == LightKind::Spot ? 0.3 : 0.0;
        f.gammaHi = kind == LightKind::Spot ? 1.4 : 12.0;
        const auto lr = viz::minmax::lowRankIntegrand(f, 0.3, 1.9, 0.12, 0.13, 0.2, 3);
        const viz::PlotData s = viz::minmax::singularValuesPlot(lr);
        EXPECT_TRUE(s.logY);
        ASSERT_EQ(s.curves.size(), 2u);
        ASSERT_EQ(s.curves[0].points.size(), 3u);
        for (int i = 0; i < 3; ++i) {
            EXPECT_EQ(s.curves[0].points[std::size_t(i)], glm::dvec2(i + 1, lr.singularValues[std::size_t(i)]));
        }
        int positive = 0;
        for (double v : lr.singularValues) positive += v > 0.0;
        EXPECT_EQ(s.curves[0].points.size() + s.curves[1].points.size(), std::size_t(positive) + 1);
        EXPECT_EQ(s.curves[1].points.front(), s.curves[0].points.back());

        const auto b = viz::minmax::basisPlots(lr, kind == LightKind::Directional);
        ASSERT_EQ(b.size(), 2u);
        ASSERT_EQ(b[0].curves.size(), 3u);
        ASSERT_EQ(b[1].curves.size(), 3u);
        const double toDegrees = 180.0 / std::numbers::pi;
        for (int i = 0; i < 3; ++i) {
            const auto& bi = b[0].curves[std::size_t(i)].points;
            const auto& gi = b[1].curves[std::size_t(i)].points;
            ASSERT_EQ(bi.size(), std::size_t(viz::minmax::kGrid));
            EXPECT_NEAR(bi.front().x, 0.3 * toDegrees, 1e-12);
            EXPECT_NEAR(bi.back().x, 1.9 * toDegrees, 1e-12);
            EXPECT_EQ(bi[10].y, double(lr.basisB[std::size_t(i * viz::minmax::kGrid + 10)]));
            EXPECT_EQ(gi[20].y, double(lr.basisGamma[std::size_t(i * viz::minmax::kGrid + 20)]));
            const double scale = kind == LightKind::Directional ? 1.0 : toDegrees;
            EXPECT_NEAR(gi.back().x, lr.gammaHi * scale, 1e-9 * scale);
        }
        EXPECT_NE(b[1].xLabel.find(kind == LightKind::Directional ? "scene units" : "degrees"), std::string::npos);
    }
}

// The reconstruction-error view: cell (x = j, y = k) is |I - I_N| / max |I| with I recomputed here from
// the integrand at (beta_k, gamma_j) (not read from the factorisation's samples); its Frobenius norm
// gives the factorisation's own figure, and rank 8 errs less than rank 2 everywhere it matters.
TEST(MinmaxLowRank, TheReconstructionErrorViewMapsEachCellsError) {
    using viz::minmax::kGrid;
    auto spot = viz::minmax::makeFrame<double>(LightKind::Spot, glm::dvec3(0.0, 6.0, -7.0), glm::dvec3(0.1, -1.0, 0.0));
    spot.gammaLo = 0.3;
    spot.gammaHi = 1.4;
    const double betaLo = 0.3, betaHi = 1.9, sigmaS = 0.12, sigmaT = 0.13, g = 0.2;
    double worst2 = 0.0, worst8 = 0.0;
    for (int rank : {2, 8}) {
        const auto lr = viz::minmax::lowRankIntegrand(spot, betaLo, betaHi, sigmaS, sigmaT, g, rank);
        const viz::Image view = viz::minmax::reconstructionErrorView(lr);
        ASSERT_EQ(view.width, kGrid);
        ASSERT_EQ(view.height, kGrid);
        double peak = 0.0;
        std::vector<double> truth(std::size_t(kGrid * kGrid));
        for (int k = 0; k < kGrid; ++k)
            for (int j = 0; j < kGrid; ++j) {
                const double beta = betaLo + k * (betaHi - betaLo) / (kGrid - 1);
                const double gamma = spot.gammaLo + j * (spot.gammaHi - spot.gammaLo) / (kGrid - 1);
                truth[std::size_t(k * kGrid + j)] = viz::minmax::scaledIntegrand(spot, beta, gamma, sigmaS, sigmaT, g);
                peak = std::max(peak, std::abs(truth[std::size_t(k * kGrid + j)]));
            }
        ASSERT_GT(peak, 0.0);
        double num = 0.0, den = 0.0, worst = 0.0;
        for (int k = 0; k < kGrid; ++k)
            for (int j = 0; j < kGrid; ++j) {
                const double d = truth[std::size_t(k * kGrid + j)] - viz::minmax::reconstruct(lr, k, j);
                EXPECT_NEAR(view.at(j, k, 0), std::abs(d) / peak, 1e-6) << "cell " << j << ", " << k;
                num += d * d;
                den += truth[std::size_t(k * kGrid + j)] * truth[std::size_t(k * kGrid + j)];
                worst = std::max(worst, double(view.at(j, k, 0)));
            }
        EXPECT_NEAR(std::sqrt(num / den), lr.reconstructionError, 1e-6 * std::max(1.0, lr.reconstructionError));
        (rank == 2 ? worst2 : worst8) = worst;
    }
    EXPECT_LT(worst8, worst2);
    EXPECT_GT(worst2, 0.0);
}
