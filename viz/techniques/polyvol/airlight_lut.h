// The 2D airlight lookup table of Billeter et al.'s supplement (after Sun et al. 2005), generated from the
// double closed form of viz/shared/airlight.h. Mirrored by shaders/polyvol/airlight_lut.glsl.
//
// In optical units (u = sigma_t s along the ray from the light's foot point P, tau_h = sigma_t h), the
// unit-intensity point-light integrand is f(u) = p(cos) e^{-(u + rho)} / rho^2, rho = sqrt(u^2 + tau_h^2),
// and  int_x0^x1 sigma_s p e^{-sigma_t (x + r)} / r^2 dx = sigma_s sigma_t e^{-sigma_t tP} int f du.
// Three premultiplied channels (the supplement's "premult" and its split at the foot point):
//   R: A(u) = tau_h int_{-kTauMax}^{-|u|} f du                 (the part before P, from its far end)
//   G: B(u) = tau_h e^{|u| + rho(|u|)} int_{|u|}^{inf} f du     (the part after P, its decay factored out)
//   B: C(u) = tau_h e^{rho(|u|) - |u|} int_{-|u|}^{0} f du      (the part before P, from P, its decay
//                                                               at -|u| factored out)
// A segment is then a difference of A values times e^{-sigma_t tP}, of C values times
// e^{-sigma_t tP - (rho - |u|)} and of B values times e^{-sigma_t x - rho}: every exponent is formed
// before exponentiating (no overflow, docs/numerics.md#combined-exponents). Before P, A(near) - A(far)
// and C(far) - C(near) are the same integral; the shader takes the one whose larger term is smaller. In
// thick rows (tau_h above ~1) the integrand before P is largest far from P: A near P is a large total,
// and a stretch next to P is a small difference of two such totals, each interpolated between rows: with
// A alone [0, 3] through P was 2.1e-3 off at tau_h = 3, 1.2e-2 at 10 and 0.67 at 30. Near P the
// integrand falls as e^{-tau_h} from row to row; C has that decay factored out, so it interpolates
// between rows as smoothly as B does.
//
// Axes. Rows: log tau_h over [kTauMin, kTauMax]. Columns: y = asinh(|u| / s), s = tau_h / (1 + tau_h),
// linear in y over [0, columnSpan()], columnSpan() = asinh(kTauMax / s(kTauMin)), the same y in every
// row. Near P the channels vary on the scale |u| ~ tau_h (the 1/rho^2 bump) when tau_h < 1 and on the
// scale |u| ~ 1 (the attenuation) when tau_h > 1, i.e. on the scale s; asinh(|u| / s) is linear in |u|
// below it and logarithmic above, and column 0 is exactly the foot point. (A first version mapped log |u|
// over [1e-5, 200]: the stretch |u| < 1e-5 around P was never counted, which lost 0.64 % of a ray's
// airlight at tau_h = 1e-3, 6.3 % at 1e-4 and half near 1e-5; README, "Rays next to the light".)
// Below kTauMin (a ray within 1e-9 optical units of the light) and at sigma_t = 0 the shader evaluates the
// closed form instead. The table depends on g only (sigma_t is scaled out), so it is built per medium g.
#pragma once

#include <vector>

namespace viz::polyvol {

struct AirlightLut {
    static constexpr double kTauMin = 1e-9;
    static constexpr double kTauMax = 200.0;  // beyond: e^{-200} of attenuation, or a clamped anchor
    // The technique's table size (columns x rows): 1.5e-4 relative on rays passing the light (README).
    static constexpr int kWidth = 1024, kHeight = 512;
    int width = 0;   // asinh(|u| / s) axis
    int height = 0;  // log tau_h axis
    double g = 0.0;
    static constexpr int kChannels = 3;  // A, B, C
    std::vector<float> texels;           // width * height * kChannels, row = tau_h index

    // s(tau_h) = tau_h / (1 + tau_h): the length scale of the columns.
    static double scaleOf(double tauH);
    // asinh(kTauMax / s(kTauMin)): the largest column coordinate y.
    static double columnSpan();
    // Table coordinates in [0, 1] (clamped): of |u| in the row of tau_h, and of tau_h.
    static double column(double u, double tauH);
    static double row(double tauH);
    // rho - |u| = tau_h^2 / (rho + |u|): the attenuation exponent factored out of C at -|u|.
    static double nearSideDecay(double u, double tauH);
    // tau_h of row j of n; |u| of column i of n in the row of tau_h (capped at kTauMax).
    static double tauAt(int j, int n);
    static double uAt(int i, int n, double tauH);
};

// Builds the table for phase asymmetry g (the double closed form at every sample; rows in parallel).
AirlightLut buildAirlightLut(double g, int width, int height);

// The closed-form channels at one point (what the table samples).
double lutChannelA(double u, double tauH, double g);
double lutChannelB(double u, double tauH, double g);
double lutChannelC(double u, double tauH, double g);

}  // namespace viz::polyvol
