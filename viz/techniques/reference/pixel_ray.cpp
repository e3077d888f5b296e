#include "techniques/reference/pixel_ray.h"

#include <cmath>

#include "scene/ray_reach.h"
#include "shared/airlight.h"

namespace viz::reference {

namespace {

bool insideLit(const VisibilitySearch& s, double t) {
    for (const Interval& i : s.lit)
        if (t >= i.a && t <= i.b) return true;
    return false;
}

}  // namespace

std::vector<VisibilitySearch> rayVisibility(const RayTracer& tracer, const PreparedLights& lights,
                                            const glm::dvec3& o, const glm::dvec3& w, double d, int samples,
                                            double sigmaT) {
    std::vector<VisibilitySearch> list(lights.points.size() + lights.directionals.size());
    const bool anyGeometry = !tracer.empty();
    SearchSpan span;
    if (sigmaT > 0.0) span.reach = scene::kReachMeanFreePaths / sigmaT;
    span.scene = tracer.insideBounds(o, w, d);
    span.farSpan = scene::kFarSpanRadii * 0.5 * tracer.boundsDiagonal();
    for (std::size_t k = 0; k < lights.points.size(); ++k) {
        const PointEmitter& e = lights.points[k];
        if (!anyGeometry) {
            list[k].lit = {{0.0, d}};
            continue;
        }
        const auto g = rayEmitterGeometry(o, w, e.position);
        list[k] = findLitIntervals([&](double t) { return !tracer.occludedSegment(o + t * w, e.position); }, d,
                                   samples, g.tP, g.h, span);
    }
    for (std::size_t k = 0; k < lights.directionals.size(); ++k) {
        const DirectionalEmitter& e = lights.directionals[k];
        VisibilitySearch& s = list[lights.points.size() + k];
        if (!anyGeometry) {
            s.lit = {{0.0, d}};
            continue;
        }
        s = findLitIntervals([&](double t) { return !tracer.occludedRay(o + t * w, -e.direction); }, d, samples,
                             0.0, -1.0, span);
    }
    return list;
}

glm::dvec3 rayAirlight(const PreparedLights& lights, const glm::dvec3& o, const glm::dvec3& w,
                       const std::vector<VisibilitySearch>& lit, const MediumParams& medium) {
    glm::dvec3 L(0.0);
    for (std::size_t k = 0; k < lights.points.size(); ++k)
        for (const Interval& iv : lit[k].lit) L += emitterSegment(lights.points[k], o, w, iv.a, iv.b, medium);
    for (std::size_t k = 0; k < lights.directionals.size(); ++k)
        for (const Interval& iv : lit[lights.points.size() + k].lit)
            L += directionalSegment(lights.directionals[k], w, iv.a, iv.b, medium);
    return L;
}

glm::dvec3 rayIntegrand(const PreparedLights& lights, const glm::dvec3& o, const glm::dvec3& w, double t,
                        const std::vector<VisibilitySearch>& lit, const MediumParams& medium) {
    glm::dvec3 sum(0.0);
    const glm::dvec3 x = o + t * w;
    for (std::size_t k = 0; k < lights.points.size(); ++k) {
        if (!insideLit(lit[k], t)) continue;
        const PointEmitter& e = lights.points[k];
        if (e.cell) {
            sum += medium.sigma_s * std::exp(-medium.sigma_t * t) * cellInScatter(*e.cell, x, w, medium);
            continue;
        }
        const glm::dvec3 toX = x - e.position;
        const double r = glm::length(toX);
        if (!(r > 0.0)) continue;
        const glm::dvec3 dir = toX / r;
        // cos theta = dot(direction light -> point, direction point -> eye) = dot(dir, -w).
        const double p = airlight::phaseHG(glm::dot(dir, -w), medium.g);
        sum += medium.sigma_s * p * e.intensity * e.profile(dir) * std::exp(-medium.sigma_t * (t + r)) / (r * r);
    }
    for (std::size_t k = 0; k < lights.directionals.size(); ++k) {
        if (!insideLit(lit[lights.points.size() + k], t)) continue;
        const DirectionalEmitter& e = lights.directionals[k];
        const double p = airlight::phaseHG(glm::dot(e.direction, -w), medium.g);
        sum += medium.sigma_s * p * e.irradiance * std::exp(-medium.sigma_t * t);
    }
    return sum;
}

}  // namespace viz::reference
