#include "techniques/reference/reference.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <sstream>
#include <string_view>

#include "core/error.h"
#include "debug/param_table.h"
#include "debug/stage_runner.h"
#include "scene/camera.h"
#include "scene/scene_source.h"
#include "techniques/reference/emitters.h"
#include "techniques/reference/parallel.h"
#include "techniques/reference/pixel_ray.h"
#include "techniques/reference/ray_integrals.h"
#include "techniques/reference/ray_tracer.h"
#include "techniques/reference/reference_cache.h"

namespace viz {

namespace {

using reference::Hit;
using reference::PointEmitter;
using reference::PreparedLights;
using reference::RayTracer;
using reference::VisibilitySearch;

// Bump whenever a change to the algorithm changes any output pixel: it is part of the cache key.
// 2: area lights as cells integrated over their area (area_cells.h) instead of Gauss-Legendre point nodes.
// 3: double's floor for rays through a point light lowered from 1e-7 to 1e-13 of the ray's extent, so a
//    ray passing 1e-6 from the light keeps its own distance (stiff/ray-near-light's centre pixel).
constexpr int kReferenceVersion = 3;

constexpr const char* kStageTrace = "reference.trace";
constexpr const char* kStageVisibility = "reference.visibility";
constexpr const char* kStageAirlight = "reference.airlight";
constexpr const char* kStageSurface = "reference.surface";
constexpr const char* kStageFinal = "reference.final";

constexpr const char* kDistance = "reference.distance";
constexpr const char* kTransitions = "reference.transitions";
constexpr const char* kLitFraction = "reference.lit_fraction";
constexpr const char* kAirlight = "reference.airlight";
constexpr const char* kSurface = "reference.surface";
constexpr const char* kFinal = "reference.final";

constexpr const char* kParamTransitionSamples = "transition_samples";
constexpr const char* kParamAreaSamples = "area_samples";
constexpr const char* kParamThreads = "threads";
constexpr const char* kParamCache = "cache";

constexpr std::array<std::string_view, 5> kStageOrder = {kStageTrace, kStageVisibility, kStageAirlight, kStageSurface,
                                                         kStageFinal};
constexpr int kTrace = stageIndexOf(kStageOrder, kStageTrace);
constexpr int kVisibility = stageIndexOf(kStageOrder, kStageVisibility);
constexpr int kAirlightStage = stageIndexOf(kStageOrder, kStageAirlight);
constexpr int kSurfaceStage = stageIndexOf(kStageOrder, kStageSurface);
constexpr int kFinalStage = stageIndexOf(kStageOrder, kStageFinal);

std::size_t triangleCount(const scene::Scene& scene) {
    std::size_t n = 0;
    for (const auto& m : scene.meshes) n += m.indices.size() / 3;
    return n;
}

// ---- per-pixel state shared by the stages of one run ----

struct FrameState {
    int width = 0, height = 0;
    const scene::Scene* scene = nullptr;
    reference::MediumParams medium;
    std::vector<Hit> hits;
    std::vector<double> distance;                     // d = min(hit, zfar)
    std::vector<std::vector<VisibilitySearch>> lit;   // per pixel: per point emitter, then directionals
    Image distanceImage, transitions, litFraction, airlight, surface, final;

    std::size_t pixel(int x, int y) const { return std::size_t(y) * std::size_t(width) + std::size_t(x); }
};

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
    glm::dvec3 radiance = sp.albedo / 3.14159265358979323846 * irradianceSum;
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

// ---- the technique ----

// The settings a run reads, each declared once with its parameter (debug/param_table.h). Callers may pass
// partial settings: a missing name takes its default.
struct ReferenceSettings {
    int transitionSamples = 0, areaSamples = 0, threads = 0;
    bool cache = false;
};

const ParamTable<ReferenceSettings>& referenceParams() {
    using S = ReferenceSettings;
    static const ParamTable<S> table =
        ParamTable<S>()
            .add(&S::transitionSamples, {kParamTransitionSamples, "visibility samples per ray and light before "
                                         "bisection", 256, 2, 1 << 20, true})
            .add(&S::areaSamples, {kParamAreaSamples, "cells per axis of each area light (one visibility search per "
                                   "cell)", 8, 1, 64, true})
            .add(&S::threads, {kParamThreads, "worker threads (0 = all cores); the result does not depend on it", 0,
                               0, 1024, true})
            .add(&S::cache, {kParamCache, "1 = reuse and store results in the on-disk cache, 0 = always compute", 1,
                             0, 1, true});
    return table;
}

class ReferenceTechnique final : public Technique {
public:
    ReferenceTechnique() {
        mStages = {
            {kStageTrace, "Trace primary rays", "first hit of each pixel ray with Embree; d = min(hit, zfar)",
             {}, {kDistance}, 1},
            {kStageVisibility, "Find shadow transitions",
             "sample V along [0, d] with occlusion rays to each light (area lights: to each cell centre), "
             "bisect each change to 1e-9 d",
             {kParamTransitionSamples, kParamAreaSamples}, {kTransitions, kLitFraction}, 1},
            {kStageAirlight, "Integrate airlight",
             "integrate sigma_s p E exp(-sigma_t t) over each lit interval (closed form or adaptive Gauss-Kronrod)",
             {kParamAreaSamples}, {kAirlight}, 1},
            {kStageSurface, "Shade surfaces", "Lambert with shadow rays, plus emitted radiance of area lights",
             {kParamAreaSamples}, {kSurface}, 1},
            {kStageFinal, "Compose", "final = surface * exp(-sigma_t d) + L_air", {}, {kFinal}, 1},
        };
        checkStageOrder(mStages, kStageOrder);
    }

    std::string id() const override { return "reference"; }
    std::string description() const override {
        return "CPU ground truth in double precision: exact visibility transitions and per-interval integrals";
    }
    const std::vector<StageInfo>& stages() const override { return mStages; }
    const std::vector<ParamInfo>& params() const override { return referenceParams().infos(); }
    bool needsGl() const override { return false; }

    Plan plan(const scene::Scene& scene, const Settings& settings) const override {
        Plan p;
        const std::size_t triangles = triangleCount(scene);
        int spots = 0, cookies = 0, areas = 0, directionals = 0, points = 0;
        for (const auto& l : scene.lights) {
            if (l.type == scene::LightType::Spot) ++spots;
            if (l.type == scene::LightType::Spot && l.cookie >= 0) ++cookies;
            if (l.type == scene::LightType::Area) ++areas;
            if (l.type == scene::LightType::Directional) ++directionals;
            if (l.type == scene::LightType::Point) ++points;
        }
        const ReferenceSettings s = referenceParams().readWithDefaults(settings);
        const int areaSamples = s.areaSamples;
        p.stages.push_back({kStageTrace, true, std::to_string(triangles) + " triangles in one Embree scene"});
        if (scene.lights.empty()) {
            p.stages.push_back({kStageVisibility, true, "no lights: nothing to search (lit fraction 0)"});
        } else if (triangles == 0) {
            p.stages.push_back({kStageVisibility, true, "no triangles: V = 1 everywhere, no search"});
        } else {
            p.stages.push_back({kStageVisibility, true,
                                std::to_string(s.transitionSamples) +
                                    " samples per ray and light, then bisection"});
        }
        if (scene.medium.sigma_s == 0.0) {
            p.stages.push_back({kStageAirlight, true, "sigma_s = 0: the medium does not scatter, L_air = 0 (zeros)"});
        } else if (scene.lights.empty()) {
            p.stages.push_back({kStageAirlight, true, "no lights: L_air = 0 (zeros)"});
        } else {
            p.stages.push_back({kStageAirlight, true, ""});
        }
        p.stages.push_back({kStageSurface, true, ""});
        p.stages.push_back({kStageFinal, true, ""});

        p.features.push_back({"point closed form", points > 0,
                              points > 0 ? "airlight::pointSegment on each lit interval" : "no point light in the scene"});
        p.features.push_back({"spot cone splitting", spots > 0,
                              spots > 0 ? "lit intervals split where the ray crosses the inner and outer cones, "
                                          "adaptive Gauss-Kronrod to 1e-11"
                                        : "no spot light in the scene"});
        p.features.push_back({"cookie quadrature", cookies > 0,
                              cookies > 0 ? "split at every texel-centre line of the cookie, adaptive Gauss-Kronrod"
                                          : "no spot light with a cookie"});
        p.features.push_back({"emitter quadrature", areas > 0,
                              areas > 0 ? std::to_string(areaSamples) + "x" + std::to_string(areaSamples) +
                                              " cells per area light, each integrated over its area"
                                        : "no area light in the scene"});
        p.features.push_back({"directional closed form", directionals > 0,
                              directionals > 0 ? "airlight::directionalSegment" : "no directional light in the scene"});
        p.features.push_back({"transition search", triangles > 0,
                              triangles > 0 ? "occlusion rays + bisection" : "no triangles: nothing casts shadows"});
        const bool cache = s.cache;
        p.features.push_back({"disk cache", cache, cache ? reference::cacheDirectory().string() : "cache = 0"});
        return p;
    }

    FrameOutput run(const FrameInput& input) override {
        VIZ_CHECK(input.scene != nullptr, "FrameInput::scene is null");
        VIZ_CHECK(input.width > 0 && input.height > 0, "image size must be positive");
        const scene::Scene& scene = *input.scene;
        const int lastStage = int(mStages.size()) - 1;
        const int stopAfter = input.stopAfterStage < 0 ? lastStage : std::min(input.stopAfterStage, lastStage);
        const bool useCache = referenceParams().readWithDefaults(input.settings).cache && stopAfter == lastStage;

        std::filesystem::path cacheFile;
        if (useCache) {
            cacheFile = reference::cacheDirectory() / reference::cacheFileName(cacheKey(input));
            CpuStopwatch watch;
            if (auto cached = reference::readCache(cacheFile, input.width, input.height)) {
                if (FrameOutput out; fromCache(*cached, scene, input, out)) {
                    out.timing.clock = "cache";
                    out.timing.stages.push_back({"reference.cache", watch.elapsedMilliseconds()});
                    return out;
                }
            }
        }

        FrameOutput out = compute(input);
        if (useCache) {
            reference::CachedImages c;
            c.width = input.width;
            c.height = input.height;
            for (const auto& im : out.intermediates) c.images.emplace_back(im.id, *im.image);
            // Failing to write the cache (read-only folder) only costs time next run.
            reference::writeCache(cacheFile, c);
        }
        return out;
    }

private:
    std::string cacheKey(const FrameInput& input) const {
        // Everything that changes a pixel: algorithm version, scene content, size and the settings
        // (except threads and cache, which do not change the result).
        std::ostringstream key;
        key.precision(17);
        key << "reference v" << kReferenceVersion << " scene " << scene::sceneContentHash(*input.scene)
            << " size " << input.width << "x" << input.height;
        for (const auto& [name, value] : input.settings) {
            if (name == kParamThreads || name == kParamCache) continue;
            key << " " << name << "=" << value;
        }
        return key.str();
    }

    // Intermediates in stage order; identical for computed and cached frames.
    void publish(FrameOutput& out, const FrameState& f, const scene::Scene& scene, int stopAfter) const {
        auto add = [&](const char* id, const char* label, const char* note, const char* units, ViewKind kind,
                       const Image& img, float lo, float hi) {
            out.intermediates.push_back(cpuIntermediate(id, label, note, kind, std::make_shared<const Image>(img), lo, hi));
            out.intermediates.back().units = units;
        };
        auto maxOf = [](const Image& img) {
            float m = 0.0f;
            for (float v : img.pixels) m = std::max(m, v);
            return m > 0.0f ? m : 1.0f;
        };
        if (stopAfter >= kTrace)
            add(kDistance, "Distance d", "distance along the pixel ray to the first surface, zfar for sky",
                "scene units", ViewKind::Depth, f.distanceImage, 0.0f, float(scene.camera.zfar));
        if (stopAfter >= kVisibility) {
            add(kTransitions, "Shadow transitions", "lit/unlit changes along [0, d], summed over lights and area cells",
                "count", ViewKind::Scalar, f.transitions, 0.0f, maxOf(f.transitions));
            add(kLitFraction, "Lit fraction", "lit length / d, averaged over lights", "fraction", ViewKind::Scalar,
                f.litFraction, 0.0f, 1.0f);
        }
        if (stopAfter >= kAirlightStage) {
            // Radiance as the GPU techniques publish it: [0, 1] at the window's exposure, so the same
            // quantity looks the same in every technique; the caption is theirs too.
            add(kAirlight, "L_air", "single scattering along [0, d], every light", "radiance", ViewKind::Color,
                f.airlight, 0.0f, 1.0f);
            out.airlight = f.airlight;
        }
        if (stopAfter >= kSurfaceStage)
            add(kSurface, "Surface radiance", "Lambert + emitted, before attenuation by exp(-sigma_t d)", "radiance",
                ViewKind::Color, f.surface, 0.0f, 1.0f);
        if (stopAfter >= kFinalStage) {
            add(kFinal, "Final", "surface * exp(-sigma_t d) + L_air", "radiance", ViewKind::Color, f.final, 0.0f,
                1.0f);
            out.final = f.final;
        }
        out.lastStageRun = stopAfter;
    }

    bool fromCache(const reference::CachedImages& c, const scene::Scene& scene, const FrameInput& input,
                   FrameOutput& out) const {
        FrameState f;
        const struct {
            const char* id;
            Image* image;
            int channels;
        } wanted[] = {{kDistance, &f.distanceImage, 1}, {kTransitions, &f.transitions, 1},
                      {kLitFraction, &f.litFraction, 1}, {kAirlight, &f.airlight, 3},
                      {kSurface, &f.surface, 3},         {kFinal, &f.final, 3}};
        for (const auto& wnt : wanted) {
            const Image* img = c.find(wnt.id);
            if (!img || img->channels != wnt.channels || img->width != input.width || img->height != input.height)
                return false;
            *wnt.image = *img;
        }
        out.plan = plan(scene, input.settings);
        publish(out, f, scene, int(mStages.size()) - 1);
        return true;
    }

    FrameOutput compute(const FrameInput& input) const {
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
                    list = reference::rayVisibility(tracer, lights, eye, eyeRay(f, x, y), d, samples);
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

    FrameOutput& finishRun(FrameOutput& out, const FrameState& f, const scene::Scene& scene, int stopAfter,
                           reference::ProgressBar& progress) const {
        progress.finish();
        publish(out, f, scene, stopAfter);
        return out;
    }

    // Lit length / d per light, averaged over lights; an area light averages its cells (equal weights
    // summing to 1).
    static double litFraction(const std::vector<VisibilitySearch>& list, const PreparedLights& lights, double d) {
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

    std::vector<StageInfo> mStages;
};

}  // namespace

std::unique_ptr<Technique> makeReferenceTechnique() { return std::make_unique<ReferenceTechnique>(); }

}  // namespace viz
