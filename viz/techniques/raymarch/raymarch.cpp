#include "techniques/raymarch/raymarch.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <cmath>
#include <memory>
#include <string>

#include "core/blue_noise.h"
#include "core/error.h"
#include "debug/param_table.h"
#include "debug/permutations.h"
#include "debug/stage_runner.h"
#include "gl/program.h"
#include "gl/stage_clock.h"
#include "gl/texture.h"
#include "render/camera_ray.h"
#include "render/host_device.h"
#include "render/intermediates.h"
#include "render/light_culling.h"
#include "render/medium_block.h"
#include "render/scene_view.h"
#include "scene/camera.h"

namespace viz {
namespace {

// ---- ids (stable: lessons and tests use them) ----
constexpr const char* kStageMarch = "raymarch.march";
constexpr const char* kAirlight = "raymarch.airlight";
constexpr const char* kLitFraction = "raymarch.lit_fraction";

constexpr std::array<std::string_view, 4> kStageOrder = {"raymarch.shadow_maps", "raymarch.surface", kStageMarch,
                                                         "raymarch.compose"};
constexpr int kMarchIndex = stageIndexOf(kStageOrder, kStageMarch);
constexpr int kComposeIndex = stageIndexOf(kStageOrder, "raymarch.compose");

// llvmpipe stops all loops of one shader invocation after 65,535 iterations in total (measured: a loop
// of 70,000 runs 65,535 times; nested loops share the count). The march splits its (light, sample)
// pairs over dispatches so that no invocation comes near it: a plain sample costs a few iterations
// (shadow lookup), an exact one up to ~150 (pointSegment's sort and 13 Gauss-Legendre panels).
constexpr int kPairsPerDispatchPlain = 8192;
constexpr int kPairsPerDispatchExact = 256;

// Shader permutations of raymarch/march.comp: feature -> {define when enabled, define when disabled}.
// Features not listed are run-time branches.
const PermutationTable kDefines = {
    // feature: {define when enabled, define when disabled}
    {"EXACT", {"EXACT", nullptr}},
    {"NAIVE_CLOSED_FORM", {"NAIVE_CLOSED_FORM", nullptr}},
    {"JITTER", {"JITTER", nullptr}},
    {"JITTER_BLUE", {"JITTER_BLUE", nullptr}},
    {"SPOT", {nullptr, "LIGHTS_NO_SPOT"}},
    {"COOKIE", {nullptr, "LIGHTS_NO_COOKIE"}},
    {"SHADOW_MAPS_CUBE", {nullptr, "SHADOW_NO_CUBE"}},
    {"SHADOW_MAPS_2D", {nullptr, "SHADOW_NO_2D"}},
    {"SHADOW_LOOKUP_MESH", {"SHADOW_LOOKUP_MESH", nullptr}},
};

enum class Jitter { Off = 0, White = 1, Blue = 2 };

// The settings a run reads, each declared once with its parameter (debug/param_table.h).
struct MarchSettings {
    int samples = 0;
    Jitter jitter = Jitter::Off;
    bool jitterPerFrame = false;  // jitter_time=per-frame
    bool exact = false;
    bool naiveClosedForm = false;  // closed_form=naive
    unsigned seed = 0;
    bool meshLookup = false;  // shadow_lookup=mesh
    int shadowMap = 0, areaSamples = 0;
    bool forceFeatures = false;
};

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
            .add(&S::forceFeatures, forceFeaturesParam());
    VIZ_CHECK(table.missing().empty(), "raymarch declares a shared parameter the shared passes lack");
    return table;
}

class RaymarchTechnique final : public Technique {
public:
    RaymarchTechnique() {
        mStages = {
            render::SceneViewPasses::shadowStage("raymarch"),
            render::SceneViewPasses::surfaceStage("raymarch"),
            {kStageMarch, "Ray march", "N shadow-map tests per ray and light, summed into L_air",
             {"samples", "jitter", "jitter_time", "exact", "closed_form", "seed", "shadow_lookup", "force_features"}, {kAirlight, kLitFraction}, 1},
            render::SceneViewPasses::composeStage("raymarch"),
        };
        checkStageOrder(mStages, kStageOrder);
    }

    std::string id() const override { return "raymarch"; }
    std::string description() const override {
        return "brute-force ray marching through shadow maps (N samples per pixel)";
    }
    const std::vector<StageInfo>& stages() const override { return mStages; }
    const std::vector<ParamInfo>& params() const override { return marchParams().infos(); }
    bool needsGl() const override { return true; }

    // Samples per ray: the brute-force curve every other technique's speed-up is read against, so it
    // spans errors from about 1 down to below 1e-2.
    // At N = 16, where the jitter's noise shows: white offsets new every frame against the same every
    // frame, the same for blue noise, and blue against white (both constant).
    bool readsFrame(const Settings& settings) const override {
        return settingOr(settings, "jitter", 0.0) != 0.0 && settingOr(settings, "jitter_time", 0.0) != 0.0;
    }
    std::vector<StabilisingOption> stabilisingOptions(const scene::Scene& scene) const override {
        (void)scene;
        const auto at = [](double jitter, double perFrame) {
            return Settings{{"samples", 16.0}, {"jitter", jitter}, {"jitter_time", perFrame}};
        };
        return {{"jitter_time=constant (white)", "white-noise offsets drawn anew every frame", at(1, 1), at(1, 0)},
                {"jitter_time=constant (blue)", "blue-noise offsets stepped every frame", at(2, 1), at(2, 0)},
                {"jitter=blue", "white noise's clumps (both constant in time)", at(1, 0), at(2, 0)}};
    }

    std::vector<QualitySetting> qualitySweep(bool quick) const override {
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

    Settings stiffSettings() const override { return {{"samples", 1024.0}, {"exact", 1.0}}; }

    // Measured by `airlight report --suite stiff` at 33x25 (figures in README.md), bounds about twice that.
    std::optional<StiffBound> stiffBound(const std::string& caseClass) const override {
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
        const auto it = kBounds.find(caseClass);
        return it == kBounds.end() ? std::nullopt : std::optional<StiffBound>(it->second);
    }

    Plan plan(const scene::Scene& scene, const Settings& settings) const override {
        Plan p;
        for (const StageInfo& s : mStages) p.stages.push_back({s.id, true, ""});
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
                                            " virtual point lights with cube shadow maps"
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
        p.features.push_back({"SHADOW_LOOKUP_MESH", m.meshLookup,
                              m.meshLookup ? "shadow_lookup=mesh: 2D maps read as polyvol's light volume mesh"
                                         : "shadow_lookup=nearest: nearest texel with bias"});
        render::planCulledLights(scene, p);
        forcePlan(p, m.forceFeatures, {"SPOT", "COOKIE", "SHADOW_MAPS_CUBE", "SHADOW_MAPS_2D"});
        annotatePermutations(p, kDefines);
        return p;
    }

    FrameOutput run(const FrameInput& input) override {
        const scene::Scene& scene = *input.scene;
        const Settings& s = input.settings;
        FrameOutput out;
        out.plan = plan(scene, s);
        gl::StageClock clock;
        StageRunner stages(mStages, input, out, mReuse, clock);
        if (!mView.runSharedStages(stages, input, "raymarch", out)) return out;

        const bool more = stages.run(
            kMarchIndex,
            [&] {
                allocateTargets(input.width, input.height);
                if (out.plan.stages[kMarchIndex].runs) {
                    const gl::Program& program = marchProgram(out.plan);
                    march(program, scene, input);
                } else {
                    mAirlight.clear(glm::vec4(0.0f));
                    mLitFraction.clear(glm::vec4(0.0f));
                }
            },
            [&] {
                out.intermediates.push_back(render::textureIntermediate(
                    kAirlight, "L_air",
                    "single-scattered light reaching the eye (the quantity every technique computes)", "radiance",
                    ViewKind::Color, 0.0f, 1.0f, mAirlight));
                out.intermediates.push_back(render::textureIntermediate(
                    kLitFraction, "Lit fraction", "fraction of the ray samples that the shadow maps call lit", "",
                    ViewKind::Scalar, 0.0f, 1.0f, mLitFraction));
                out.airlight = render::readRgb(mAirlight);
            });
        if (!more) return out;

        stages.run(kComposeIndex, [&] { mView.compose(scene, mAirlight, out.intermediates, "raymarch"); },
                   [&] { out.final = mView.readFinal(); });
        return out;
    }

    // Linked cursors: the pixel's eye ray and its lit/shadow changes in each light's shadow map.
    std::vector<ViewMarker> markersFor(glm::ivec2 pixel, const std::string& id) const override {
        return mView.shadowMapMarkers(pixel, id, "raymarch");
    }

private:
    void allocateTargets(int width, int height) {
        if (mAirlight && mAirlight.size().x == width && mAirlight.size().y == height) return;
        mAirlight = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_RGBA32F, .size = {width, height, 1},
                                         .levels = 1, .label = kAirlight});
        mLitFraction = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_R32F, .size = {width, height, 1},
                                            .levels = 1, .label = kLitFraction});
    }

    // Compiles only the features the plan enabled (shader permutations by #define), cached per set:
    // an enabled EXACT / JITTER adds its define, a disabled light or shadow feature adds the define that
    // leaves its code out (shaders/common/lights.glsl, shadow_map.glsl).
    const gl::Program& marchProgram(const Plan& plan) {
        std::string key;
        const gl::ShaderDefines defines = permutationDefines(plan, kDefines, &key);
        // One program per permutation, kept: switching settings back and forth never recompiles (and a
        // timing never includes a compile after the warm-up).
        auto it = mMarchPrograms.find(key);
        if (it == mMarchPrograms.end())
            it = mMarchPrograms
                     .emplace(key, gl::Program::compile({.stages = {"raymarch/march.comp"},
                                                         .defines = defines,
                                                         .label = "raymarch.march"}))
                     .first;
        return it->second;
    }

    void march(const gl::Program& program, const scene::Scene& scene, const FrameInput& input) {
        const scene::Camera& cam = scene.camera;
        const MarchSettings s = marchParams().read(input.settings);
        program.use();
        render::bindCameraRay(program, cam, input.width, input.height);
        program.set("uSamples", s.samples);
        program.set("uLightCount", mView.lights().count());
        mMedium.bind(scene.medium);
        // jitter_time=per-frame: frame f draws new offsets (white: the seed moves by a large odd step; blue:
        // each pixel's offset moves by f times the golden ratio, modulo 1, a low-discrepancy walk in time
        // that keeps every frame's offsets a blue-noise pattern).
        const unsigned frame = s.jitterPerFrame ? unsigned(std::max(0, input.frame)) : 0u;
        program.set("uSeed", s.seed + frame * 0x9E3779B1u);
        program.set("uBlueShift", float(std::fmod(double(frame) * 0.6180339887498949, 1.0)));
        if (s.jitter == Jitter::Blue) blueNoiseTexture().bindUnit(render::hd::kFirstFreeTextureUnit + 1);
        mView.lights().bind();
        mView.shadows().bind();
        mView.surface().distance().bindUnit(render::hd::kFirstFreeTextureUnit);
        mAirlight.bindImage(0, GL_READ_WRITE);
        mLitFraction.bindImage(1, GL_READ_WRITE);
        const glm::ivec3 groups = gl::groupCount({input.width, input.height, 1}, program.workGroupSize());
        const std::int64_t pairs = std::int64_t(mView.lights().count()) * std::int64_t(s.samples);
        const std::int64_t chunk = pairsPerDispatch(s);
        for (std::int64_t begin = 0; begin == 0 || begin < pairs; begin += chunk) {
            const std::int64_t end = std::min(pairs, begin + chunk);
            program.set("uPairBegin", int(begin));
            program.set("uPairEnd", int(end));
            program.set("uFirst", begin == 0);
            program.set("uLast", end >= pairs);
            glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
            // The next dispatch reads what this one stored.
            glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        }
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }

    // The 64x64 blue-noise tile (core/blue_noise.h), made on first use.
    const gl::Texture& blueNoiseTexture() {
        if (!mBlueNoise) {
            const std::vector<float> values = blueNoise(kBlueNoiseSize);
            mBlueNoise = gl::Texture::create(
                {.format = GL_R32F, .size = {kBlueNoiseSize, kBlueNoiseSize, 1}, .label = "raymarch.blue_noise"});
            mBlueNoise.upload(GL_RED, GL_FLOAT, values.data());
        }
        return mBlueNoise;
    }
    static constexpr int kBlueNoiseSize = 64;  // shaders/raymarch/march.comp masks pixel coordinates with 63

    std::vector<StageInfo> mStages;
    gl::Texture mBlueNoise;
    render::SceneViewPasses mView;
    render::MediumBlock mMedium;  // sigma_s, sigma_t, g for the shaders (common/medium.glsl)
    StageReuse mReuse;  // stages carried over from the last run (FrameInput::resumeAtStage)
    static std::int64_t pairsPerDispatch(const MarchSettings& s) {
        return s.exact ? kPairsPerDispatchExact : kPairsPerDispatchPlain;
    }

    std::map<std::string, gl::Program> mMarchPrograms;  // by permutation key
    gl::Texture mAirlight, mLitFraction;
};

}  // namespace

std::unique_ptr<Technique> makeRaymarchTechnique() { return std::make_unique<RaymarchTechnique>(); }

}  // namespace viz
