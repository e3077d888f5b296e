// The low-rank integrand of Chen et al. 2011, section 3.2 (`integrand=svd`): everything in the scattering
// integral but the visibility (and, section 3.4, but the light's angular texture T), as a function of beta
// and gamma, sampled on a 64 x 64 grid and approximated by its top N singular vectors,
//   I(beta, gamma) ~ sum_i B_i(beta) Gamma_i(gamma),   L(alpha, beta) = sum_i B_i(beta) sum_lit Gamma_i T dgamma.
// Per unit light intensity, with the Jacobian dt/dgamma of the camera ray (epipolar.h):
//   spot:        I = sigma_s p(cos(beta + gamma)) exp(-sigma_t (t + r)) / (D sin(beta))
//                (t = D sin(gamma) / sin(beta + gamma), r = D sin(beta) / sin(beta + gamma): the 1/r^2
//                 falloff times dt/dgamma = D sin(beta) / sin^2(beta + gamma)), 0 for gamma >= pi - beta;
//   directional: I = sigma_s p(cos(beta)) exp(-sigma_t gamma / sin(beta)) / sin(beta).
// Both carry 1 / sin(beta), singular at the epipole: the SVD factorises I sin(beta) instead and the shader
// divides by sin(beta) again, so the grid sees a bounded, smooth function.
#pragma once

#include <vector>

#include "techniques/minmax/epipolar.h"

namespace viz::minmax {

inline constexpr int kGrid = 64;
inline constexpr int kMaxRank = 8;

struct LowRank {
    double betaLo = 0.0, betaHi = 1.0;    // B_i sampled at beta_k = betaLo + k (betaHi - betaLo) / 63
    double gammaLo = 0.0, gammaHi = 1.0;  // Gamma_i sampled at gamma_j = gammaLo + j (gammaHi - gammaLo) / 63
    int rank = 4;
    std::vector<double> singularValues;   // all 64, descending
    std::vector<float> basisB;            // kMaxRank x 64: B_i(beta_k) = s_i u_i(k) (zero beyond rank)
    std::vector<float> basisGamma;        // kMaxRank x 64: Gamma_i(gamma_j) = v_i(j)
    std::vector<double> samples;          // 64 x 64 of I sin(beta), row k = beta_k
    double reconstructionError = 0.0;     // ||I - I_N||_F / ||I||_F on the grid
};

// I(beta, gamma) sin(beta) of the header comment.
double scaledIntegrand(const EpipolarFrame<double>& f, double beta, double gamma, double sigmaS, double sigmaT,
                       double g);

LowRank lowRankIntegrand(const EpipolarFrame<double>& f, double betaLo, double betaHi, double sigmaS,
                         double sigmaT, double g, int rank);

// Rank-N reconstruction of the scaled integrand at grid point (k, j).
double reconstruct(const LowRank& lr, int k, int j);

// How far the tables the shaders read are from the true airlight of a fully lit ray, measured where the
// factorisation was not fitted: at the 63 betas half way between the grid's, each ray's integral over the
// frame's whole gamma range as the traversal would take it (B_i and Gamma_i interpolated linearly between
// their 64 samples as the shaders do, Gamma_i summed at the centres of `textureColumns` table texels as
// prefix.comp does) against the segment integral of the same ray (shared/airlight.h: pointSegment or
// directionalSegment, the analytic integrand's). Relative L2 over the 63 rays (0 when they carry no light).
// It sees what the grid's reconstruction error cannot: an integrand that changes within one grid step or
// one table texel (a thick medium, a sun's map spanning far more than the extinction length).
double rowIntegralError(const EpipolarFrame<double>& f, const LowRank& lr, double sigmaS, double sigmaT, double g,
                        int textureColumns);

}  // namespace viz::minmax
