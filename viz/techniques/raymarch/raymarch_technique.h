// The raymarch technique as one class, declared here for its three files: raymarch.cpp (parameters,
// stages, plan, run), raymarch_passes.cpp (the GL pass: the march) and raymarch_views.cpp (what it shows:
// intermediates, markers). Only those files include it; the rest of the program knows raymarch through
// raymarch.h.
#pragma once

#include <cstdint>

#include "render/gl_technique.h"
#include "techniques/raymarch/raymarch.h"

namespace viz::raymarch_detail {

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
inline const PermutationTable kDefines = {
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
    {"FAR_RAYS", {"FAR_RAYS", nullptr}},
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

const ParamTable<MarchSettings>& marchParams();

class RaymarchTechnique final : public render::GlTechnique<MarchSettings> {
public:
    RaymarchTechnique();

    bool readsFrame(const Settings& settings) const override;
    std::vector<StabilisingOption> stabilisingOptions(const scene::Scene& scene) const override;
    // Samples per ray: the brute-force curve every other technique's speed-up is read against, so it
    // spans errors from about 1 down to below 1e-2.
    std::vector<QualitySetting> qualitySweep(bool quick) const override;
    // Area lights: more VPLs, each count also at fewer of its samples (SceneViewPasses::areaSampleSweep).
    std::vector<QualitySetting> areaLightSweep(bool quick) const override {
        return render::SceneViewPasses::areaSampleSweep(quick, 16, "samples", 16);
    }
    Settings stiffSettings() const override { return {{"samples", 1024.0}, {"exact", 1.0}}; }
    // Measured by `airlight report --suite stiff` at 33x25 (figures in README.md), bounds about twice that.
    std::optional<StiffBound> stiffBound(const std::string& caseClass) const override;
    Plan plan(const scene::Scene& scene, const Settings& settings) const override;
    FrameOutput run(const FrameInput& input) override;
    // Linked cursors: the pixel's eye ray and its lit/shadow changes in each light's shadow map.
    std::vector<ViewMarker> markersFor(glm::ivec2 pixel, const std::string& id) const override;

private:
    // raymarch_passes.cpp
    void allocateTargets(int width, int height);
    // Compiles only the features the plan enabled (shader permutations by #define), cached per set:
    // an enabled EXACT / JITTER adds its define, a disabled light or shadow feature adds the define that
    // leaves its code out (shaders/common/lights.glsl, shadow_map.glsl).
    const gl::Program& marchProgram(const Plan& plan);
    void march(const gl::Program& program, const Plan& plan, const scene::Scene& scene, const FrameInput& input);

    // The 64x64 blue-noise tile (core/blue_noise.h), made on first use.
    const gl::Texture& blueNoiseTexture();
    static constexpr int kBlueNoiseSize = 64;  // shaders/raymarch/march.comp masks pixel coordinates with 63
    // raymarch_views.cpp: the march stage's intermediates and L_air.
    void publishMarch(FrameOutput& out, const FrameInput& input) const;

    gl::Texture mBlueNoise;
    static std::int64_t pairsPerDispatch(const MarchSettings& s) {
        return s.exact ? kPairsPerDispatchExact : kPairsPerDispatchPlain;
    }

    std::map<std::string, gl::Program> mMarchPrograms;  // by permutation key
    gl::Texture mAirlight, mLitFraction;
};

}  // namespace viz::raymarch_detail
