#include "techniques/polyvol/airlight_lut.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "shared/airlight.h"

namespace viz::polyvol {

double AirlightLut::scaleOf(double tauH) { return tauH / (1.0 + tauH); }

double AirlightLut::columnSpan() { return std::asinh(kTauMax / scaleOf(kTauMin)); }

double AirlightLut::column(double u, double tauH) {
    const double s = scaleOf(std::max(tauH, kTauMin));
    return std::clamp(std::asinh(std::min(std::abs(u), kTauMax) / s) / columnSpan(), 0.0, 1.0);
}

double AirlightLut::row(double tauH) {
    const double lo = std::log(kTauMin), hi = std::log(kTauMax);
    return std::clamp((std::log(std::max(tauH, kTauMin)) - lo) / (hi - lo), 0.0, 1.0);
}

double AirlightLut::tauAt(int j, int n) {
    const double lo = std::log(kTauMin), hi = std::log(kTauMax);
    return std::exp(lo + (hi - lo) * double(j) / double(n - 1));
}

double AirlightLut::uAt(int i, int n, double tauH) {
    return std::min(scaleOf(tauH) * std::sinh(columnSpan() * double(i) / double(n - 1)), kTauMax);
}

// A(u) = tau_h int_{-kTauMax}^{-|u|} f: tP = 0 puts x = u, so pointSegment's e^{-sigma_t (x + r)} is
// e^{-(u + rho)} with sigma_t = 1. Split at -max(|u|, tau_h): pointSegment raises h to 1e-7 times the
// segment's extent when the foot point is inside or at an end of the segment (its guard for rays through
// a light), which for [-200, 0] would replace a tau_h below 2e-5; on each piece the extent is at most
// max(|u|, tau_h) wherever P touches it, so the guard never exceeds 1e-7 tau_h there.
double lutChannelA(double u, double tauH, double g) {
    const double end = -std::min(std::abs(u), AirlightLut::kTauMax);
    const double split = std::max(-AirlightLut::kTauMax, std::min(end, -tauH));
    return tauH * (airlight::pointSegment<double>(0.0, tauH, -AirlightLut::kTauMax, split, 1.0, 1.0, g, 1.0) +
                   airlight::pointSegment<double>(0.0, tauH, split, end, 1.0, 1.0, g, 1.0));
}

double AirlightLut::nearSideDecay(double u, double tauH) {
    u = std::abs(u);
    return tauH * tauH / (std::hypot(u, tauH) + u);  // rho - |u| without the cancellation
}

// C(u) = tau_h e^{rho - |u|} int_{-|u|}^0 f, split at -tau_h as A is (pointSegment's guard for a foot point
// at an end).
double lutChannelC(double u, double tauH, double g) {
    const double end = -std::min(std::abs(u), AirlightLut::kTauMax);
    const double split = std::min(0.0, std::max(end, -tauH));
    return tauH * std::exp(AirlightLut::nearSideDecay(end, tauH)) *
           (airlight::pointSegment<double>(0.0, tauH, end, split, 1.0, 1.0, g, 1.0) +
            airlight::pointSegment<double>(0.0, tauH, split, 0.0, 1.0, 1.0, g, 1.0));
}

// B(u) = tau_h e^{u + rho} int_u^inf f: tP = -u puts the segment start at x = 0, so pointSegment returns
// e^{-rho(u)} e^{u} int_u^inf f (its own exponent stays small).
double lutChannelB(double u, double tauH, double g) {
    u = std::abs(u);
    const double rho = std::hypot(u, tauH);
    return tauH * std::exp(rho) *
           airlight::pointSegment<double>(-u, tauH, 0.0, std::numeric_limits<double>::infinity(), 1.0, 1.0, g, 1.0);
}

namespace {

// tau_h int f du over the part of the ray between |u| = ua and |u| = ub (0 <= ua <= ub), before the foot
// point (side = -1: u in [-ub, -ua]) or after it (side = +1: u in [ua, ub]), in y = asinh(u / tau_h):
// tau_h f du = p(-tanh y) e^{-tau_h e^y} / cosh(y) dy. One 16-point Gauss-Legendre panel: between two
// neighbouring columns the integrand is analytic and changes by at most a factor ~e^{-10} (the last
// columns of the thickest rows), where the rule's error is below 1e-11 of the panel.
double piece(double ua, double ub, double tauH, int side, double g) {
    if (!(ub > ua)) return 0.0;
    using Rule = airlight::GaussLegendre<16>;
    const double ya = double(side) * std::asinh(ua / tauH), yb = double(side) * std::asinh(ub / tauH);
    const double lo = std::min(ya, yb), hi = std::max(ya, yb);
    const double half = 0.5 * (hi - lo), mid = 0.5 * (hi + lo);
    auto integrand = [&](double y) {
        const double e = std::exp(-std::abs(y)), e2 = e * e;
        const double sech = 2.0 * e / (1.0 + e2);
        // 1 -+ cos(theta_s) with cos(theta_s) = -tanh(y), from e = e^{-|y|} (no cancellation).
        const double oneMinusCos = y >= 0.0 ? 2.0 / (1.0 + e2) : 2.0 * e2 / (1.0 + e2);
        const double onePlusCos = y >= 0.0 ? 2.0 * e2 / (1.0 + e2) : 2.0 / (1.0 + e2);
        return airlight::phaseHGFromCosTerms(oneMinusCos, onePlusCos, g) * std::exp(-tauH * std::exp(y)) * sech;
    };
    double sum = 0.0;
    for (int k = 0; k < 8; ++k) {
        const double dx = half * Rule::kX[k];
        sum += Rule::kW[k] * (integrand(mid - dx) + integrand(mid + dx));
    }
    return sum * half;
}

}  // namespace

// Row by row, from the last column (|u| = kTauMax, where A = 0 and B comes from the closed form) towards
// the foot point, adding one Gauss-Legendre panel per column interval to both running integrals: A is the
// integral before P from -kTauMax to -|u|, T the integral after P from |u| to infinity, B = e^{u + rho} T.
// Then from the foot point outwards for C, the integral before P from -|u| to 0, with the same panels.
// All terms are positive, so the running sums keep their relative accuracy (double, ~1e-13).
AirlightLut buildAirlightLut(double g, int width, int height) {
    AirlightLut lut;
    lut.width = width;
    lut.height = height;
    lut.g = g;
    constexpr int n = AirlightLut::kChannels;
    lut.texels.resize(std::size_t(width) * std::size_t(height) * n);
    for (int j = 0; j < height; ++j) {
        const double tauH = AirlightLut::tauAt(j, height);
        double before = 0.0;
        double uPrevious = AirlightLut::kTauMax;
        // tau_h int_{kTauMax}^{inf} f, e^{-(u + rho)} included.
        double after = lutChannelB(AirlightLut::kTauMax, tauH, g) *
                       std::exp(-(AirlightLut::kTauMax + std::hypot(AirlightLut::kTauMax, tauH)));
        for (int i = width - 1; i >= 0; --i) {
            const double u = AirlightLut::uAt(i, width, tauH);
            before += piece(u, uPrevious, tauH, -1, g);
            after += piece(u, uPrevious, tauH, +1, g);
            uPrevious = u;
            const std::size_t k = (std::size_t(j) * std::size_t(width) + std::size_t(i)) * n;
            lut.texels[k] = float(before);
            lut.texels[k + 1] = float(std::exp(u + std::hypot(u, tauH)) * after);
        }
        double fromP = 0.0;
        uPrevious = 0.0;  // column 0 is the foot point, where C = 0
        for (int i = 1; i < width; ++i) {
            const double u = AirlightLut::uAt(i, width, tauH);
            fromP += piece(uPrevious, u, tauH, -1, g);
            uPrevious = u;
            lut.texels[(std::size_t(j) * std::size_t(width) + std::size_t(i)) * n + 2] =
                float(std::exp(AirlightLut::nearSideDecay(u, tauH)) * fromP);
        }
    }
    return lut;
}

}  // namespace viz::polyvol
