// Airlight math for the GPU techniques: single scattering from a point or directional light in a
// homogeneous medium along one segment of an eye ray. Float mirror of viz/shared/airlight.h (same
// function names, argument order and structure, line by line); Sun et al. 2005 and
// docs/numerics.md#quadrature.
// Inputs are camera-relative (tP, h computed in double on the CPU when world coordinates are large).
// No step relies on compensated arithmetic (every difference that could cancel is rewritten as a sum and
// log1p/expm1 use series near 0), so `precise` is not needed and fast-math reassociation is harmless.
#ifndef AIRLIGHT_GLSL
#define AIRLIGHT_GLSL

#include "common/constants.glsl"
#include "common/solid_angle.glsl"
#include "common/sort.glsl"
#include "common/work_counters.glsl"

// ---- Precision-dependent knobs (Precision<float> in airlight.h) ---------------------------------------
const int AIRLIGHT_NODES = 8;
const float AIRLIGHT_NEAR_WIDTH = 2.0;
const float AIRLIGHT_ATTENUATION_CUT = 20.0;
const float AIRLIGHT_WINDOW = 17.0;
const float AIRLIGHT_ASINH_LARGE = 1e4;
const int AIRLIGHT_SERIES_TERMS = 10;

// Light-to-ray distance floor: Precision<float>::kMinRelativeH and kMinAbsoluteH (see pointSegment).
const float AIRLIGHT_MIN_RELATIVE_H = 1e-7;
const float AIRLIGHT_MIN_ABSOLUTE_H = 1e-15;
const float AIRLIGHT_INV_4PI = 0.0795774715459476679;
const float AIRLIGHT_LN2 = 0.693147180559945309417;

// ---- 8-point Gauss-Legendre rule on [-1, 1]: positive abscissae and weights (symmetric rule) ----------
const float AIRLIGHT_GL_X[4] = float[4](0.960289856497536231684, 0.796666477413626739592,
                                        0.525532409916328985818, 0.183434642495649804939);
const float AIRLIGHT_GL_W[4] = float[4](0.101228536290376259153, 0.222381034453374470544,
                                        0.313706645877887287338, 0.362683783378361982965);

// ---- Elementary helpers (GLSL has no log1p/expm1; docs/numerics.md#elementary-functions) ------------

// log(1 + x) without losing x when |x| << 1: 2 atanh(z) series, z = x / (2 + x), on (-0.5, 1). GLSL's
// log has only an absolute error bound of 2^-21 near 1, so Kahan's log(u) x / (u - 1) trick fails here.
float stableLog1p(float x) {
    if (x > -0.5 && x < 1.0) {
        float z = x / (2.0 + x);
        float z2 = z * z;
        float sum = 0.0;
        for (int k = AIRLIGHT_SERIES_TERMS - 1; k >= 0; --k) {
            sum = 1.0 / float(2 * k + 1) + z2 * sum;
        }
        return 2.0 * z * sum;
    }
    return log(1.0 + x);
}

// exp(x) - 1 without cancellation: Taylor series (Horner form) for |x| < 0.5, exp(x) - 1 outside.
float stableExpm1(float x) {
    if (abs(x) < 0.5) {
        float sum = 1.0;
        for (int k = AIRLIGHT_SERIES_TERMS; k >= 2; --k) {
            sum = 1.0 + x * sum / float(k);
        }
        return x * sum;
    }
    return exp(x) - 1.0;
}

// asinh(x) = sign(x) log1p(|x| + x^2 / (1 + sqrt(1 + x^2))); the built-in asinh cancels for x < 0.
float stableAsinh(float x) {
    float a = abs(x);
    float result;
    if (a > AIRLIGHT_ASINH_LARGE) {
        result = log(a) + AIRLIGHT_LN2;
    } else {
        result = stableLog1p(a + a * a / (1.0 + sqrt(1.0 + a * a)));
    }
    return x < 0.0 ? -result : result;
}

// sqrt(a^2 + b^2) without overflow of the squares.
float scaledHypot(float a, float b) {
    float big = max(abs(a), abs(b));
    float small = min(abs(a), abs(b));
    if (big == 0.0 || isinf(big)) return big;
    float ratio = small / big;
    return big * sqrt(1.0 + ratio * ratio);
}

// ---- Phase function --------------------------------------------------------------------------------

// Henyey-Greenstein with the denominator as a sum of non-negative terms: (1 - g)^2 + 2 g (1 - cos) for
// g > 0, (1 + g)^2 - 2 g (1 + cos) for g < 0 (no cancellation in either lobe); 1/(4 pi) for g == 0.
float phaseHGFromCosTerms(float oneMinusCos, float onePlusCos, float g) {
    if (g == 0.0) return AIRLIGHT_INV_4PI;
    float denom = g > 0.0 ? (1.0 - g) * (1.0 - g) + 2.0 * g * oneMinusCos
                          : (1.0 + g) * (1.0 + g) - 2.0 * g * onePlusCos;
    return (1.0 - g) * (1.0 + g) * AIRLIGHT_INV_4PI / (denom * sqrt(denom));
}

// cosTheta = dot(direction light->point, direction point->eye): +1 is forward scattering.
float phaseHG(float cosTheta, float g) {
    return phaseHGFromCosTerms(1.0 - cosTheta, 1.0 + cosTheta, g);
}

// ---- Ray-light geometry -----------------------------------------------------------------------------

struct RayLightGeometry {
    float tP;  // signed distance eye -> foot point P of the light on the ray
    float h;   // light-to-ray distance, >= 0
};

// D = light - eye (camera-relative), w unit. h = |D x w|, never sqrt(|D|^2 - tP^2).
RayLightGeometry rayLightGeometry(vec3 D, vec3 w) {
    return RayLightGeometry(dot(D, w), length(cross(D, w)));
}

// ---- Point light: anchored log-tangent Gauss-Legendre ----------------------------------------------
// (docs/numerics.md#anchored-point-light-segment and docs/numerics.md#quadrature)

// An angular factor that follows the ray (AngularFactor in airlight.h): A(y) = c + a sech(y) + b tanh(y),
// clamped at 0, stored as vec4(c, a, b, 0); vec4(c, a, b, 1) is min(1, max(0, c + a sech + b tanh))^2, a
// spot's penumbra (spotPenumbraLobeOf). vec4(1, 0, 0, 0) is a point light (A = 1 exactly); an area
// light's VPL is vec4(0, n . m, n . w, 0) (cosineLobeSegment).
const vec4 AIRLIGHT_NO_LOBE = vec4(1.0, 0.0, 0.0, 0.0);

// An area light's VPL as its cell of the emitter (lights.glsl, vplHasCell) inside the segment integral
// (GPU only: viz/shared/airlight.h has no cells; tests/gl/vpl_cell_test.cpp checks it against an
// independent quadrature). Positions relative to the foot point F of the VPL's node on the ray, so that
// the point at s along the ray from F is s w. The angular factor becomes A(y) = Omega_cell(s w) r^2 / dA
// (r: the distance to the node, h cosh y): times the point kernel's I0 / r^2 with I0 = L_e dA that is
// L_e Omega_cell, the cosine lobe far from the cell and bounded next to it. area 0: no cell.
struct AirlightCell {
    vec3 corner;  // a corner of the cell - F
    vec3 edgeU;   // its edges
    vec3 edgeV;
    vec3 normal;  // unit, toward the lit side
    vec3 w;       // the ray's unit direction
    float area;   // |edgeU x edgeV|; 0: no cell
};
const AirlightCell AIRLIGHT_NO_CELL = AirlightCell(vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), 0.0);

// p(cos) * exp(-nu expm1(eta)) / cosh(y) * A(y), y = y0 + eta; 1 -+ cos = 1 +- tanh(y) from e = exp(-|y|).
// h: the light-to-ray distance the segment uses (a cell's A(y) needs the position along the ray).
float pointIntegrand(float eta, float y0, float nu, float g, vec4 lobe, float h, AirlightCell cell) {
    float y = y0 + eta;
    float e = exp(-abs(y));
    float e2 = e * e;
    float sech = 2.0 * e / (1.0 + e2);
    float oneMinusCos = y >= 0.0 ? 2.0 / (1.0 + e2) : 2.0 * e2 / (1.0 + e2);
    float onePlusCos = y >= 0.0 ? 2.0 * e2 / (1.0 + e2) : 2.0 / (1.0 + e2);
    float tanhY = (y >= 0.0 ? 1.0 : -1.0) * ((1.0 - e2) / (1.0 + e2));
    float angular;
    if (cell.area > 0.0) {
        if (!(e > 0.0)) return 0.0;  // sech = 0 there: nothing to add, and sinh would overflow
        float s = h * ((y >= 0.0 ? 1.0 : -1.0) * (1.0 - e2) / (2.0 * e));  // h sinh(y)
        float omega = parallelogramSolidAngle(cell.corner - s * cell.w, cell.edgeU, cell.edgeV, cell.normal, cell.area);
        angular = omega * ((h * h + s * s) / cell.area);
    } else {
        float linear = max(0.0, lobe.x + lobe.y * sech + lobe.z * tanhY);
        float clipped = min(linear, 1.0);
        angular = lobe.w > 0.0 ? clipped * clipped : linear;
    }
    float attenuation = exp(-nu * stableExpm1(eta));
    return phaseHGFromCosTerms(oneMinusCos, onePlusCos, g) * attenuation * sech * angular;
}

// 8-point Gauss-Legendre over eta in [a, b]; 0 for an empty panel.
float pointPanel(float a, float b, float y0, float nu, float g, vec4 lobe, float h, AirlightCell cell) {
    if (!(b > a)) return 0.0;
    WORK_COUNT(kWorkQuadratureNodes, AIRLIGHT_NODES);
    float half_ = 0.5 * (b - a);
    float mid = 0.5 * (a + b);
    float sum = 0.0;
    for (int k = 0; k < AIRLIGHT_NODES / 2; ++k) {
        float dx = half_ * AIRLIGHT_GL_X[k];
        sum += AIRLIGHT_GL_W[k] * (pointIntegrand(mid - dx, y0, nu, g, lobe, h, cell) +
                                   pointIntegrand(mid + dx, y0, nu, g, lobe, h, cell));
    }
    return sum * half_;
}

// L(x0, x1) = int_x0^x1 sigma_s p(cos) I0 exp(-sigma_t (x + r(x))) / r(x)^2 dx, x1 may be +inf.
// Anchored at x0 (docs/numerics.md#anchored-point-light-segment); see viz/shared/airlight.h for the
// derivation, the h floor for rays through the light, and the quadrature windows. pointSegmentWithLobe
// multiplies the integrand by the angular factor A(y); pointSegmentCell takes a VPL's cell's instead
// (AirlightCell; the lobe then only ends the segment at the emitter's plane).
float pointSegmentCell(float tP, float h, float x0, float x1, float sigma_s, float sigma_t, float g, float I0,
                       vec4 lobe, AirlightCell cell) {
    if (!(x1 > x0) || !(sigma_s > 0.0) || !(I0 > 0.0)) return 0.0;

    // Positions relative to the foot point P; s1 = +inf for the sky.
    float s0 = x0 - tP;
    float s1 = x1 - tP;
    bool footInside = s0 <= 0.0 && s1 >= 0.0;
    float scale = footInside ? max(abs(s0), isinf(s1) ? 0.0 : s1)
                             : min(abs(s0), abs(s1));
    if (scale == 0.0) scale = abs(tP);
    h = max(h, max(AIRLIGHT_MIN_RELATIVE_H * scale, AIRLIGHT_MIN_ABSOLUTE_H));

    // A lobe without a constant term changes sign at s = -h a / b: the segment ends at that zero of the
    // integrand's own A, so every panel is smooth (see airlight.h).
    float length_ = x1 - x0;
    if (lobe.x == 0.0) {
        if (lobe.z == 0.0) {
            if (!(lobe.y > 0.0)) return 0.0;
        } else {
            float sZero = -h * (lobe.y / lobe.z);
            if (lobe.z > 0.0 ? !(sZero < s1) : !(sZero > s0)) return 0.0;
            if (lobe.z > 0.0 && sZero > s0) {
                s0 = sZero;
                x0 = tP + sZero;
                length_ = s1 - s0;
            } else if (lobe.z < 0.0 && sZero < s1) {
                s1 = sZero;
                x1 = tP + sZero;
                length_ = s1 - s0;
            }
        }
    }
    WORK_COUNT(kWorkClosedFormSegments, 1);

    // Segment start: r0 = |light - point|, q0 = s0 + r0 written without cancellation for s0 < 0.
    float r0 = scaledHypot(s0, h);
    float q0 = s0 >= 0.0 ? s0 + r0 : h * (h / (r0 - s0));
    float y0 = stableAsinh(s0 / h);

    // E = y1 - y0 = ln(q1 / q0) from q1 - q0 = (x1 - x0)(q1 + q0)/(r1 + r0): all terms positive.
    float E = 1e30;
    if (!isinf(x1)) {
        float r1 = scaledHypot(s1, h);
        float q1 = s1 >= 0.0 ? s1 + r1 : h * (h / (r1 - s1));
        E = stableLog1p(length_ * ((q1 + q0) / (r1 + r0)) / q0);
    }

    // Extinction cut: nu expm1(eta) reaches K at eta = log1p(K / nu).
    float nu = sigma_t * q0;
    if (nu > 0.0) E = min(E, stableLog1p(AIRLIGHT_ATTENUATION_CUT / nu));

    // Window around the closest approach, widened for a strong HG lobe.
    float window_ = AIRLIGHT_WINDOW - 2.0 * log(1.0 - abs(g));
    float split = clamp(0.0, y0, y0 + E) - y0;
    float lo = max(0.0, split - window_);
    float hi = min(E, split + window_);

    // Break points graded around the closest approach and the HG peak (a, 2a, rest) plus optical depths
    // 2 and 6 from x0; clamped into [lo, hi], sorted, empty panels cost nothing.
    float a = AIRLIGHT_NEAR_WIDTH;
    float centre1 = split;
    if (abs(g) > 0.5) {
        float yPeak = log(0.5 * (1.0 - abs(g)));
        centre1 = (g > 0.0 ? yPeak : -yPeak) - y0;
    }
    float depth2 = nu > 0.0 ? stableLog1p(2.0 / nu) : hi;
    float depth6 = nu > 0.0 ? stableLog1p(6.0 / nu) : hi;
    float breaks[18] = float[18](split - 3.0 * a, split - a, split, split + a, split + 3.0 * a,
                                 centre1 - 3.0 * a, centre1 - a, centre1, centre1 + a, centre1 + 3.0 * a,
                                 depth2, depth6, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    int count = 12;
    // A cell's factor turns from the near field (Omega_cell up to 2 pi) to the cosine lobe where the
    // distance from the node passes the cell's size c. A ray that passes the node closer than c / 4 meets
    // that turn inside the wide panels beside its closest approach (they reach |s| = h sinh(3 a), 200 h),
    // so it gets breaks where |s| = c / 4, c and 4 c on both sides of the foot point (a ray through the
    // node was 4.4e-4 off without them). Further away the turn lies within a few h of the closest
    // approach, where the panels are fine (rays 0.3 to 2 cells from the node: 3.4e-6 at worst,
    // tests/gl/vpl_cell_test.cpp), and a point light or a cell-less VPL keeps its 12 breaks.
    float c = sqrt(cell.area);
    if (cell.area > 0.0 && h < 0.25 * c) {
        for (int i = 0; i < 3; ++i) {
            float yc = stableAsinh(c * (0.25 * float(1 << (2 * i))) / h);
            breaks[12 + 2 * i] = yc - y0;
            breaks[13 + 2 * i] = -yc - y0;
        }
        count = 18;
    }
    for (int i = 0; i < count; ++i) {
        breaks[i] = clamp(breaks[i], lo, hi);
    }
    SORT_ASCENDING(breaks, count);
    float sum = pointPanel(lo, breaks[0], y0, nu, g, lobe, h, cell) +
                pointPanel(breaks[count - 1], hi, y0, nu, g, lobe, h, cell);
    for (int i = 0; i < count - 1; ++i) {
        sum += pointPanel(breaks[i], breaks[i + 1], y0, nu, g, lobe, h, cell);
    }
    if (!(sum > 0.0)) return 0.0;

    // Exponents combined before exponentiating: exp(-x) flushes to 0 for x > ~87 on GPUs
    // (docs/numerics.md#combined-exponents).
    float logL = log(sigma_s) + log(I0) - log(h) - sigma_t * (x0 + r0) + log(sum);
    return exp(logL);
}

float pointSegmentWithLobe(float tP, float h, float x0, float x1, float sigma_s, float sigma_t, float g, float I0,
                           vec4 lobe) {
    return pointSegmentCell(tP, h, x0, x1, sigma_s, sigma_t, g, I0, lobe, AIRLIGHT_NO_CELL);
}

float pointSegment(float tP, float h, float x0, float x1, float sigma_s, float sigma_t, float g, float I0) {
    return pointSegmentWithLobe(tP, h, x0, x1, sigma_s, sigma_t, g, I0, AIRLIGHT_NO_LOBE);
}

// ---- Cosine-lobe emitter (an area light's VPL; docs/numerics.md#cosine-lobe-emitter) -----------------

// The part of [x0, x1] in front of the emitter's plane through D with normal n (where x (w . n) > D . n);
// empty (y <= x) when none is. For the lobe's pieces under AIRLIGHT_LUT (polyvol's segment.glsl), whose
// table holds only the isotropic integral.
vec2 frontOfEmitter(vec3 D, vec3 w, vec3 n, float x0, float x1) {
    float wn = dot(w, n);
    float dn = dot(D, n);
    if (wn != 0.0) {
        float tPlane = dn / wn;
        if (wn > 0.0) {
            x0 = max(x0, tPlane);
        } else {
            x1 = min(x1, tPlane);
        }
    } else if (dn >= 0.0) {
        return vec2(0.0);
    }
    return vec2(x0, x1);
}

// L(x0, x1) for a light at D (camera-relative) emitting I0 max(0, n . u) toward u, n its unit normal: the
// lobe (n . m) sech(y) + (n . w) tanh(y) integrated exactly, the segment ended at the lobe's zero (the
// emitter's plane) by pointSegmentWithLobe (see airlight.h).
// The lobe of a light at D with normal n along the ray w: vec4(0, n . m / |m|, n . w, 0), m = (D x w) x w.
vec4 cosineLobeOf(vec3 D, vec3 w, vec3 n) {
    vec3 m = cross(cross(D, w), w);
    float mLength = length(m);
    return vec4(0.0, mLength > 0.0 ? dot(m, n) / mLength : 0.0, dot(w, n), 0.0);
}

// A VPL's cell (lights.glsl, vplHasCell) for pointSegmentCell along the ray w from the eye (the origin):
// corner c, edges eU and eV, unit normal n, area; D the node, tP its foot point's parameter on the ray.
AirlightCell airlightCellOf(vec3 corner, vec3 eU, vec3 eV, vec3 n, float area, vec3 w, float tP) {
    return AirlightCell(corner - tP * w, eU, eV, n, w, area);
}

float cosineLobeSegment(vec3 D, vec3 w, vec3 n, float x0, float x1, float sigma_s, float sigma_t, float g, float I0) {
    RayLightGeometry geo = rayLightGeometry(D, w);
    return pointSegmentWithLobe(geo.tP, geo.h, x0, x1, sigma_s, sigma_t, g, I0, cosineLobeOf(D, w, n));
}

// ---- Spot light's penumbra (spotPenumbraSegment in airlight.h; docs/numerics.md#spot-penumbra) --------

// A spot at D with unit axis a and KHR falloff clamp(cd scale + offset, 0, 1)^2 along the ray w: in its
// penumbra the square of the lobe vec4(offset, scale (a . m / |m|), scale (a . w), 1), m = (D x w) x w.
vec4 spotPenumbraLobeOf(vec3 D, vec3 w, vec3 a, float scale, float offset) {
    vec3 m = cross(cross(D, w), w);
    float mLength = length(m);
    return vec4(offset, scale * (mLength > 0.0 ? dot(m, a) / mLength : 0.0), scale * dot(w, a), 1.0);
}

float spotPenumbraSegment(vec3 D, vec3 w, vec3 a, float scale, float offset, float x0, float x1, float sigma_s,
                          float sigma_t, float g, float I0) {
    RayLightGeometry geo = rayLightGeometry(D, w);
    return pointSegmentWithLobe(geo.tP, geo.h, x0, x1, sigma_s, sigma_t, g, I0,
                                spotPenumbraLobeOf(D, w, a, scale, offset));
}

#ifdef AIRLIGHT_NAIVE_CLOSED_FORM
// ---- Teaching only: Sun et al. 2005's closed form evaluated as printed -------------------------------
// (docs/numerics.md#the-textbook-closed-form)
// Compiled in only by a shader that defines AIRLIGHT_NAIVE_CLOSED_FORM (raymarch's closed_form=naive),
// to show why pointSegment exists; no technique's result uses it. No CPU mirror in airlight.h.

// F(u, v) = int_0^v exp(-u tan xi) dxi (Sun et al. tabulate it): 8-point Gauss-Legendre on 8 panels
// [v/2^(k+1), v/2^k], the last one [0, v/128], so that the decay near 0 for large u is resolved. F itself
// is accurate to float rounding here; what fails below is the formula around it.
float naiveSunF(float u, float v) {
    float sum = 0.0;
    float b = v;
    for (int panel = 0; panel < 8; ++panel) {
        float a = panel == 7 ? 0.0 : 0.5 * b;
        float half_ = 0.5 * (b - a);
        float mid = 0.5 * (a + b);
        for (int k = 0; k < AIRLIGHT_NODES / 2; ++k) {
            float dx = half_ * AIRLIGHT_GL_X[k];
            sum += AIRLIGHT_GL_W[k] * half_ * (exp(-u * tan(mid - dx)) + exp(-u * tan(mid + dx)));
        }
        b = a;
    }
    return sum;
}

// Isotropic L(x0, x1) for a unit-intensity point light at D (camera-relative), ray direction w, the
// textbook way: gamma = acos(cos gamma), Tsv = sigma_t |D|,
//   A0 = sigma_s sigma_t I0 exp(-Tsv cos gamma) / (2 pi Tsv sin gamma),   A1 = Tsv sin gamma,
//   xi(x) = pi/4 + atan((sigma_t x - Tsv cos gamma) / A1) / 2,   L = A0 [F(A1, xi1) - F(A1, xi0)].
// The bracket is a difference of two O(1/A1) values whose true difference carries e^{-sigma_t (|D| - tP)}
// while A0 carries e^{+sigma_t (|D| - tP)}: float rounding of F is amplified by that factor (thick media),
// exp(-Tsv cos gamma) overflows for a light far behind the ray, and gamma = 0 (a ray through the light)
// gives inf * 0. The phase function is isotropic whatever g is: the closed form has no HG version.
float pointSegmentNaive(vec3 D, vec3 w, float x0, float x1, float sigma_s, float sigma_t, float I0) {
    WORK_COUNT(kWorkClosedFormSegments, 1);
    float Dsv = length(D);
    float gamma = acos(clamp(dot(D, w) / Dsv, -1.0, 1.0));
    float Tsv = sigma_t * Dsv;
    float A0 = sigma_s * sigma_t * I0 * exp(-Tsv * cos(gamma)) / (2.0 * kPi * Tsv * sin(gamma));
    float A1 = Tsv * sin(gamma);
    float xi0 = 0.25 * kPi + 0.5 * atan((sigma_t * x0 - Tsv * cos(gamma)) / A1);
    float xi1 = 0.25 * kPi + 0.5 * atan((sigma_t * x1 - Tsv * cos(gamma)) / A1);
    return A0 * (naiveSunF(A1, xi1) - naiveSunF(A1, xi0));
}
#endif  // AIRLIGHT_NAIVE_CLOSED_FORM

// ---- Directional light ----------------------------------------------------------------------------

// int_x0^x1 sigma_s p(cosTheta) E exp(-sigma_t x) dx; sigma_t -> 0 and x1 = +inf via expm1.
float directionalSegment(float cosTheta, float x0, float x1, float sigma_s, float sigma_t, float g, float E) {
    if (!(x1 > x0) || !(sigma_s > 0.0) || !(E > 0.0)) return 0.0;
    WORK_COUNT(kWorkClosedFormSegments, 1);
    float length_ = x1 - x0;
    float tau = sigma_t * length_;
    float pathIntegral = tau > 0.0 ? -stableExpm1(-tau) / sigma_t : length_;
    float logScale = log(sigma_s) + log(E) - sigma_t * x0;
    return exp(logScale) * phaseHG(cosTheta, g) * pathIntegral;
}

// ---- Transmittance ----------------------------------------------------------------------------------

// exp(-sigma_t distance); 1 for sigma_t == 0 even at distance = +inf.
float transmittance(float sigma_t, float distance) {
    return sigma_t > 0.0 ? exp(-sigma_t * distance) : 1.0;
}

#endif  // AIRLIGHT_GLSL
