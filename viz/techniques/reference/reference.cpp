#include "techniques/reference/reference_technique.h"

#include <algorithm>
#include <filesystem>
#include <memory>
#include <sstream>

#include "core/error.h"
#include "scene/scene_source.h"

namespace viz::reference_detail {

namespace {

std::size_t triangleCount(const scene::Scene& scene) {
    std::size_t n = 0;
    for (const auto& m : scene.meshes) n += m.indices.size() / 3;
    return n;
}

}  // namespace

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

ReferenceTechnique::ReferenceTechnique()
    : DeclaredTechnique({.id = "reference",
                         .description = "CPU ground truth in double precision: exact visibility transitions and "
                                        "per-interval integrals",
                         .needsGl = false},
                        referenceParams()) {
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

Plan ReferenceTechnique::plan(const scene::Scene& scene, const Settings& settings) const {
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

FrameOutput ReferenceTechnique::run(const FrameInput& input) {
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

std::string ReferenceTechnique::cacheKey(const FrameInput& input) const {
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

}  // namespace viz::reference_detail

namespace viz {

std::unique_ptr<Technique> makeReferenceTechnique() { return std::make_unique<reference_detail::ReferenceTechnique>(); }

}  // namespace viz
