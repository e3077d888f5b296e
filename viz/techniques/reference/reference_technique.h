// The reference as one class, declared here for its three files: reference.cpp (parameters, stages,
// plan, run and its disk cache), reference_passes.cpp (the stages' work: primary hits, visibility
// transitions, airlight, surface shading, compose) and reference_views.cpp (what it shows: the
// intermediates, from a computed or a cached frame). Only those files include it; the rest of the program
// knows the reference through reference.h.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "debug/declared_technique.h"
#include "debug/stage_runner.h"
#include "techniques/reference/parallel.h"
#include "techniques/reference/ray_integrals.h"
#include "techniques/reference/ray_tracer.h"
#include "techniques/reference/reference.h"
#include "techniques/reference/reference_cache.h"

namespace viz::reference_detail {

using reference::Hit;
using reference::PointEmitter;
using reference::PreparedLights;
using reference::RayTracer;
using reference::VisibilitySearch;

// Bump whenever a change to the algorithm changes any output pixel: it is part of the cache key.
// 2: area lights as cells integrated over their area (area_cells.h) instead of Gauss-Legendre point nodes.
// 3: double's floor for rays through a point light lowered from 1e-7 to 1e-13 of the ray's extent, so a
//    ray passing 1e-6 from the light keeps its own distance (stiff/ray-near-light's centre pixel).
// 4: the visibility search covers at most 60 mean free paths and, on rays longer than 8 radii of the
//    scene's bounds, samples inside the bounds (a camera's zfar of 1e6 once left a colonnade's shafts
//    unsearched: L_air 0.36 at zfar 1e4 and 0.60 at 1e6 where 1e2 and 1e3 give 0.428).
// 5: a spot's (and every profile-weighted emitter's) quadrature takes the closed forms' floor on the
//    light-to-ray distance instead of 1e-300 (a spot at the eye gave Inf on every pixel).
constexpr int kReferenceVersion = 5;

// ---- ids (stable: lessons and tests use them) ----
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

// The settings a run reads, each declared once with its parameter (debug/param_table.h). Callers may pass
// partial settings: a missing name takes its default.
struct ReferenceSettings {
    int transitionSamples = 0, areaSamples = 0, threads = 0;
    bool cache = false;
};

const ParamTable<ReferenceSettings>& referenceParams();

class ReferenceTechnique final : public DeclaredTechnique<ReferenceSettings> {
public:
    ReferenceTechnique();

    Plan plan(const scene::Scene& scene, const Settings& settings) const override;
    FrameOutput run(const FrameInput& input) override;

private:
    // Everything that changes a pixel: algorithm version, scene content, size and the settings
    // (except threads and cache, which do not change the result).
    std::string cacheKey(const FrameInput& input) const;
    // reference_views.cpp: intermediates in stage order; identical for computed and cached frames.
    void publish(FrameOutput& out, const FrameState& f, const scene::Scene& scene, int stopAfter) const;
    bool fromCache(const reference::CachedImages& c, const scene::Scene& scene, const FrameInput& input,
                   FrameOutput& out) const;
    // reference_passes.cpp: the five stages.
    FrameOutput compute(const FrameInput& input) const;
    FrameOutput& finishRun(FrameOutput& out, const FrameState& f, const scene::Scene& scene, int stopAfter,
                           reference::ProgressBar& progress) const;
    // Lit length / d per light, averaged over lights; an area light averages its cells (equal weights
    // summing to 1).
    static double litFraction(const std::vector<VisibilitySearch>& list, const PreparedLights& lights, double d);

};

}  // namespace viz::reference_detail
