#include "techniques/polyvol/airlight_lut.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "shared/airlight.h"

namespace viz::polyvol {

double AirlightLut::axis(double tau) {
    const double lo = std::log(kTauMin), hi = std::log(kTauMax);
    return std::clamp((std::log(std::max(tau, kTauMin)) - lo) / (hi - lo), 0.0, 1.0);
}

double AirlightLut::tauAt(int k, int n) {
    const double lo = std::log(kTauMin), hi = std::log(kTauMax);
    return std::exp(lo + (hi - lo) * double(k) / double(n - 1));
}

// A(u) = tau_h int_{-kTauMax}^{-u} f: tP = 0 puts x = u, so pointSegment's e^{-sigma_t (x + r)} is
// e^{-(u + rho)} with sigma_t = 1.
double lutChannelA(double u, double tauH, double g) {
    const double end = -std::min(u, AirlightLut::kTauMax);
    return tauH * airlight::pointSegment<double>(0.0, tauH, -AirlightLut::kTauMax, end, 1.0, 1.0, g, 1.0);
}

// B(u) = tau_h e^{u + rho} int_u^inf f: tP = -u puts the segment start at x = 0, so pointSegment returns
// e^{-rho(u)} e^{u} int_u^inf f (its own exponent stays small).
double lutChannelB(double u, double tauH, double g) {
    const double rho = std::hypot(u, tauH);
    return tauH * std::exp(rho) *
           airlight::pointSegment<double>(-u, tauH, 0.0, std::numeric_limits<double>::infinity(), 1.0, 1.0, g, 1.0);
}

AirlightLut buildAirlightLut(double g, int width, int height) {
    AirlightLut lut;
    lut.width = width;
    lut.height = height;
    lut.g = g;
    lut.rg.resize(std::size_t(width) * std::size_t(height) * 2);
    for (int j = 0; j < height; ++j) {
        const double tauH = AirlightLut::tauAt(j, height);
        for (int i = 0; i < width; ++i) {
            const double u = AirlightLut::tauAt(i, width);
            const std::size_t k = (std::size_t(j) * std::size_t(width) + std::size_t(i)) * 2;
            lut.rg[k] = float(lutChannelA(u, tauH, g));
            lut.rg[k + 1] = float(lutChannelB(u, tauH, g));
        }
    }
    return lut;
}

}  // namespace viz::polyvol
