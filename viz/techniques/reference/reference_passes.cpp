#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>

#include "scene/camera.h"
#include "techniques/reference/emitters.h"
#include "techniques/reference/pixel_ray.h"
#include "techniques/reference/ray_tracer.h"
#include "techniques/reference/reference_technique.h"

namespace viz::reference_detail {

namespace {

glm::dvec3 eyeRay(const FrameState& f, int x, int y) {
    return scene::pixelRay(f.scene->camera, f.width, f.height, double(x), double(y));
}

// ---- surface shading ----

struct SurfacePoint {
    glm::dvec3 position{0.0};
    glm::dvec3 normal{0.0};       // shading normal, facing the eye
    glm::dvec3 offsetNormal{0.0}; // geometric normal facing the eye: shadow rays start along it
    glm::dvec2 uv{0.0};
    glm::dvec3 albedo{1.0};
};

SurfacePoint surfacePoint(const scene::Scene& scene, const std::vector<reference::LinearTexture>& textures,
                          const Hit& hit, const glm::dvec3& o, const glm::dvec3& w) {
    const scene::Mesh& mesh = scene.meshes[std::size_t(hit.mesh)];
    const std::size_t t = std::size_t(hit.triangle);
    const std::uint32_t i0 = mesh.indices[3 * t], i1 = mesh.indices[3 * t + 1], i2 = mesh.indices[3 * t + 2];
    const double b0 = 1.0 - hit.u - hit.v, b1 = hit.u, b2 = hit.v;
    const glm::dvec3 p0(mesh.positions[i0]), p1(mesh.positions[i1]), p2(mesh.positions[i2]);
    SurfacePoint sp;
    sp.position = o + hit.t * w;
    glm::dvec3 ng = glm::cross(p1 - p0, p2 - p0);
    ng = glm::length(ng) > 0.0 ? glm::normalize(ng) : -w;
    if (glm::dot(ng, w) > 0.0) ng = -ng;
    sp.offsetNormal = ng;
    sp.normal = ng;
    if (!mesh.normals.empty()) {
        const glm::dvec3 n = b0 * glm::dvec3(mesh.normals[i0]) + b1 * glm::dvec3(mesh.normals[i1]) +
                             b2 * glm::dvec3(mesh.normals[i2]);
        if (glm::length(n) > 0.0) {
            sp.normal = glm::normalize(n);
            // Flipped to face the eye, like the geometric normal.
            if (glm::dot(sp.normal, w) > 0.0) sp.normal = -sp.normal;
        }
    }
    if (!mesh.uvs.empty()) {
        sp.uv = b0 * glm::dvec2(mesh.uvs[i0]) + b1 * glm::dvec2(mesh.uvs[i1]) + b2 * glm::dvec2(mesh.uvs[i2]);
    }
    if (mesh.material >= 0 && std::size_t(mesh.material) < scene.materials.size()) {
        const scene::Material& mat = scene.materials[std::size_t(mesh.material)];
        sp.albedo = glm::dvec3(mat.baseColorFactor);
        if (mat.baseColorTexture >= 0 && std::size_t(mat.baseColorTexture) < textures.size()) {
            sp.albedo *= textures[std::size_t(mat.baseColorTexture)].sample(sp.uv);
        }
    }
    return sp;
}

// Surface radiance towards the eye: emitted L_e (emitting side of an area light) + Lambert.
glm::dvec3 shadeSurface(const scene::Scene& scene, const PreparedLights& lights, const RayTracer& tracer,
                        const reference::MediumParams& m, const Hit& hit, const glm::dvec3& o,
                        const glm::dvec3& w) {
    const SurfacePoint sp = surfacePoint(scene, lights.textures, hit, o, w);
    const glm::dvec3 start = sp.position + tracer.rayEpsilon() * sp.offsetNormal;
    glm::dvec3 irradianceSum(0.0);  // sum over lights of E_surface * max(0, n.l) * V
    for (const PointEmitter& e : lights.points) {
        if (e.cell) {
            // Area cell: its irradiance integral over the cell (area_cells.h), visibility from its centre.
            if (glm::dot(e.normal, sp.position - e.position) <= 0.0) continue;  // behind the emitter
            if (tracer.occludedSegment(start, e.position)) continue;
            irradianceSum += reference::cellIrradiance(*e.cell, sp.position, sp.normal, m.sigma_t);
            continue;
        }
        const glm::dvec3 toLight = e.position - sp.position;
        const double r = glm::length(toLight);
        if (!(r > 0.0)) continue;
        const glm::dvec3 l = toLight / r;
        const double cosSurface = glm::dot(sp.normal, l);
        if (cosSurface <= 0.0) continue;
        const glm::dvec3 profile = e.profile(-l);
        if (profile == glm::dvec3(0.0)) continue;
        if (tracer.occludedSegment(start, e.position)) continue;
        irradianceSum += e.intensity * profile * (std::exp(-m.sigma_t * r) / (r * r)) * cosSurface;
    }
    for (const auto& e : lights.directionals) {
        const double cosSurface = glm::dot(sp.normal, -e.direction);
        if (cosSurface <= 0.0) continue;
        if (tracer.occludedRay(start, -e.direction)) continue;
        irradianceSum += e.irradiance * cosSurface;
    }
    glm::dvec3 radiance = sp.albedo / std::numbers::pi * irradianceSum;
    for (const auto& area : lights.areas) {
        const scene::Light& light = scene.lights[std::size_t(area.light)];
        if (light.mesh != hit.mesh || glm::dot(light.direction, -w) <= 0.0) continue;
        // Rectangle coordinates of the hit: uv (0,0) at position - halfU - halfV.
        const glm::dvec3 rel = sp.position - (light.position - light.halfU - light.halfV);
        const glm::dvec2 uv(glm::dot(rel, light.halfU) / (2.0 * glm::dot(light.halfU, light.halfU)),
                            glm::dot(rel, light.halfV) / (2.0 * glm::dot(light.halfV, light.halfV)));
        radiance += reference::areaRadiance(light, lights.textures, uv);
    }
    return radiance;
}

}  // namespace

FrameOutput ReferenceTechnique::compute(const FrameInput& input) const {
    const scene::Scene& scene = *input.scene;
    FrameOutput out;
    out.plan = plan(scene, input.settings);
    const ReferenceSettings s = referenceParams().readWithDefaults(input.settings);
    const int threads = s.threads;
    const int samples = s.transitionSamples;
    const int areaSamples = s.areaSamples;
    reference::ProgressBar progress(reference::stderrIsTerminal());
    FrameState f;
    f.width = input.width;
    f.height = input.height;
    f.scene = &scene;
    f.medium = {scene.medium.sigma_s, scene.medium.sigma_t(), scene.medium.g};
    const std::size_t n = std::size_t(f.width) * std::size_t(f.height);
    const glm::dvec3 eye = scene.camera.position;

    CpuStageClock clock;
    StageReuse reuse;  // the reference keeps nothing between runs
    StageRunner stages(mStages, input, out, reuse, clock);
    const auto stopped = [&]() -> FrameOutput& { return finishRun(out, f, scene, stages.stop(), progress); };

    // ---- stage 0: primary hits ----
    // Embree's scene and the lights' sampling are built in the first stage (their cost is its cost).
    std::optional<RayTracer> builtTracer;
    std::optional<PreparedLights> builtLights;
    if (!stages.run(kTrace, [&] {
        const RayTracer& tracer = builtTracer.emplace(scene);
        builtLights.emplace(PreparedLights::build(scene, areaSamples));
        f.hits.resize(n);
        f.distance.assign(n, scene.camera.zfar);
        f.distanceImage = Image(f.width, f.height, 1);
        reference::parallelRows(f.height, threads, [&](int y) {
            for (int x = 0; x < f.width; ++x) {
                const std::size_t i = f.pixel(x, y);
                f.hits[i] = tracer.intersect(eye, eyeRay(f, x, y), scene.camera.zfar);
                f.distance[i] = f.hits[i].found ? std::min(f.hits[i].t, scene.camera.zfar) : scene.camera.zfar;
                f.distanceImage.at(x, y) = float(f.distance[i]);
            }
        }, &progress, kStageTrace);
    }))
        return stopped();
    const RayTracer& tracer = *builtTracer;
    const PreparedLights& lights = *builtLights;

    // ---- stage 1: visibility transitions ----
    if (!stages.run(kVisibility, [&] {
        f.lit.assign(n, {});
        f.transitions = Image(f.width, f.height, 1);
        f.litFraction = Image(f.width, f.height, 1);
        reference::parallelRows(f.height, threads, [&](int y) {
            for (int x = 0; x < f.width; ++x) {
                const std::size_t i = f.pixel(x, y);
                const double d = f.distance[i];
                auto& list = f.lit[i];
                list = reference::rayVisibility(tracer, lights, eye, eyeRay(f, x, y), d, samples, f.medium.sigma_t);
                int transitions = 0;
                for (const VisibilitySearch& v : list) transitions += v.transitions;
                f.transitions.at(x, y) = float(transitions);
                f.litFraction.at(x, y) = float(litFraction(list, lights, d));
            }
        }, &progress, kStageVisibility);
    }))
        return stopped();

    // ---- stage 2: airlight ----
    if (!stages.run(kAirlightStage, [&] {
        f.airlight = Image(f.width, f.height, 3);
        if (f.medium.sigma_s != 0.0) {
            reference::parallelRows(f.height, threads, [&](int y) {
                for (int x = 0; x < f.width; ++x) {
                    const std::size_t i = f.pixel(x, y);
                    const glm::dvec3 w = eyeRay(f, x, y);
                    const glm::dvec3 L = reference::rayAirlight(lights, eye, w, f.lit[i], f.medium);
                    for (int c = 0; c < 3; ++c) f.airlight.at(x, y, c) = float(L[c]);
                }
            }, &progress, kStageAirlight);
        }
    }))
        return stopped();

    // ---- stage 3: surface radiance ----
    if (!stages.run(kSurfaceStage, [&] {
        f.surface = Image(f.width, f.height, 3);
        reference::parallelRows(f.height, threads, [&](int y) {
            for (int x = 0; x < f.width; ++x) {
                const Hit& hit = f.hits[f.pixel(x, y)];
                // Sky (and surfaces beyond zfar) have surface radiance 0.
                if (!hit.found || hit.t > scene.camera.zfar) continue;
                const glm::dvec3 Ls = shadeSurface(scene, lights, tracer, f.medium, hit, eye, eyeRay(f, x, y));
                for (int c = 0; c < 3; ++c) f.surface.at(x, y, c) = float(Ls[c]);
            }
        }, &progress, kStageSurface);
    }))
        return stopped();

    // ---- stage 4: compose ----
    stages.run(kFinalStage, [&] {
        f.final = Image(f.width, f.height, 3);
        for (int y = 0; y < f.height; ++y) {
            for (int x = 0; x < f.width; ++x) {
                const double T = std::exp(-f.medium.sigma_t * f.distance[f.pixel(x, y)]);
                for (int c = 0; c < 3; ++c)
                    f.final.at(x, y, c) = float(double(f.surface.at(x, y, c)) * T + double(f.airlight.at(x, y, c)));
            }
        }
    });
    return stopped();
}

FrameOutput& ReferenceTechnique::finishRun(FrameOutput& out, const FrameState& f, const scene::Scene& scene, int stopAfter,
                       reference::ProgressBar& progress) const {
    progress.finish();
    publish(out, f, scene, stopAfter);
    return out;
}

double ReferenceTechnique::litFraction(const std::vector<VisibilitySearch>& list, const PreparedLights& lights, double d) {
    if (lights.lightCount == 0 || !(d > 0.0)) return 0.0;
    std::vector<double> perLight(std::size_t(lights.lightCount), 0.0);
    for (std::size_t k = 0; k < lights.points.size(); ++k)
        perLight[std::size_t(lights.points[k].light)] += lights.points[k].nodeWeight * list[k].litLength() / d;
    for (std::size_t k = 0; k < lights.directionals.size(); ++k)
        perLight[std::size_t(lights.directionals[k].light)] += list[lights.points.size() + k].litLength() / d;
    double sum = 0.0;
    for (double v : perLight) sum += v;
    return sum / double(lights.lightCount);
}

}  // namespace viz::reference_detail
