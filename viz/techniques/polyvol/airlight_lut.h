// The 2D airlight lookup table of Billeter et al.'s supplement (after Sun et al. 2005), generated from the
// double closed form of viz/shared/airlight.h. Mirrored by shaders/polyvol/airlight_lut.glsl.
//
// In optical units (u = sigma_t s along the ray from the light's foot point P, tau_h = sigma_t h), the
// unit-intensity point-light integrand is f(u) = p(cos) e^{-(u + rho)} / rho^2, rho = sqrt(u^2 + tau_h^2),
// and  int_x0^x1 sigma_s p e^{-sigma_t (x + r)} / r^2 dx = sigma_s sigma_t e^{-sigma_t tP} int f du.
// Two premultiplied channels, both O(1) over the whole table (the supplement's "premult" and its split
// at the foot point), on log-mapped axes |u|, tau_h in [kTauMin, kTauMax]:
//   R: A(u) = tau_h int_{-kTauMax}^{-|u|} f du                 (the part before P)
//   G: B(u) = tau_h e^{|u| + rho(|u|)} int_{|u|}^{inf} f du     (the part after P, its decay factored out)
// A segment is then a difference of A values times e^{-sigma_t tP} and of B values times
// e^{-sigma_t x - rho}: every exponent is formed before exponentiating (no overflow, NUMERICS.md row 3).
// The table depends on g only (sigma_t is scaled out), so it is built per medium g.
#pragma once

#include <vector>

namespace viz::polyvol {

struct AirlightLut {
    static constexpr double kTauMin = 1e-5;
    static constexpr double kTauMax = 200.0;  // beyond: e^{-200} of attenuation, or a clamped anchor
    int width = 0;   // |u| axis
    int height = 0;  // tau_h axis
    double g = 0.0;
    std::vector<float> rg;  // width * height * 2, row = tau_h index

    // Table coordinate in [0, 1] of an optical length (clamped to the axis).
    static double axis(double tau);
    // The optical length of sample k of n along an axis.
    static double tauAt(int k, int n);
};

// Builds the table for phase asymmetry g (the double closed form at every sample).
AirlightLut buildAirlightLut(double g, int width, int height);

// The closed-form channels at one point (what the table samples).
double lutChannelA(double u, double tauH, double g);
double lutChannelB(double u, double tauH, double g);

}  // namespace viz::polyvol
