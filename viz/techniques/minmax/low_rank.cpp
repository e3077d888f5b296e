#include "techniques/minmax/low_rank.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
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

namespace {

// A basis row sampled at 64 points over [lo, hi], read at x with linear interpolation (shaders'
// betaBasis / gammaBasis: clamped to the range, the last cell closed).
double interpolated(const std::vector<float>& basis, int i, double lo, double hi, double x) {
    const double u = std::clamp((x - lo) / (hi - lo), 0.0, 1.0) * (kGrid - 1);
    const int k = std::min(int(std::floor(u)), kGrid - 2);
    const double w = u - k;
    const double a = basis[std::size_t(i * kGrid + k)], b = basis[std::size_t(i * kGrid + k + 1)];
    return a + (b - a) * w;
}

}  // namespace

double rowIntegralError(const EpipolarFrame<double>& f, const LowRank& lr, double sigmaS, double sigmaT, double g,
                        int textureColumns) {
    VIZ_CHECK(textureColumns >= 1, "rowIntegralError needs at least one table texel");
    const double dGamma = (lr.gammaHi - lr.gammaLo) / textureColumns;
    // The tables' sums over the whole row: sum_j Gamma_i(gamma_j) dgamma, per rank.
    std::vector<double> table(std::size_t(lr.rank), 0.0);
    for (int i = 0; i < lr.rank; ++i)
        for (int j = 0; j < textureColumns; ++j)
            table[std::size_t(i)] +=
                interpolated(lr.basisGamma, i, lr.gammaLo, lr.gammaHi, lr.gammaLo + (j + 0.5) * dGamma) * dGamma;
    std::vector<std::pair<double, double>> rays;  // (tables, segment integral)
    for (int m = 0; m + 1 < kGrid; ++m) {
        const double beta = lr.betaLo + (m + 0.5) * (lr.betaHi - lr.betaLo) / (kGrid - 1);
        const double sinBeta = std::sin(beta);
        if (!(sinBeta > 0.0)) continue;
        double approx = 0.0;
        for (int i = 0; i < lr.rank; ++i)
            approx += interpolated(lr.basisB, i, lr.betaLo, lr.betaHi, beta) * table[std::size_t(i)];
        approx /= sinBeta;
        const double t0 = distanceAtGamma(f, beta, lr.gammaLo), t1 = distanceAtGamma(f, beta, lr.gammaHi);
        double exact = 0.0;
        if (f.kind == LightKind::Directional) {
            exact = airlight::directionalSegment(std::cos(beta), t0, t1, sigmaS, sigmaT, g, 1.0);
        } else {
            const glm::dvec3 w = std::cos(beta) * f.axis + sinBeta * f.u;
            const auto geo = airlight::rayLightGeometry(f.lightDistance * f.axis, w);
            exact = airlight::pointSegment<double>(geo.tP, geo.h, t0, t1, sigmaS, sigmaT, g, 1.0);
        }
        rays.emplace_back(approx, exact);
    }
    // Scaled by the largest value first: a thick medium's integrals (e^-400) would underflow when squared.
    double scale = 0.0;
    for (const auto& [approx, exact] : rays) scale = std::max({scale, std::abs(approx), std::abs(exact)});
    if (!(scale > 0.0)) return scale == 0.0 ? 0.0 : std::numeric_limits<double>::quiet_NaN();
    double num = 0.0, den = 0.0;
    for (const auto& [approx, exact] : rays) {
        num += (approx - exact) / scale * ((approx - exact) / scale);
        den += exact / scale * (exact / scale);
    }
    return den > 0.0 ? std::sqrt(num / den) : (num > 0.0 ? 1.0 : 0.0);
}

}  // namespace viz::minmax
