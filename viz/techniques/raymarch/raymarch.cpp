#include "techniques/raymarch/raymarch_technique.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <map>
#include <memory>
#include <string>

#include "core/error.h"
#include "gl/stage_clock.h"
#include "render/intermediates.h"
#include "render/light_culling.h"
#include "scene/ray_reach.h"

namespace viz::raymarch_detail {

const ParamTable<MarchSettings>& marchParams() {
    using S = MarchSettings;
    static const ParamTable<S> table =
        ParamTable<S>()
            .add(&S::samples, {"samples", "samples per pixel and light along [0, d]", 64, 1, 65536, true})
            .add(&S::jitter, {"jitter", "off: interval midpoints; white: a random offset per pixel, sample interval and "
                              "light; blue: one offset per pixel for all its intervals, from a 64x64 blue-noise tile",
                              0, 0, 2, true, {"off", "white", "blue"}})
            .add(&S::jitterPerFrame,
                 {"jitter_time", "constant: the same offsets every frame (seed fixed); per-frame: new offsets on every "
                  "frame of an animation (white: the seed advances; blue: the tile's values step by the golden ratio)",
                  0, 0, 1, true, {"constant", "per-frame"}})
            .add(&S::exact, {"exact", "1: integrate the unshadowed airlight exactly over each sample's interval", 0, 0, 1,
                             true})
            .add(&S::naiveClosedForm,
                 {"closed_form",
                  "exact=1, point and spot lights: stable (pointSegment) or naive (teaching only: Sun et al.'s textbook "
                  "A0 [F(A1, xi1) - F(A1, xi0)], isotropic, fails in thick media)",
                  0, 0, 1, true, {"stable", "naive"}})
            .add(&S::seed, {"seed", "jitter seed", 1, 0, 1e9, true})
            .add(&S::meshLookup, {"shadow_lookup", "nearest: nearest texel with bias; mesh: depth linear across "
                                  "polyvol's triangles", 0, 0, 1, true, {"nearest", "mesh"}})
            .add(&S::shadowMap, render::SceneViewPasses::params(), "shadow_map")
            .add(&S::areaSamples, render::SceneViewPasses::params(), "area_samples")
            .declare(render::SceneViewPasses::params(), "vpl_kernel")
            .add(&S::forceFeatures, forceFeaturesParam());
    VIZ_CHECK(table.missing().empty(), "raymarch declares a shared parameter the shared passes lack");
    return table;
}

RaymarchTechnique::RaymarchTechnique()
    : GlTechnique({.id = "raymarch",
                   .description = "brute-force ray marching through shadow maps (N samples per pixel)"},
                  marchParams()) {
    mStages = {
        render::SceneViewPasses::shadowStage("raymarch"),
        render::SceneViewPasses::surfaceStage("raymarch"),
        {kStageMarch, "Ray march", "N shadow-map tests per ray and light, summed into L_air",
         {"samples", "jitter", "jitter_time", "exact", "closed_form", "seed", "shadow_lookup", "force_features"}, {kAirlight, kLitFraction}, 1},
        render::SceneViewPasses::composeStage("raymarch"),
    };
    checkStageOrder(mStages, kStageOrder);
}

std::vector<QualitySetting> RaymarchTechnique::qualitySweep(bool quick) const {
    std::vector<QualitySetting> sweep;
    for (int n = 4; n <= (quick ? 1024 : 2048); n *= quick ? 4 : 2)
        sweep.push_back({"N=" + std::to_string(n), {{"samples", double(n)}}});
    // At many samples the default 1024^2 map's resolution bounds the error, not the march: the
    // accurate end sweeps the map too, as the techniques' own sweeps do (equal-error comparisons need
    // both sides at their best).
    auto withMap = [&](int n, int map) {
        sweep.push_back({"N=" + std::to_string(n) + " map=" + std::to_string(map),
                         {{"samples", double(n)}, {"shadow_map", double(map)}}});
    };
    if (quick) {
        withMap(1024, 2048);
    } else {
        for (int n : {512, 1024, 2048}) withMap(n, 2048);
        for (int n : {1024, 2048}) withMap(n, 4096);
    }
    return sweep;
}

bool RaymarchTechnique::readsFrame(const Settings& settings) const {
    return settingOr(settings, "jitter", 0.0) != 0.0 && settingOr(settings, "jitter_time", 0.0) != 0.0;
}

// At N = 16, where the jitter's noise shows: white offsets new every frame against the same every
// frame, the same for blue noise, and blue against white (both constant).
std::vector<StabilisingOption> RaymarchTechnique::stabilisingOptions(const scene::Scene& scene) const {
    (void)scene;
    const auto at = [](double jitter, double perFrame) {
        return Settings{{"samples", 16.0}, {"jitter", jitter}, {"jitter_time", perFrame}};
    };
    return {{"jitter_time=constant (white)", "white-noise offsets drawn anew every frame", at(1, 1), at(1, 0)},
            {"jitter_time=constant (blue)", "blue-noise offsets stepped every frame", at(2, 1), at(2, 0)},
            {"jitter=blue", "white noise's clumps (both constant in time)", at(1, 0), at(2, 0)}};
}

std::optional<StiffBound> RaymarchTechnique::stiffBound(const std::string& caseClass) const {
    static const std::map<std::string, StiffBound> kBounds = {
        {"medium", {0.02, "exact=1 integrates each interval's unshadowed airlight: thick media cost nothing"}},
        {"intensity", {0.02, "linear in the intensity; float holds 1e-3 to 1e7 without clamping"}},
        {"scale", {0.02, "eye-relative coordinates and distance-valued shadow maps are scale-free"}},
        {"singular-ray", {0.005, "the shared closed form clamps h; the light's own pixel is left out"}},
        {"near-light", {1e-4, "exact=1 integrates each lit interval in closed form with the ray's own h (7.7e-7)"}},
        {"epipole", {0.04, "no epipolar structure to break; grazing sun is the worst (shadow-map bias)"}},
        {"camera-placement", {0.04, "rays start at the eye wherever it is"}},
        {"geometry", {0.05, "shadow-map rasterisation drops slivers the reference still hits"}},
        {"leak", {0.04, "the medium lookup reconstructs grazing planes and drops the surface bias (0.0018 measured: the march itself)"}},
        {"depth-range", {0.03, "distance-valued R32F maps keep the precision near the occluders"}},
        {"phase", {0.03, "the HG lobe is sampled along the ray; g = 0.99 is the worst"}},
    };
    return boundOf(kBounds, caseClass);
}


Plan RaymarchTechnique::plan(const scene::Scene& scene, const Settings& settings) const {
    Plan p = planEveryStage(mStages);
    if (scene.medium.sigma_s == 0.0) {
        p.stages[kMarchIndex].runs = false;
        p.stages[kMarchIndex].why = "sigma_s = 0: the medium scatters nothing, L_air = 0";
    }
    const bool hasSpot = render::hasLightOfType(scene, scene::LightType::Spot);
    const bool hasCookie = std::any_of(scene.lights.begin(), scene.lights.end(),
                                       [](const scene::Light& l) { return l.cookie >= 0; });
    const MarchSettings m = marchParams().read(settings);
    const bool exact = m.exact;
    const bool jitter = m.jitter != Jitter::Off;
    const bool blue = m.jitter == Jitter::Blue;
    const int area = m.areaSamples;
    p.features.push_back({"EXACT", exact,
                          exact ? "analytic unshadowed segment per sample interval (airlight.glsl pointSegment)"
                                : "exact=0: midpoint rule of the integrand"});
    // Teaching mode only (lesson 1): never in qualitySweep() or stiffSettings(), off by default.
    const bool naive = exact && m.naiveClosedForm;
    p.features.push_back({"NAIVE_CLOSED_FORM", naive,
                          naive ? "TEACHING MODE, wrong on purpose: Sun et al.'s closed form evaluated as printed "
                                  "(isotropic; cancels and overflows in thick media, NaN on a ray through the light)"
                                : "closed_form=stable (or exact=0): the stable anchored form of airlight.glsl"});
    p.features.push_back({"JITTER", jitter, jitter ? "stratified offsets" : "jitter=off: interval midpoints"});
    p.features.push_back({"JITTER_BLUE", blue,
                          blue ? std::string("one blue-noise offset per pixel") +
                                     (m.jitterPerFrame ? ", stepped every frame" : ", the same every frame")
                                          : "jitter=" + std::string(jitter ? "white" : "off") + ": no blue-noise tile"});
    p.features.push_back({"SPOT", hasSpot, hasSpot ? "spot falloff A_spot" : "no spot light in the scene"});
    p.features.push_back({"COOKIE", hasCookie, hasCookie ? "cookie texture" : "no light has a cookie"});
    p.features.push_back({"HENYEY_GREENSTEIN", scene.medium.g != 0.0,
                          scene.medium.g != 0.0 ? "g != 0 (run-time branch of phaseHG)"
                                                : "g = 0: isotropic phase 1/(4 pi) (run-time branch)"});
    const bool hasArea = render::hasLightOfType(scene, scene::LightType::Area);
    p.features.push_back({"AREA_VPLS", hasArea,
                          hasArea ? "each area light -> " + std::to_string(area * area) +
                                        " virtual point lights with cube shadow maps, " +
                                        render::SceneViewPasses::vplKernelText(settings)
                                  : "no area light in the scene"});
    const bool cubes = render::hasLightOfType(scene, scene::LightType::Point) || hasArea;
    p.features.push_back({"SHADOW_MAPS_CUBE", cubes,
                          cubes ? "point lights / VPLs need omnidirectional maps"
                                : "no point light or area light: no cube map needed"});
    const bool maps2D = hasSpot || render::hasLightOfType(scene, scene::LightType::Directional);
    p.features.push_back({"SHADOW_MAPS_2D", maps2D,
                          maps2D ? "spot / directional lights" : "no spot or directional light"});
    {
        // GPU lights: every light the view can see, an area light as area_samples^2 VPLs.
        std::int64_t lights = 0;
        for (const scene::Light& l : scene.lights)
            if (render::lightReachesView(l, scene.camera)) lights += l.type == scene::LightType::Area ? area * area : 1;
        const std::int64_t pairs = lights * std::int64_t(m.samples);
        const std::int64_t chunk = pairsPerDispatch(m);
        const std::int64_t dispatches = std::max<std::int64_t>(1, (pairs + chunk - 1) / chunk);
        p.features.push_back({"SPLIT_DISPATCHES", dispatches > 1,
                              std::to_string(pairs) + " (light, sample) pairs per pixel in " + std::to_string(dispatches) +
                                  " dispatch(es) of at most " + std::to_string(chunk) +
                                  ": llvmpipe stops an invocation's loops after 65,535 iterations"});
    }
    {
        // How long a lit span can be (litInterval: d <= zfar, at most 60 mean free paths) against the scene.
        const double longest = scene::longestLitSpan(scene);
        const double far = scene::farSpan(scene);
        const bool farRays = scene::farRaysPossible(scene);
        char why[200];
        std::snprintf(why, sizeof why,
                      farRays ? "spans up to %.3g against the scene's radius %.3g: spans over %.3g are sampled by the "
                                "light (equiangular about point-like lights, by transmittance for directional ones)"
                              : "every lit span (at most %.3g) fits in 8 of the scene's radii (%.3g; %.3g): "
                                "uniform samples",
                      longest, far / scene::kFarSpanRadii, far);
        p.features.push_back({"FAR_RAYS", farRays, why});
    }
    p.features.push_back({"SHADOW_LOOKUP_MESH", m.meshLookup,
                          m.meshLookup ? "shadow_lookup=mesh: 2D maps read as polyvol's light volume mesh"
                                     : "shadow_lookup=nearest: nearest texel with bias"});
    render::planCulledLights(scene, p);
    forcePlan(p, m.forceFeatures, {"SPOT", "COOKIE", "SHADOW_MAPS_CUBE", "SHADOW_MAPS_2D"});
    annotatePermutations(p, kDefines);
    return p;
}

FrameOutput RaymarchTechnique::run(const FrameInput& input) {
    const scene::Scene& scene = *input.scene;
    FrameOutput out;
    startRun(input, out);
    gl::StageClock clock;
    StageRunner stages(mStages, input, out, mReuse, clock);
    if (!mView.runSharedStages(stages, input, "raymarch", out)) return out;

    const bool more = stages.run(
        kMarchIndex,
        [&] {
            allocateTargets(input.width, input.height);
            if (out.plan.stages[kMarchIndex].runs) {
                const gl::Program& program = marchProgram(out.plan);
                march(program, out.plan, scene, input);
            } else {
                mAirlight.clear(glm::vec4(0.0f));
                mLitFraction.clear(glm::vec4(0.0f));
            }
        },
        [&] { publishMarch(out, input); });
    if (!more) return out;

    mView.runCompose(stages, kComposeIndex, input, mAirlight, out, "raymarch");
    return out;
}

}  // namespace viz::raymarch_detail

namespace viz {

std::unique_ptr<Technique> makeRaymarchTechnique() { return std::make_unique<raymarch_detail::RaymarchTechnique>(); }

}  // namespace viz
