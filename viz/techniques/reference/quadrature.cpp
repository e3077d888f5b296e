#include "techniques/reference/quadrature.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "core/error.h"

namespace viz::reference {

namespace {

struct Piece {
    double a, b;
    glm::dvec3 value;
    double error;
};

double maxAbs(const glm::dvec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

// One 15-point Kronrod estimate with the embedded 7-point Gauss rule as its error estimate.
Piece kronrod15(const std::function<glm::dvec3(double)>& f, double a, double b, int& evaluations) {
    using Kronrod = boost::math::quadrature::gauss_kronrod<double, 15>;
    using Gauss = boost::math::quadrature::gauss<double, 7>;
    const auto& x = Kronrod::abscissa();     // x[0] = 0, then increasing; Gauss nodes at even indices
    const auto& wk = Kronrod::weights();
    const auto& wg = Gauss::weights();
    const double c = 0.5 * (a + b), hw = 0.5 * (b - a);
    const glm::dvec3 f0 = f(c);
    glm::dvec3 kronrod = wk[0] * f0, gauss = wg[0] * f0;
    for (std::size_t i = 1; i < x.size(); ++i) {
        const glm::dvec3 fsum = f(c - hw * x[i]) + f(c + hw * x[i]);
        kronrod += wk[i] * fsum;
        if (i % 2 == 0) gauss += wg[i / 2] * fsum;
    }
    evaluations += 15;
    return Piece{a, b, hw * kronrod, maxAbs(hw * (kronrod - gauss))};
}

}  // namespace

QuadratureResult integrateAdaptive(const std::function<glm::dvec3(double)>& f, double a, double b,
                                   double relTol, double absTol, int maxIntervals) {
    QuadratureResult result;
    if (!(b > a)) return result;
    std::vector<Piece> pieces{kronrod15(f, a, b, result.evaluations)};
    auto byError = [](const Piece& p, const Piece& q) { return p.error < q.error; };
    glm::dvec3 total = pieces[0].value;
    double error = pieces[0].error;
    while (error > std::max(absTol, relTol * maxAbs(total))) {
        if (int(pieces.size()) >= maxIntervals) {
            result.converged = false;
            break;
        }
        // The pieces form a max-heap on error: split the worst one in two.
        std::pop_heap(pieces.begin(), pieces.end(), byError);
        const Piece worst = pieces.back();
        pieces.pop_back();
        const double mid = 0.5 * (worst.a + worst.b);
        if (!(mid > worst.a && mid < worst.b)) {
            // Interval at double resolution: nothing left to refine.
            pieces.push_back(Piece{worst.a, worst.b, worst.value, 0.0});
            std::push_heap(pieces.begin(), pieces.end(), byError);
            result.converged = false;
            break;
        }
        const Piece left = kronrod15(f, worst.a, mid, result.evaluations);
        const Piece right = kronrod15(f, mid, worst.b, result.evaluations);
        pieces.push_back(left);
        std::push_heap(pieces.begin(), pieces.end(), byError);
        pieces.push_back(right);
        std::push_heap(pieces.begin(), pieces.end(), byError);
        // Re-sum rather than update incrementally, so rounding does not accumulate.
        total = glm::dvec3(0.0);
        error = 0.0;
        for (const Piece& p : pieces) {
            total += p.value;
            error += p.error;
        }
    }
    result.value = total;
    result.errorEstimate = error;
    return result;
}


}  // namespace viz::reference
