// The minmax technique (Chen, Baran, Durand, Jarosz 2011) as one class, declared here for its three files:
// minmax.cpp (parameters, stages, plan, run), minmax_passes.cpp (the GL passes: rectification, prefix sums,
// min-max trees, traversal) and minmax_views.cpp (what it shows: intermediates, charts, markers). Only those
// files include it; the rest of the program knows minmax through minmax.h.
#pragma once

#include <bit>
#include <cstdint>
#include <cstdio>
#include <map>
#include <numbers>

#include "gl/buffer.h"
#include "render/camera_ray.h"
#include "render/gl_technique.h"
#include "render/host_device.h"
#include "render/shadow_map_markers.h"
#include "techniques/minmax/charts.h"
#include "techniques/minmax/epipolar_setup.h"
#include "techniques/minmax/integrand_choice.h"
#include "techniques/minmax/low_rank.h"

namespace viz::minmax_detail {

// The two values S stores that are not an occluder's beta.
inline std::vector<Sentinel> outsideAndUnblocked() {
    return {{minmax::kOutsideCone, "outside the spot's cone"}, {minmax::kUnblocked, "unblocked light ray"}};
}

using minmax::LightKind;

// ---- ids (stable: lessons and tests use them) ----
constexpr const char* kStageRectify = "minmax.rectify";
constexpr const char* kStageMipmap = "minmax.mipmap";
constexpr const char* kStageTraverse = "minmax.traverse";
constexpr const char* kRectified = "minmax.rectified";
constexpr const char* kRectifiedView = "minmax.rectified_view";
constexpr const char* kTree = "minmax.tree";
constexpr const char* kPyramid = "minmax.pyramid";
constexpr const char* kTrace = "minmax.trace";
constexpr const char* kAirlight = "minmax.airlight";
constexpr const char* kVisited = "minmax.visited";
constexpr const char* kNearMask = "minmax.near_epipole";
constexpr const char* kRayCoords = "minmax.ray_coords";
constexpr const char* kSingularValues = "minmax.singular_values";
constexpr const char* kBasis = "minmax.basis";
constexpr const char* kPrefixSums = "minmax.prefix_sums";
constexpr const char* kReconstructionError = "minmax.reconstruction_error";
constexpr const char* kRowGamma = "minmax.row_gamma";

constexpr std::array<std::string_view, 6> kStageOrder = {"minmax.shadow_maps", "minmax.surface", kStageRectify,
                                                         kStageMipmap, kStageTraverse, "minmax.compose"};
constexpr int kRectifyIndex = stageIndexOf(kStageOrder, kStageRectify);
constexpr int kMipmapIndex = stageIndexOf(kStageOrder, kStageMipmap);
constexpr int kTraverseIndex = stageIndexOf(kStageOrder, kStageTraverse);
constexpr int kComposeIndex = stageIndexOf(kStageOrder, "minmax.compose");

// Shader permutations of minmax/*.comp: feature -> {define when enabled, define when disabled}.
inline const PermutationTable kDefines = {
    {"NEAR_EPIPOLE", {"NEAR_EPIPOLE", nullptr}},
    {"EPIPOLAR_POINT", {"EPIPOLAR_POINT", nullptr}},
    {"INTEGRAND_SVD", {"INTEGRAND_SVD", nullptr}},
    {"PREFIX_LOG2_PASSES", {"LOG2_PASSES", nullptr}},
    {"SPOT", {nullptr, "LIGHTS_NO_SPOT"}},
    {"COOKIE", {nullptr, "LIGHTS_NO_COOKIE"}},
    {"SHADOW_MAPS_CUBE", {nullptr, "SHADOW_NO_CUBE"}},
    {"SHADOW_MAPS_2D", {nullptr, "SHADOW_NO_2D"}},
    {"FAR_RAYS", {"FAR_RAYS", nullptr}},
};

// Lights with an epipolar path: spot and directional (2D maps), point (cube maps, per-row gamma ranges).
// Area lights (VPLs) are marched.
inline bool epipolarLight(const scene::Light& l) {
    return l.type == scene::LightType::Spot || l.type == scene::LightType::Directional ||
           l.type == scene::LightType::Point;
}

// One epipolar light's GPU objects, kept from frame to frame (prepareLights() moves them all to the next
// frame's LightWork; each is made again only where its size no longer fits).
struct LightTargets {
    // Point light: the gamma range of each row, [0, hi_i], one float per row stored as its uint bits
    // (gamma_range.comp); read back only to publish minmax.row_gamma.
    gl::Buffer rowGamma;
    gl::Texture rectified;  // r32f, columns x slices
    gl::Texture tree;       // rg32f, 2 columns x slices (Ahnentafel rows)
    gl::Texture prefix;     // integrand=svd: rgba32f array, (texels + 1) x rows x ceil(3 N / 4) layers
};

// Everything one epipolar light needs between the stages: its GPU objects and this frame's figures.
struct LightWork : LightTargets {
    int gpuIndex = 0;  // into GpuLights::lights()
    minmax::Setup setup;
    bool point() const { return setup.frame.kind == LightKind::Point; }
    int levelsBuilt = 0;
    // integrand=svd: the rank-N factorisation whose prefix sums of Gamma_i T `prefix` holds (prefix.comp).
    minmax::LowRank lowRank;
    int prefixRows = 0;
};

// integrand=: the segment integral per lit run, the paper's low-rank approximation, or whichever of the two
// plan() picks for the scene (integrand_choice.h).
enum class Integrand { Analytic = 0, Svd = 1, Auto = 2 };
enum class PrefixScan { Sequential = 0, Log2 = 1, Auto = 2 };

// Whether prefix.comp's sequential scan of one table row stays within llvmpipe's loop limit: it stops an
// invocation's loops after 65,535 iterations in total (docs/numerics.md, "GPU loop limits"), and a row
// takes about texels x (rank + layers + 4) (rank 8 with 4096 texels went silently wrong at texel 3855).
inline bool sequentialScanFits(int texels, int rank) {
    const long layers = (3 * rank + 3) / 4;
    return long(texels) * (rank + layers + 4) + 64 <= 65535;
}

// The settings a run reads, each declared once with its parameter (minmaxParams(), debug/param_table.h).
struct MinmaxSettings {
    int slices = 0, sliceOversampling = 0;
    bool fixedFrame = false;  // slice_frame=fixed
    int columns = 0;
    Integrand integrand = Integrand::Auto;
    int rank = 0, textureColumns = 0;
    PrefixScan prefixScan = PrefixScan::Auto;  // prefix_sums
    bool blendRows = true;                     // slice_blend=linear
    bool linear = false;       // traversal=linear
    bool marchPoints = false;  // point_lights=march
    int spotPieces = 0;
    double epipoleRadius = 0.0;
    int marchSamples = 0;
    int vplSamples = 0;
    int shadowMap = 0;
    bool forceFeatures = false;
};
const ParamTable<MinmaxSettings>& minmaxParams();

class MinmaxTechnique final : public render::GlTechnique<MinmaxSettings> {
public:
    MinmaxTechnique();

    // Stepping the mipmap level by level: mip_levels = 1 .. log2(columns) - 1, then 0 (all levels).
    // Stepping the picked pixel's walk node by node: trace_steps = 1 .. 2 columns - 2, then 0 (the whole
    // walk), a walk visiting each of the row's 2 columns - 1 nodes at most; each run says how many nodes
    // the picked walk has (FrameOutput::substepCounts), and stepping ends there (about 80 on grate).
    std::vector<double> substepValues(int stage, const Settings& s) const override;

    // Shadow-map size, slice count and rank (issue 9), cheapest first: the analytic integrand at growing
    // shadow maps and slice counts (with the spot pieces and brute-force samples that go with them), then
    // the SVD integrand at growing rank. Fewer spot pieces blur a cookie and fewer samples near the
    // epipole cost accuracy where the light is in view. The quick sweep keeps two points, a coarse grid
    // and rank 8 on a 1024 map: its share of `airlight report --quick` stays near 40 s on two cores.
    std::vector<QualitySetting> qualitySweep(bool quick) const override;
    // Area lights: more VPLs, each count also at fewer of vpl_samples, the march of each VPL (SceneViewPasses::areaSampleSweep).
    std::vector<QualitySetting> areaLightSweep(bool quick) const override {
        return render::SceneViewPasses::areaSampleSweep(quick, 16, "vpl_samples", 16);
    }
    std::vector<StabilisingOption> stabilisingOptions(const scene::Scene& scene) const override;

    // The accurate end of the knobs: every camera ray within 1/8 pixel of a slice (slice_oversampling 4),
    // 128 spot pieces, 1024 near-epipole samples; the default integrand=auto (analytic on the cases whose
    // integrand the SVD's tables do not hold: tests/gl/minmax_integrand_test.cpp). Keeps the 21 cases at
    // 33x25 within seconds.
    // Chen et al. 2011: the rank-4 SVD integrand with prefix sums, one slice per half pixel (k = 1), each
    // ray reading its nearest slice's table.
    Settings paperSettings() const override {
        return {{"integrand", 1.0}, {"rank", 4.0}, {"slice_oversampling", 1.0}, {"slice_blend", 0.0}};
    }
    Settings stiffSettings() const override {
        return {{"slice_oversampling", 4.0}, {"spot_pieces", 128.0}, {"march_samples", 1024.0}};
    }

    // Measured by `airlight report --suite stiff` at 33x25 (table in README.md); bounds about twice the
    // worst case of each class.
    std::optional<StiffBound> stiffBound(const std::string& caseClass) const override;

    Plan plan(const scene::Scene& scene, const Settings& settings) const override;

    FrameOutput run(const FrameInput& input) override;

    // The pixel's epipolar slice (first epipolar light) as a row of the rectified map, its view and the
    // min-max tree; after the traversal also the columns the camera ray covers (gamma from the eye up to
    // its end column cEnd, the GPU's own value) as a segment on that row.
    // In every light's shadow map: the eye ray and its lit/shadow changes (render/shadow_map_markers.h).
    std::vector<ViewMarker> markersFor(glm::ivec2 pixel, const std::string& id) const override;

private:
    static int levelCount(const LightWork& w) { return std::bit_width(unsigned(w.setup.frame.columns)) - 1; }

    // Epipolar setup of every spot, directional and point light with a shadow map; others are marched.
    // `notes` gets one line per light whose slices leave some camera ray farther from its slice than the
    // settings promise (the slice cap reached, or a fixed count too low for the image).
    void prepareLights(const scene::Scene& scene, const FrameInput& input, std::vector<std::string>& notes);

    void sliceGapNote(const scene::Scene& scene, int light, const FrameInput& input, const minmax::Setup& setup,
                      std::vector<std::string>& notes) const;

    void setFrameUniforms(const gl::Program& p, const minmax::EpipolarFrame<float>& f) const;

    static int sliceCount(const LightWork& w) { return w.setup.frame.slices; }

    // Point light: each row's largest gamma over its pixels' rays at their distance d (gamma_range.comp).
    void measureRowGamma(LightWork& w, const scene::Scene& scene, const FrameInput& input);

    void rectify(LightWork& w);

    // integrand=svd: factorise I(beta, gamma) sin(beta) for this light's frame over the screen's betas, then
    // fill the prefix-sum tables of Gamma_i T (one row per slice for a spot, one shared row otherwise).
    void prefixSums(LightWork& w, const scene::Scene& scene);

    // Leaves, then levels L-1 .. 0 (one pass each); `wanted` > 0 stops after that many level passes.
    void buildTree(LightWork& w, int wanted);

    void allocateTargets(int width, int height);

    const gl::Program& traverseProgram(const Plan& plan);

    // One light (index into GpuLights): the epipolar walk (work != nullptr) or the brute-force march.
    void traverse(const gl::Program& program, const scene::Scene& scene, const FrameInput& input,
                  const LightWork* work, int gpuIndex, bool writeCoords);

    // ---- intermediates ----

    // Row `row` of a float texture (GL row index) as `channels` floats per texel.
    static std::vector<float> readRow(const gl::Texture& t, int row, int channels);

    // The slice row of the picked pixel for the first epipolar light (computed on the CPU like the shader).
    int pickedRow(const FrameInput& input) const;

    void publishRectified(FrameOutput& out, const FrameInput& input) const;

    // Singular values, B_i(beta) and Gamma_i(gamma) as plots, the rank-N reconstruction error and the
    // prefix-sum tables of the first epipolar light.
    void publishLowRank(FrameOutput& out) const;

    // The gamma range of every row of the first point light, as a 1 x slices image (image row i = slice i).
    void publishRowGamma(FrameOutput& out) const;

    // Row `row` of a light's trees as nodes (x = min, y = max).
    static std::vector<glm::vec2> readTreeRow(const gl::Texture& tree, int row);

    void publishTree(FrameOutput& out, const FrameInput& input) const;

    void publishTraverse(FrameOutput& out, const FrameInput& input);

    std::vector<LightWork> mWork;
    std::vector<int> mBruteLights;  // GpuLights indices marched by brute force
    bool mLog2Prefix = false;       // the plan's PREFIX_LOG2_PASSES
    bool mSvd = false;              // the run's integrand (the plan's INTEGRAND_SVD: integrand=auto decides there)
    bool mFarRays = false;          // the traverse program's FAR_RAYS (its far-camera uniforms are set)
    minmax::IntegrandChooser mIntegrandChooser;  // integrand=auto, for plan()
    gl::Program mRectify, mRectifyPoint, mGammaRange, mMipmap, mTraverse;
    std::map<int, gl::Program> mPrefix;  // by variant: 1 point light (EPIPOLAR_POINT), 2 LOG2_PASSES, rank << 2
    std::string mProgramKey;
    gl::Texture mAirlight, mVisited, mNearMask, mRayCoords;
    // The rows of the rectified map its picture shows (publishRectified), kept while its size holds.
    mutable gl::Texture mRectifiedRows;
    // What markersFor needs of the last run.
    scene::Camera mMarkCamera;
    glm::ivec2 mMarkSize{0};
    bool mMarkTraversed = false;
};

}  // namespace viz::minmax_detail
