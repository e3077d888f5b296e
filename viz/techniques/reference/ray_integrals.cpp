#include "techniques/reference/ray_integrals.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "shared/airlight.h"
#include "techniques/reference/quadrature.h"

namespace viz::reference {

// ---- visibility transitions ----

VisibilitySearch findLitIntervals(const std::function<bool(double)>& visible, double d, int samples,
                                  double tP, double h, const SearchSpan& span) {
    VisibilitySearch out;
    d = std::min(d, span.reach);  // beyond: unlit (less than exp(-60) of what the light gives)
    if (!(d > 0.0)) return out;
    samples = std::max(samples, 2);
    std::vector<double> ts;
    ts.reserve(std::size_t(samples) + 2);
    // Uniform in t, end points included; on a span longer than farSpan, half of them inside the scene.
    int uniform = (h > 0.0) ? std::max(2, samples / 2) : samples;
    const double sceneIn = std::max(span.scene.x, 0.0), sceneOut = std::min(span.scene.y, d);
    if (d > span.farSpan && sceneOut > sceneIn) {
        const int inside = std::max(2, uniform / 2);
        for (int i = 0; i < inside; ++i) ts.push_back(sceneIn + (sceneOut - sceneIn) * double(i) / double(inside - 1));
        uniform = std::max(2, uniform - inside);
    }
    for (int i = 0; i < uniform; ++i) ts.push_back(d * double(i) / double(uniform - 1));
    // Uniform in the angle seen from the light: t = tP + h tan(theta). The integrand (~ 1 / r^2) is
    // largest near the closest approach, and a shadow boundary there is where a missed sliver costs most.
    if (h > 0.0) {
        const int angular = samples - uniform;
        const double th0 = std::atan((0.0 - tP) / h), th1 = std::atan((d - tP) / h);
        for (int i = 0; i < angular; ++i) {
            const double th = th0 + (th1 - th0) * (double(i) + 0.5) / double(angular);
            ts.push_back(std::clamp(tP + h * std::tan(th), 0.0, d));
        }
    }
    std::sort(ts.begin(), ts.end());
    ts.erase(std::unique(ts.begin(), ts.end()), ts.end());

    std::vector<char> lit(ts.size());
    for (std::size_t i = 0; i < ts.size(); ++i) lit[i] = visible(ts[i]) ? 1 : 0;

    const double tol = 1e-9 * d;
    double start = lit[0] ? 0.0 : -1.0;  // start of the current lit interval, -1 = in shadow
    for (std::size_t i = 1; i < ts.size(); ++i) {
        if (lit[i] == lit[i - 1]) continue;
        // Bisect the bracket [lo, hi] whose ends differ until it is below tol.
        double lo = ts[i - 1], hi = ts[i];
        const bool loLit = lit[i - 1] != 0;
        while (hi - lo > tol) {
            const double mid = 0.5 * (lo + hi);
            if (visible(mid) == loLit) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        const double edge = 0.5 * (lo + hi);
        ++out.transitions;
        if (loLit) {
            out.lit.push_back(Interval{start, edge});
            start = -1.0;
        } else {
            start = edge;
        }
    }
    if (start >= 0.0) out.lit.push_back(Interval{start, d});
    return out;
}

// ---- geometry ----

RayEmitterGeometry rayEmitterGeometry(const glm::dvec3& o, const glm::dvec3& w, const glm::dvec3& P) {
    RayEmitterGeometry g;
    const glm::dvec3 D = P - o;
    const auto lg = airlight::rayLightGeometry(D, w);
    g.tP = lg.tP;
    g.h = lg.h;
    // Offset of the light from its closest point on the line; its length is h.
    const glm::dvec3 off = D - g.tP * w;
    const double len = glm::length(off);
    if (len > 0.0) {
        g.nHat = off / len;
    } else {
        // The ray passes through the light: any unit vector orthogonal to w.
        const glm::dvec3 a = std::abs(w.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
        g.nHat = glm::normalize(glm::cross(w, a));
    }
    return g;
}

namespace {

// Unit direction light -> x(theta): x - P = (t - tP) w - h nHat = r (sin(theta) w - cos(theta) nHat).
glm::dvec3 dirFromLight(const RayEmitterGeometry& g, const glm::dvec3& w, double theta) {
    return std::sin(theta) * w - std::cos(theta) * g.nHat;
}

// Angles theta in (th0, th1) where dot(a, dir(theta)) = c, i.e. A sin(theta) - B cos(theta) = c with
// A = a.w, B = a.nHat; written R sin(theta - phi) = c, R = hypot(A, B), phi = atan2(B, A).
void solveDirectionDot(const glm::dvec3& a, double c, const RayEmitterGeometry& g, const glm::dvec3& w,
                       double th0, double th1, std::vector<double>& out) {
    const double A = glm::dot(a, w), B = glm::dot(a, g.nHat);
    const double R = std::hypot(A, B);
    if (!(R > 0.0) || std::abs(c) > R) return;
    const double phi = std::atan2(B, A);
    const double s = std::asin(c / R);
    for (double base : {phi + s, phi + std::numbers::pi - s}) {
        // theta lives in (-pi/2, pi/2): bring each solution into [-pi, pi) then test.
        double th = std::remainder(base, 2.0 * std::numbers::pi);
        if (th > th0 && th < th1) out.push_back(th);
    }
}

}  // namespace

std::vector<double> profileKinks(const PointEmitter& e, const RayEmitterGeometry& g, const glm::dvec3& w,
                                 double theta0, double theta1) {
    std::vector<double> kinks;
    if (e.kind == ProfileKind::Lambertian) {
        // The emitter's plane: max(0, cos theta_e) has a kink where cos theta_e changes sign.
        solveDirectionDot(e.normal, 0.0, g, w, theta0, theta1, kinks);
    } else if (e.kind == ProfileKind::Spot) {
        const SpotProfile& sp = *e.spot;
        // Outer cone (A reaches 0) and inner cone (A reaches 1): cd = dot(s, dir) = cos(angle).
        solveDirectionDot(sp.axis, sp.cosOuter, g, w, theta0, theta1, kinks);
        solveDirectionDot(sp.axis, sp.cosInner, g, w, theta0, theta1, kinks);
        if (sp.cookie) {
            // Bilinear filtering is linear between texel centres: kinks on the lines
            // u = (i + 0.5) / W, i.e. dot(right - k s, dir) = 0 with k = (2u - 1) tan(outer) (and the
            // same for v with `up`). Each line is a plane through the light.
            std::vector<double> cookieKinks;
            const int W = sp.cookie->width(), H = sp.cookie->height();
            for (int i = 0; i < W; ++i) {
                const double k = (2.0 * (i + 0.5) / W - 1.0) * sp.tanOuter;
                solveDirectionDot(sp.right - k * sp.axis, 0.0, g, w, theta0, theta1, cookieKinks);
            }
            for (int j = 0; j < H; ++j) {
                const double k = (2.0 * (j + 0.5) / H - 1.0) * sp.tanOuter;
                solveDirectionDot(sp.up - k * sp.axis, 0.0, g, w, theta0, theta1, cookieKinks);
            }
            // Keep the ones inside the outer cone (in front of the light); outside, A = 0 anyway.
            for (double th : cookieKinks) {
                if (glm::dot(sp.axis, dirFromLight(g, w, th)) > sp.cosOuter) kinks.push_back(th);
            }
        }
    }
    std::sort(kinks.begin(), kinks.end());
    kinks.erase(std::unique(kinks.begin(), kinks.end()), kinks.end());
    return kinks;
}

glm::dvec3 pointEmitterSegment(const PointEmitter& e, const glm::dvec3& o, const glm::dvec3& w, double a,
                               double b, const MediumParams& m, SegmentStats* stats, double relTol) {
    if (!(b > a) || m.sigma_s == 0.0) return glm::dvec3(0.0);
    const RayEmitterGeometry g = rayEmitterGeometry(o, w, e.position);
    if (e.kind == ProfileKind::Isotropic) {
        const double v = airlight::pointSegment(g.tP, g.h, a, b, m.sigma_s, m.sigma_t, m.g, 1.0);
        if (stats) ++stats->pieces;
        return e.intensity * v;
    }
    // Profile-weighted: integrate in theta = atan((t - tP) / h) over [theta(a), theta(b)], where
    // dt / r^2 = dtheta / h and cos(phase angle) = dot(dir light->x, -w) = -sin(theta).
    // Raised to the floor the closed forms use (a ray from or through the light: a spot at the eye).
    const double h = airlight::flooredLightDistance(g.tP, g.h, a, b);
    const double th0 = std::atan((a - g.tP) / h), th1 = std::atan((b - g.tP) / h);
    std::vector<double> cuts{th0};
    for (double k : profileKinks(e, g, w, th0, th1)) cuts.push_back(k);
    cuts.push_back(th1);

    auto integrand = [&](double th) {
        const double s = std::sin(th), c = std::cos(th);
        const double t = g.tP + h * (s / c);  // tan(th) from the sine and cosine already at hand
        const double r = h / c;
        const glm::dvec3 dir = s * w - c * g.nHat;
        const double phase = airlight::phaseHG(-s, m.g);
        return (m.sigma_s * phase * std::exp(-m.sigma_t * (t + r)) / h) * e.profile(dir);
    };
    glm::dvec3 sum(0.0);
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        const double lo = cuts[i], hi = cuts[i + 1];
        if (!(hi > lo)) continue;
        // Outside the outer cone or behind the emitter the whole piece is zero: skip it.
        const double mid = 0.5 * (lo + hi);
        const glm::dvec3 midDir = dirFromLight(g, w, mid);
        const bool dark = e.kind == ProfileKind::Spot ? e.spot->attenuation(midDir) == 0.0
                                                      : glm::dot(e.normal, midDir) <= 0.0;
        if (dark) continue;
        const QuadratureResult q = integrateAdaptive(integrand, lo, hi, relTol, 0.0);
        sum += q.value;
        if (stats) {
            ++stats->pieces;
            stats->evaluations += q.evaluations;
            const double mag = std::max({std::abs(q.value.x), std::abs(q.value.y), std::abs(q.value.z)});
            if (mag > 0.0) stats->relError = std::max(stats->relError, q.errorEstimate / mag);
        }
    }
    return e.intensity * sum;
}

// ---- area cells ----

glm::dvec3 cellSegment(const AreaCell& cell, const glm::dvec3& o, const glm::dvec3& w, double a, double b,
                       const MediumParams& m) {
    if (!(b > a) || m.sigma_s == 0.0) return glm::dvec3(0.0);
    const AreaEmitter& e = *cell.emitter;
    // Keep the part of [a, b] in front of the emitter's plane (s = signed height above it, linear in t):
    // behind it cos(theta_e) <= 0 for every node, and a near-miss there must not refine the cell.
    const double s0 = glm::dot(o + a * w - e.corner, e.normal), s1 = glm::dot(o + b * w - e.corner, e.normal);
    if (s0 <= 0.0 && s1 <= 0.0) return glm::dvec3(0.0);
    if (s0 < 0.0) a += (b - a) * (-s0 / (s1 - s0));
    if (s1 < 0.0) b = a + (b - a) * (s0 / (s0 - s1));
    if (!(b > a)) return glm::dvec3(0.0);
    glm::dvec3 sum(0.0);
    for (const CellNode& node : cellNodes(cell, o + a * w, o + b * w)) {
        PointEmitter p;
        p.position = node.position;
        p.intensity = node.weight;
        p.kind = ProfileKind::Lambertian;
        p.normal = e.normal;
        sum += pointEmitterSegment(p, o, w, a, b, m, nullptr, kCellNodeRelTol);
    }
    return sum;
}

glm::dvec3 cellInScatter(const AreaCell& cell, const glm::dvec3& x, const glm::dvec3& w, const MediumParams& m) {
    const glm::dvec3 normal = cell.emitter->normal;
    glm::dvec3 sum(0.0);
    for (const CellNode& node : cellNodes(cell, x, x)) {
        const glm::dvec3 toX = x - node.position;
        const double r = glm::length(toX);
        if (!(r > 0.0)) continue;
        const glm::dvec3 dir = toX / r;
        const double cosE = glm::dot(normal, dir);
        if (cosE <= 0.0) continue;
        // cos(phase angle) = dot(direction node -> x, direction x -> eye) = dot(dir, -w).
        const double p = airlight::phaseHG(glm::dot(dir, -w), m.g);
        sum += node.weight * (cosE * p * std::exp(-m.sigma_t * r) / (r * r));
    }
    return sum;
}

glm::dvec3 emitterSegment(const PointEmitter& e, const glm::dvec3& o, const glm::dvec3& w, double a, double b,
                          const MediumParams& m) {
    return e.cell ? cellSegment(*e.cell, o, w, a, b, m) : pointEmitterSegment(e, o, w, a, b, m);
}

glm::dvec3 directionalSegment(const DirectionalEmitter& e, const glm::dvec3& w, double a, double b,
                              const MediumParams& m) {
    if (!(b > a) || m.sigma_s == 0.0) return glm::dvec3(0.0);
    // cos(phase angle) = dot(travel direction, direction x -> eye) = dot(dir, -w).
    const double cosTheta = glm::dot(e.direction, -w);
    return e.irradiance * airlight::directionalSegment(cosTheta, a, b, m.sigma_s, m.sigma_t, m.g, 1.0);
}

}  // namespace viz::reference
