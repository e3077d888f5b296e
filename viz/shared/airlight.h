// Airlight math shared by the CPU reference (double), its float mirror and the GPU techniques: the
// single-scattering integral from a point or directional light in a homogeneous medium along one
// segment of an eye ray. shaders/common/airlight.glsl holds the same functions with the same names and
// argument order; keep the two files line-by-line comparable when editing either. The one exception is
// the GLSL file's pointSegmentNaive (Sun et al.'s closed form as printed, compiled only under
// AIRLIGHT_NAIVE_CLOSED_FORM for raymarch's closed_form=naive teaching mode), which has no mirror here.
//
// Notation (docs/numerics.md#notation; Sun et al. 2005): D = light - eye (camera-relative), w the unit ray
// direction, tP = dot(D, w) the signed distance to the light's foot point P on the ray, h = |D x w| the
// light-to-ray distance, s = x - tP, r(x) = sqrt(s^2 + h^2), y = asinh(s / h), q = s + r = h e^y.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <glm/glm.hpp>

namespace viz::airlight {

// ---- Precision-dependent knobs --------------------------------------------------------------------
// kNodes: Gauss-Legendre nodes per panel (docs/numerics.md#quadrature). With the graded panels below, 8
//   (fp32) and 16 (fp64) per panel reach ~1e-5 and ~1e-13 (measured by tests/cpu/math/airlight_test.cpp
//   against Boost.Math), at 1-6 panels for ~90% of the test grid (up to 13 for a strong HG lobe with the
//   light beside the segment).
// kNearWidth (a): panel widths in y around each centre are a, 2a, then the rest.
// kAttenuationCut (K): the segment is cut where the extinction from its start exceeds e^-K.
// kWindow (W): the geometric factor 1/cosh(y) is below 2 e^-W farther than W from the closest approach.
// kAsinhLarge: above it asinh(a) = ln(2a) to working precision (the 1/(4a^2) term is below epsilon).
// kSeriesTerms: terms of the log1p and expm1 series near 0 (the first omitted one is below epsilon).
// kMinRelativeH: light-to-ray distance floor relative to the segment's extent (see pointSegment). It sits
//   a little above the rounding of h = |D x w| itself (~1e-7 |D| in float, ~1e-16 |D| in double), so it
//   only ever changes a ray that passes through the light to working precision; a ray passing 1e-6 from
//   a light 33 units down a 40-unit ray (h/extent 3e-8) keeps its own h in double.
template <typename Real>
struct Precision;

template <>
struct Precision<float> {
    static constexpr int kNodes = 8;
    static constexpr float kNearWidth = 2.0f;
    static constexpr float kAttenuationCut = 20.0f;
    static constexpr float kWindow = 17.0f;
    static constexpr float kAsinhLarge = 1e4f;
    static constexpr int kSeriesTerms = 10;
    static constexpr float kMinRelativeH = 1e-7f;
};

template <>
struct Precision<double> {
    static constexpr int kNodes = 16;
    static constexpr double kNearWidth = 2.0;
    static constexpr double kAttenuationCut = 40.0;
    static constexpr double kWindow = 30.0;
    static constexpr double kAsinhLarge = 1e9;
    static constexpr int kSeriesTerms = 18;
    static constexpr double kMinRelativeH = 1e-13;
};

// Absolute light-to-ray distance floor (see pointSegment), for a light at the segment's end.
inline constexpr double kMinAbsoluteH = 1e-15;
inline constexpr double kInv4Pi = 0.25 * std::numbers::inv_pi;

// ---- Gauss-Legendre rules on [-1, 1] ----------------------------------------------------------------
// Positive abscissae (descending) and their weights; the rule is symmetric. Values computed with mpmath
// (Newton iteration on P_N to 40 digits), printed to 21 digits.
template <int N>
struct GaussLegendre;

template <>
struct GaussLegendre<8> {
    static constexpr double kX[4] = {0.960289856497536231684, 0.796666477413626739592,
                                     0.525532409916328985818, 0.183434642495649804939};
    static constexpr double kW[4] = {0.101228536290376259153, 0.222381034453374470544,
                                     0.313706645877887287338, 0.362683783378361982965};
};

template <>
struct GaussLegendre<16> {
    static constexpr double kX[8] = {0.989400934991649932596, 0.944575023073232576078,
                                     0.86563120238783174388,  0.755404408355003033895,
                                     0.617876244402643748447, 0.458016777657227386342,
                                     0.28160355077925891323,  0.0950125098376374401853};
    static constexpr double kW[8] = {0.0271524594117540948518, 0.0622535239386478928628,
                                     0.0951585116824927848099, 0.124628971255533872052,
                                     0.149595988816576732082,  0.169156519395002538189,
                                     0.182603415044923588867,  0.189450610455068496285};
};

template <>
struct GaussLegendre<32> {
    static constexpr double kX[16] = {
        0.997263861849481563545, 0.9856115115452683354,   0.964762255587506430774,
        0.934906075937739689171, 0.896321155766052123965, 0.849367613732569970134,
        0.794483795967942406963, 0.732182118740289680387, 0.663044266930215200975,
        0.587715757240762329041, 0.506899908932229390024, 0.421351276130635345364,
        0.33186860228212764978,  0.239287362252137074545, 0.144471961582796493485,
        0.0483076656877383162348};
    static constexpr double kW[16] = {
        0.00701861000947009660041, 0.0162743947309056706052, 0.0253920653092620594558,
        0.0342738629130214331027,  0.0428358980222266806569, 0.0509980592623761761962,
        0.0586840934785355471453,  0.0658222227763618468377, 0.0723457941088485062254,
        0.0781938957870703064717,  0.0833119242269467552222, 0.0876520930044038111428,
        0.0911738786957638847129,  0.0938443990808045656392, 0.0956387200792748594191,
        0.0965400885147278005668};
};

// ---- Elementary helpers (GLSL has no log1p/expm1; docs/numerics.md#elementary-functions) ----------

// log(1 + x) without losing x when |x| << 1. Near 0 it uses the series
// log1p(x) = 2 atanh(z) = 2 (z + z^3/3 + z^5/5 + ...), z = x / (2 + x), |z| <= 1/3 on (-0.5, 1); outside,
// log(1 + x) is already accurate. No reliance on log() being relatively accurate near 1: GLSL only
// guarantees an absolute error of 2^-21 there, which breaks Kahan's log(u) x / (u - 1) trick on GPUs
// (measured: 3e-3 relative error on llvmpipe).
template <typename Real>
Real stableLog1p(Real x) {
    if (x > Real(-0.5) && x < Real(1)) {
        const Real z = x / (Real(2) + x);
        const Real z2 = z * z;
        Real sum = Real(0);
        for (int k = Precision<Real>::kSeriesTerms - 1; k >= 0; --k) {
            sum = Real(1) / Real(2 * k + 1) + z2 * sum;
        }
        return Real(2) * z * sum;
    }
    return std::log(Real(1) + x);
}

// exp(x) - 1 without cancellation: Taylor series (Horner form) for |x| < 0.5, exp(x) - 1 outside, where
// the subtraction loses at most a factor 2.5 in relative error.
template <typename Real>
Real stableExpm1(Real x) {
    if (std::abs(x) < Real(0.5)) {
        Real sum = Real(1);
        for (int k = Precision<Real>::kSeriesTerms; k >= 2; --k) {
            sum = Real(1) + x * sum / Real(k);
        }
        return x * sum;
    }
    return std::exp(x) - Real(1);
}

// asinh(x) = sign(x) log1p(|x| + x^2 / (1 + sqrt(1 + x^2))): exact for tiny |x|, no cancellation for
// x < 0 (the textbook log(x + sqrt(x^2 + 1)) returns 0 or -inf there), no overflow for huge |x|.
template <typename Real>
Real stableAsinh(Real x) {
    const Real a = std::abs(x);
    Real result;
    if (a > Precision<Real>::kAsinhLarge) {
        result = std::log(a) + Real(std::numbers::ln2);
    } else {
        result = stableLog1p(a + a * a / (Real(1) + std::sqrt(Real(1) + a * a)));
    }
    return x < Real(0) ? -result : result;
}

// sqrt(a^2 + b^2) without overflow of the squares (huge world scales, x1 -> very far).
template <typename Real>
Real scaledHypot(Real a, Real b) {
    const Real big = std::max(std::abs(a), std::abs(b));
    const Real small = std::min(std::abs(a), std::abs(b));
    if (big == Real(0) || std::isinf(big)) return big;
    const Real ratio = small / big;
    return big * std::sqrt(Real(1) + ratio * ratio);
}

// ---- Phase function -------------------------------------------------------------------------------

// Henyey-Greenstein from 1 - cos(theta) and 1 + cos(theta):
// p = (1 - g^2) / (4 pi (1 + g^2 - 2 g cos)^(3/2)) with the denominator written as a sum of non-negative
// terms, (1 - g)^2 + 2 g (1 - cos) for g > 0 and (1 + g)^2 - 2 g (1 + cos) for g < 0: no cancellation in
// the peak of either lobe (docs/numerics.md#phase-function). Exactly 1/(4 pi) for g == 0.
// Requires |g| < 1.
template <typename Real>
Real phaseHGFromCosTerms(Real oneMinusCos, Real onePlusCos, Real g) {
    if (g == Real(0)) return Real(kInv4Pi);
    const Real denom = g > Real(0) ? (Real(1) - g) * (Real(1) - g) + Real(2) * g * oneMinusCos
                                   : (Real(1) + g) * (Real(1) + g) - Real(2) * g * onePlusCos;
    return (Real(1) - g) * (Real(1) + g) * Real(kInv4Pi) / (denom * std::sqrt(denom));
}

// cosTheta = dot(direction light->point, direction point->eye): +1 is forward scattering.
template <typename Real>
Real phaseHG(Real cosTheta, Real g) {
    return phaseHGFromCosTerms(Real(1) - cosTheta, Real(1) + cosTheta, g);
}

// ---- Ray-light geometry -----------------------------------------------------------------------------

template <typename Real>
struct RayLightGeometry {
    Real tP;  // signed distance eye -> foot point P of the light on the ray
    Real h;   // light-to-ray distance, >= 0
};

// D = light - eye, camera-relative (compute it in double when world coordinates are large,
// docs/numerics.md#camera-relative-coordinates); w unit. h = |D x w|; never sqrt(|D|^2 - tP^2), which
// cancels when h << |D|.
template <typename Real>
RayLightGeometry<Real> rayLightGeometry(glm::vec<3, Real> D, glm::vec<3, Real> w) {
    return RayLightGeometry<Real>{glm::dot(D, w), glm::length(glm::cross(D, w))};
}

// ---- Point light: anchored log-tangent Gauss-Legendre ----------------------------------------------
// (docs/numerics.md#anchored-point-light-segment and docs/numerics.md#quadrature)

// An angular factor that follows the ray: the direction from the light to the ray's point at y is
// u(y) = m sech(y) + w tanh(y), m the unit vector from the light to the foot point P (m . w = 0). A light
// whose intensity toward u(y) is I0 A(y), A(y) = c + a sech(y) + b tanh(y) (clamped at 0), enters the
// integrand exactly. A point light is {1, 0, 0} (A = 1); an area light's VPL,
// I0 max(0, n . u) around its emitter normal n, is {0, n . m, n . w} (cosineLobeSegment). `squared` takes
// A(y) = min(1, max(0, c + a sech(y) + b tanh(y)))^2 instead: a spot light's KHR falloff, whose penumbra
// is the square of such a lobe (spotPenumbraSegment).
template <typename Real>
struct AngularFactor {
    Real constant = Real(1);  // c
    Real foot = Real(0);      // a, the coefficient of sech(y) = |P - light| / r
    Real ray = Real(0);       // b, the coefficient of tanh(y) = (x - tP) / r
    bool squared = false;
};

// The integrand in eta = y - y0 without the constant factors: p(cos) * exp(-nu expm1(eta)) / cosh(y) * A(y).
// cos(theta_s) = -tanh(y), so 1 - cos = 1 + tanh(y) = 2/(1 + e^2) for y >= 0 and 2 e^2/(1 + e^2) for
// y < 0, with e = exp(-|y|), and 1 + cos the mirror image (no cancellation on either side);
// 1/cosh(y) = 2 e/(1 + e^2), tanh(y) = sign(y) (1 - e^2)/(1 + e^2).
// exp(-nu expm1(eta)) = exp(-sigma_t ((x + r) - (x0 + r0))): extinction relative to the segment start.
// A(y) = 1 exactly for a point light ({1, 0, 0}), so its integrand is unchanged to the last bit.
template <typename Real>
Real pointIntegrand(Real eta, Real y0, Real nu, Real g, AngularFactor<Real> lobe) {
    const Real y = y0 + eta;
    const Real e = std::exp(-std::abs(y));
    const Real e2 = e * e;
    const Real sech = Real(2) * e / (Real(1) + e2);
    const Real oneMinusCos = y >= Real(0) ? Real(2) / (Real(1) + e2) : Real(2) * e2 / (Real(1) + e2);
    const Real onePlusCos = y >= Real(0) ? Real(2) * e2 / (Real(1) + e2) : Real(2) / (Real(1) + e2);
    const Real tanhY = (y >= Real(0) ? Real(1) : Real(-1)) * ((Real(1) - e2) / (Real(1) + e2));
    const Real linear = std::max(Real(0), lobe.constant + lobe.foot * sech + lobe.ray * tanhY);
    const Real clipped = std::min(linear, Real(1));
    const Real angular = lobe.squared ? clipped * clipped : linear;
    const Real attenuation = std::exp(-nu * stableExpm1(eta));
    return phaseHGFromCosTerms(oneMinusCos, onePlusCos, g) * attenuation * sech * angular;
}

// N-point Gauss-Legendre over eta in [a, b]; 0 for an empty panel.
template <typename Real, int N>
Real pointPanel(Real a, Real b, Real y0, Real nu, Real g, AngularFactor<Real> lobe) {
    if (!(b > a)) return Real(0);
    const Real half = Real(0.5) * (b - a);
    const Real mid = Real(0.5) * (a + b);
    Real sum = Real(0);
    for (int k = 0; k < N / 2; ++k) {
        const Real dx = half * Real(GaussLegendre<N>::kX[k]);
        sum += Real(GaussLegendre<N>::kW[k]) *
               (pointIntegrand(mid - dx, y0, nu, g, lobe) + pointIntegrand(mid + dx, y0, nu, g, lobe));
    }
    return sum * half;
}

// L(x0, x1) = int_x0^x1 sigma_s p(cos) I0 exp(-sigma_t (x + r(x))) / r(x)^2 dx for a point light at
// foot-point distance tP and ray distance h; x1 may be +inf (sky). Evaluated directly for the segment,
// anchored at x0 (docs/numerics.md#anchored-point-light-segment):
//   L = sigma_s I0 exp(-sigma_t (x0 + r0)) / h * int_0^E p(-tanh y) exp(-nu expm1(eta)) / cosh y deta,
//   y = y0 + eta, y0 = asinh(s0 / h), nu = sigma_t q0, E = y1 - y0 = log1p((x1 - x0)(q1 + q0)/((r1 + r0) q0)).
// Every factor is bounded by its value at x0 and nothing large is subtracted, which keeps it stable on
// all the stiff inputs of docs/numerics.md#stiff-inputs-of-the-kernel (thin/zero/thick medium, light
// behind the camera, ray through or along the light, sky, large sigma_t h, slivers, g -> 1); Sun et al.
// 2005's closed form is the isotropic special case but cancels catastrophically there
// (docs/numerics.md#the-textbook-closed-form).
//
// Ray through the light: h is raised to max(Precision<Real>::kMinRelativeH * scale, kMinAbsoluteH), scale = distance from
// P to the nearer segment end when P is outside the segment (a harmless clamp: L changes by O((h/s)^2)),
// or the segment's extent around P when P is inside. In the latter case the exact integral diverges like
// sigma_s I0 e^(-sigma_t tP) / (4 h); the result is that of a ray passing at the floor distance: finite
// and large. The floor is 1e-7 (float) or 1e-13 (double) of the extent, each just above the rounding of h
// in that precision, so float and double agree wherever float can tell h apart from 0 and differ only on
// rays through the light itself. Callers that can see the light itself should give it a size.
//
// Quadrature: eta is cut where the extinction from x0 exceeds e^-K and to a window of W (+ 2 ln 1/(1-|g|)
// for the HG lobe) around the closest approach y = 0 (clamped into the segment); N-node Gauss-Legendre
// panels between break points graded around the closest approach and the HG peak
// y_g = sign(g) ln((1 - |g|)/2), plus optical depths 2 and 6 from x0.
//
// pointSegmentWithLobe multiplies the integrand by the angular factor A(y) (AngularFactor); A varies on
// the same scale in y as 1/cosh(y), with poles at the same places, so the same panels resolve it. A lobe
// without a constant term is cut where it changes sign (below).
// The light-to-ray distance of the segment [x0, x1] raised to the floor described above (every caller
// that integrates along a ray past a point light takes it from here: pointSegmentWithLobe and the
// reference's profile-weighted quadrature).
template <typename Real>
Real flooredLightDistance(Real tP, Real h, Real x0, Real x1) {
    // Positions relative to the foot point P; s1 = +inf for the sky.
    const Real s0 = x0 - tP, s1 = x1 - tP;
    const bool footInside = s0 <= Real(0) && s1 >= Real(0);
    Real scale = footInside ? std::max(std::abs(s0), std::isinf(s1) ? Real(0) : s1)
                            : std::min(std::abs(s0), std::abs(s1));
    if (scale == Real(0)) scale = std::abs(tP);
    return std::max(h, std::max(Precision<Real>::kMinRelativeH * scale, Real(kMinAbsoluteH)));
}

template <typename Real, int N = Precision<Real>::kNodes>
Real pointSegmentWithLobe(Real tP, Real h, Real x0, Real x1, Real sigma_s, Real sigma_t, Real g, Real I0,
                          AngularFactor<Real> lobe) {
    if (!(x1 > x0) || !(sigma_s > Real(0)) || !(I0 > Real(0))) return Real(0);

    // Positions relative to the foot point P; s1 = +inf for the sky.
    Real s0 = x0 - tP;
    Real s1 = x1 - tP;
    h = flooredLightDistance(tP, h, x0, x1);

    // A lobe without a constant term, a sech(y) + b tanh(y) = (a + b sinh(y)) / cosh(y), changes sign at
    // s = h sinh(y) = -h a / b and is negative on one side: the segment ends there, at the zero of the
    // integrand's own A, so the integrand is smooth on every panel. (A cut at the emitter's plane in x,
    // D . n / w . n, carries the rounding of |D|-sized values, a large fraction of h next to the light,
    // and the kink it left inside a panel cost the float kernel 6.5e-5 on a ray passing 1e-5 from a VPL.)
    Real length = x1 - x0;
    if (lobe.constant == Real(0)) {
        if (lobe.ray == Real(0)) {
            if (!(lobe.foot > Real(0))) return Real(0);
        } else {
            const Real sZero = -h * (lobe.foot / lobe.ray);
            if (lobe.ray > Real(0) ? !(sZero < s1) : !(sZero > s0)) return Real(0);
            if (lobe.ray > Real(0) && sZero > s0) {
                s0 = sZero;
                x0 = tP + sZero;
                length = s1 - s0;
            } else if (lobe.ray < Real(0) && sZero < s1) {
                s1 = sZero;
                x1 = tP + sZero;
                length = s1 - s0;
            }
        }
    }

    // Segment start: r0 = |light - point|, q0 = s0 + r0 written without cancellation for s0 < 0.
    const Real r0 = scaledHypot(s0, h);
    const Real q0 = s0 >= Real(0) ? s0 + r0 : h * (h / (r0 - s0));
    const Real y0 = stableAsinh(s0 / h);

    // E = y1 - y0 = ln(q1 / q0), from q1 - q0 = (x1 - x0)(q1 + q0)/(r1 + r0): all terms positive, so
    // short slivers far from P keep their digits (no difference of two asinh values).
    Real E = Real(1e30);
    if (!std::isinf(x1)) {
        const Real r1 = scaledHypot(s1, h);
        const Real q1 = s1 >= Real(0) ? s1 + r1 : h * (h / (r1 - s1));
        E = stableLog1p(length * ((q1 + q0) / (r1 + r0)) / q0);
    }

    // Extinction cut: sigma_t ((x + r) - (x0 + r0)) = nu expm1(eta) reaches K at eta = log1p(K / nu).
    const Real nu = sigma_t * q0;
    if (nu > Real(0)) E = std::min(E, stableLog1p(Real(Precision<Real>::kAttenuationCut) / nu));

    // Window around the closest approach, widened for a strong HG lobe.
    const Real window = Real(Precision<Real>::kWindow) - Real(2) * std::log(Real(1) - std::abs(g));
    const Real split = std::clamp(Real(0), y0, y0 + E) - y0;
    const Real lo = std::max(Real(0), split - window);
    const Real hi = std::min(E, split + window);

    // Break points, graded around two centres: the closest approach and the HG peak of p(y)/cosh(y)
    // (forward lobe at y < 0 for g > 0). 1/cosh(y) has poles at y = +-i pi/2 and HG a branch point at
    // y_g +- i pi/2, so a single panel reaching far beyond a centre converges slowly; panels of width a,
    // 2a and the rest keep every singularity relatively far from the panel it is not an end of.
    // Points are clamped into [lo, hi] and sorted; empty panels cost nothing.
    const Real a = Real(Precision<Real>::kNearWidth);
    Real centre1 = split;
    if (std::abs(g) > Real(0.5)) {
        const Real yPeak = std::log(Real(0.5) * (Real(1) - std::abs(g)));
        centre1 = (g > Real(0) ? yPeak : -yPeak) - y0;
    }
    // Extinction grading: optical depths 2 and 6 from the segment start, so that no panel has to
    // resolve more than a factor e^-4 of decay where it matters (the cut at K ends the last one).
    const Real depth2 = nu > Real(0) ? stableLog1p(Real(2) / nu) : hi;
    const Real depth6 = nu > Real(0) ? stableLog1p(Real(6) / nu) : hi;
    Real breaks[12] = {split - Real(3) * a, split - a, split, split + a, split + Real(3) * a,
                       centre1 - Real(3) * a, centre1 - a, centre1, centre1 + a, centre1 + Real(3) * a,
                       depth2, depth6};
    for (int i = 0; i < 12; ++i) {
        breaks[i] = std::clamp(breaks[i], lo, hi);
    }
    for (int i = 1; i < 12; ++i) {
        const Real v = breaks[i];
        int j = i - 1;
        while (j >= 0 && breaks[j] > v) {
            breaks[j + 1] = breaks[j];
            --j;
        }
        breaks[j + 1] = v;
    }
    Real sum = pointPanel<Real, N>(lo, breaks[0], y0, nu, g, lobe) +
               pointPanel<Real, N>(breaks[11], hi, y0, nu, g, lobe);
    for (int i = 0; i < 11; ++i) {
        sum += pointPanel<Real, N>(breaks[i], breaks[i + 1], y0, nu, g, lobe);
    }
    if (!(sum > Real(0))) return Real(0);

    // sigma_s I0 e^{-sigma_t (x0 + r0)} / h * sum with the exponents combined first: e^{+-100}-type
    // factors of thick media and bright lights never overflow or flush to zero on their own
    // (docs/numerics.md#combined-exponents). x0 + r0 >= |D|, so this is at most e^{-sigma_t |D|}-scaled.
    const Real logL = std::log(sigma_s) + std::log(I0) - std::log(h) - sigma_t * (x0 + r0) + std::log(sum);
    return std::exp(logL);
}

template <typename Real, int N = Precision<Real>::kNodes>
Real pointSegment(Real tP, Real h, Real x0, Real x1, Real sigma_s, Real sigma_t, Real g, Real I0) {
    return pointSegmentWithLobe<Real, N>(tP, h, x0, x1, sigma_s, sigma_t, g, I0, AngularFactor<Real>{});
}

// ---- Cosine-lobe emitter (an area light's VPL; docs/numerics.md#cosine-lobe-emitter) -----------------

// L(x0, x1) for a light at D (camera-relative) whose intensity toward a unit direction u is
// I0 max(0, n . u), n the emitter's unit normal: the lobe n . u(y) = (n . m) sech(y) + (n . w) tanh(y)
// integrated exactly, with m = (P - light) / |P - light| formed from cross products ((D x w) x w =
// P - light, no difference of |D|-sized vectors). Behind the emitter's plane nothing is emitted: the lobe
// is negative there, and pointSegmentWithLobe ends the segment at the lobe's zero. Piecewise-constant
// pieces of the lobe instead (its value at each piece's middle angle) are off by the lobe's curvature over
// a piece and cost one segment each.
template <typename Real, int N = Precision<Real>::kNodes>
Real cosineLobeSegment(glm::vec<3, Real> D, glm::vec<3, Real> w, glm::vec<3, Real> n, Real x0, Real x1,
                       Real sigma_s, Real sigma_t, Real g, Real I0) {
    // rayLightGeometry's D x w, once: h = |D x w| and m = (D x w) x w.
    const glm::vec<3, Real> dw = glm::cross(D, w);
    const glm::vec<3, Real> m = glm::cross(dw, w);
    const Real mLength = glm::length(m);
    const Real mn = mLength > Real(0) ? glm::dot(m, n) / mLength : Real(0);
    return pointSegmentWithLobe<Real, N>(glm::dot(D, w), glm::length(dw), x0, x1, sigma_s, sigma_t, g, I0,
                                         AngularFactor<Real>{Real(0), mn, glm::dot(w, n)});
}

// ---- Spot light's penumbra (docs/numerics.md#spot-penumbra) -------------------------------------------

// L(x0, x1) for a spot light at D (camera-relative) with unit axis `axis` and KHR_lights_punctual falloff
// A_spot = clamp(cd scale + offset, 0, 1)^2, cd = axis . u the cosine between the axis and the direction u
// from the light, on a segment that lies in the penumbra (0 <= cd scale + offset <= 1 along it; the
// caller cuts the ray at the cones). cd(y) = (axis . m) sech(y) + (axis . w) tanh(y) is a lobe, so
// A_spot(y) is the square of the lobe {offset, scale (axis . m), scale (axis . w)}, smooth on the segment,
// and integrated by the same panels as the rest of the integrand (one segment instead of pieces of
// constant A_spot, which are off by its curvature over a piece and cost a segment each). The clamp at 0
// and 1 is kept, so a segment that crosses a cone stays bounded, but its kink then falls inside a panel.
template <typename Real, int N = Precision<Real>::kNodes>
Real spotPenumbraSegment(glm::vec<3, Real> D, glm::vec<3, Real> w, glm::vec<3, Real> axis, Real scale, Real offset,
                         Real x0, Real x1, Real sigma_s, Real sigma_t, Real g, Real I0) {
    // As in cosineLobeSegment: m = (D x w) x w = P - light from cross products.
    const glm::vec<3, Real> dw = glm::cross(D, w);
    const glm::vec<3, Real> m = glm::cross(dw, w);
    const Real mLength = glm::length(m);
    const Real am = mLength > Real(0) ? glm::dot(m, axis) / mLength : Real(0);
    return pointSegmentWithLobe<Real, N>(glm::dot(D, w), glm::length(dw), x0, x1, sigma_s, sigma_t, g, I0,
                                         AngularFactor<Real>{offset, scale * am, scale * glm::dot(w, axis), true});
}

// ---- Directional light ----------------------------------------------------------------------------

// int_x0^x1 sigma_s p(cosTheta) E exp(-sigma_t x) dx = sigma_s p E e^{-sigma_t x0} (-expm1(-sigma_t len))
// / sigma_t, len = x1 - x0; equals sigma_s p E len for sigma_t == 0 and 1/sigma_t-scaled for x1 = +inf.
// cosTheta uses the light's travel direction. The only infinite result is the genuinely infinite
// sigma_t == 0 with x1 = +inf.
template <typename Real>
Real directionalSegment(Real cosTheta, Real x0, Real x1, Real sigma_s, Real sigma_t, Real g, Real E) {
    if (!(x1 > x0) || !(sigma_s > Real(0)) || !(E > Real(0))) return Real(0);
    const Real length = x1 - x0;
    const Real tau = sigma_t * length;
    const Real pathIntegral = tau > Real(0) ? -stableExpm1(-tau) / sigma_t : length;
    const Real logScale = std::log(sigma_s) + std::log(E) - sigma_t * x0;
    return std::exp(logScale) * phaseHG(cosTheta, g) * pathIntegral;
}

// ---- Transmittance ----------------------------------------------------------------------------------

// exp(-sigma_t distance); 1 for sigma_t == 0 even at distance = +inf.
template <typename Real>
Real transmittance(Real sigma_t, Real distance) {
    return sigma_t > Real(0) ? std::exp(-sigma_t * distance) : Real(1);
}

}  // namespace viz::airlight
