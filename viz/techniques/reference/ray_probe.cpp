#include "techniques/reference/ray_probe.h"

#include <algorithm>

#include "scene/camera.h"
#include "techniques/reference/emitters.h"
#include "techniques/reference/pixel_ray.h"
#include "techniques/reference/ray_tracer.h"

namespace viz::reference {

namespace {

// Sorted union of intervals.
std::vector<Interval> unionOf(std::vector<Interval> all) {
    std::sort(all.begin(), all.end(), [](const Interval& a, const Interval& b) { return a.a < b.a; });
    std::vector<Interval> out;
    for (const Interval& i : all) {
        if (!out.empty() && i.a <= out.back().b) out.back().b = std::max(out.back().b, i.b);
        else out.push_back(i);
    }
    return out;
}

}  // namespace

RayProbe probePixel(const scene::Scene& scene, int width, int height, int x, int y, const ProbeOptions& options) {
    RayProbe probe;
    probe.x = x, probe.y = y;
    const RayTracer tracer(scene);
    const PreparedLights lights = PreparedLights::build(scene, options.areaSamples);
    const MediumParams medium{scene.medium.sigma_s, scene.medium.sigma_t(), scene.medium.g};
    const glm::dvec3 eye = scene.camera.position;
    const glm::dvec3 w = scene::pixelRay(scene.camera, width, height, double(x), double(y));
    probe.direction = w;
    const Hit hit = tracer.intersect(eye, w, scene.camera.zfar);
    probe.d = hit.found ? std::min(hit.t, scene.camera.zfar) : scene.camera.zfar;

    const std::vector<VisibilitySearch> lit = rayVisibility(tracer, lights, eye, w, probe.d, options.transitionSamples, medium.sigma_t);
    probe.airlight = medium.sigma_s != 0.0 ? rayAirlight(lights, eye, w, lit, medium) : glm::dvec3(0.0);

    // Per scene light: its emitters' intervals and share of L_air.
    probe.lights.resize(scene.lights.size());
    std::vector<std::vector<Interval>> intervals(scene.lights.size());
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        probe.lights[i].light = int(i);
        probe.lights[i].name = scene.lights[i].name;
    }
    const auto account = [&](int light, const VisibilitySearch& v, const glm::dvec3& share) {
        if (light < 0 || std::size_t(light) >= probe.lights.size()) return;
        intervals[std::size_t(light)].insert(intervals[std::size_t(light)].end(), v.lit.begin(), v.lit.end());
        probe.lights[std::size_t(light)].airlight += share;
    };
    for (std::size_t k = 0; k < lights.points.size(); ++k) {
        glm::dvec3 share(0.0);
        if (medium.sigma_s != 0.0)
            for (const Interval& iv : lit[k].lit) share += emitterSegment(lights.points[k], eye, w, iv.a, iv.b, medium);
        account(lights.points[k].light, lit[k], share);
    }
    for (std::size_t k = 0; k < lights.directionals.size(); ++k) {
        const VisibilitySearch& v = lit[lights.points.size() + k];
        glm::dvec3 share(0.0);
        if (medium.sigma_s != 0.0)
            for (const Interval& iv : v.lit) share += directionalSegment(lights.directionals[k], w, iv.a, iv.b, medium);
        account(lights.directionals[k].light, v, share);
    }
    for (std::size_t i = 0; i < probe.lights.size(); ++i) probe.lights[i].lit = unionOf(intervals[i]);

    const int n = std::max(2, options.curvePoints);
    for (int j = 0; j < n; ++j) {
        const double t = probe.d * (double(j) + 0.5) / double(n);
        probe.t.push_back(t);
        probe.integrand.push_back(rayIntegrand(lights, eye, w, t, lit, medium));
    }
    return probe;
}

}  // namespace viz::reference
