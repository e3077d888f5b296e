#include "techniques/minmax/low_rank.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Dense>

#include "core/error.h"
#include "shared/airlight.h"

namespace viz::minmax {

double scaledIntegrand(const EpipolarFrame<double>& f, double beta, double gamma, double sigmaS, double sigmaT,
                       double g) {
    if (f.kind == LightKind::Directional) {
        const double s = std::sin(beta);
        if (!(s > 0.0)) return 0.0;
        return sigmaS * airlight::phaseHG(std::cos(beta), g) * std::exp(-sigmaT * gamma / s);
    }
    const double s = std::sin(beta + gamma);
    if (!(s > 0.0) || beta + gamma >= std::numbers::pi) return 0.0;
    const double D = f.lightDistance;
    const double t = D * std::sin(gamma) / s;
    const double r = D * std::sin(beta) / s;
    return sigmaS * airlight::phaseHG(std::cos(beta + gamma), g) * std::exp(-sigmaT * (t + r)) / D;
}

LowRank lowRankIntegrand(const EpipolarFrame<double>& f, double betaLo, double betaHi, double sigmaS,
                         double sigmaT, double g, int rank) {
    VIZ_CHECK(rank >= 1 && rank <= kMaxRank, "rank out of range");
    LowRank lr;
    lr.betaLo = betaLo;
    lr.betaHi = std::max(betaHi, betaLo + 1e-6);
    lr.gammaLo = f.gammaLo;
    lr.gammaHi = f.gammaHi;
    lr.rank = rank;
    Eigen::MatrixXd m(kGrid, kGrid);
    for (int k = 0; k < kGrid; ++k) {
        const double beta = lr.betaLo + k * (lr.betaHi - lr.betaLo) / (kGrid - 1);
        for (int j = 0; j < kGrid; ++j) {
            const double gamma = lr.gammaLo + j * (lr.gammaHi - lr.gammaLo) / (kGrid - 1);
            m(k, j) = scaledIntegrand(f, beta, gamma, sigmaS, sigmaT, g);
        }
    }
    lr.samples.assign(m.data(), m.data() + m.size());  // column-major: index k + 64 j
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(m, Eigen::ComputeThinU | Eigen::ComputeThinV);
    const Eigen::VectorXd s = svd.singularValues();
    lr.singularValues.assign(s.data(), s.data() + s.size());
    lr.basisB.assign(std::size_t(kMaxRank * kGrid), 0.0f);
    lr.basisGamma.assign(std::size_t(kMaxRank * kGrid), 0.0f);
    for (int i = 0; i < rank; ++i) {
        for (int k = 0; k < kGrid; ++k) lr.basisB[std::size_t(i * kGrid + k)] = float(s(i) * svd.matrixU()(k, i));
        for (int j = 0; j < kGrid; ++j) lr.basisGamma[std::size_t(i * kGrid + j)] = float(svd.matrixV()(j, i));
    }
    double num = 0.0, den = 0.0;
    for (int k = 0; k < kGrid; ++k)
        for (int j = 0; j < kGrid; ++j) {
            const double d = m(k, j) - reconstruct(lr, k, j);
            num += d * d;
            den += m(k, j) * m(k, j);
        }
    lr.reconstructionError = den > 0.0 ? std::sqrt(num / den) : 0.0;
    return lr;
}

double reconstruct(const LowRank& lr, int k, int j) {
    double sum = 0.0;
    for (int i = 0; i < lr.rank; ++i)
        sum += double(lr.basisB[std::size_t(i * kGrid + k)]) * double(lr.basisGamma[std::size_t(i * kGrid + j)]);
    return sum;
}

}  // namespace viz::minmax
