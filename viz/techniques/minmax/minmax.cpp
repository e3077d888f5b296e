#include "techniques/minmax/minmax.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstdio>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "core/error.h"
#include "debug/permutations.h"
#include "gl/buffer.h"
#include "gl/program.h"
#include "gl/stage_clock.h"
#include "gl/texture.h"
#include "render/host_device.h"
#include "render/intermediates.h"
#include "render/light_culling.h"
#include "render/scene_view.h"
#include "render/shadow_map_markers.h"
#include "scene/camera.h"
#include "techniques/minmax/epipolar_setup.h"
#include "techniques/minmax/low_rank.h"
#include "techniques/minmax/views.h"

namespace viz {
namespace {

// The two values S stores that are not an occluder's beta.
std::vector<Sentinel> outsideAndUnblocked() {
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
// Stepping the picked pixel's walk node by node: sub-steps 1 .. 63 show its first k nodes, the last the
// whole walk (trace_steps = 0); walks are a few dozen nodes on the built-in scenes.
constexpr int kTraceSubsteps = 64;
constexpr const char* kNearMask = "minmax.near_epipole";
constexpr const char* kRayCoords = "minmax.ray_coords";
constexpr const char* kSingularValues = "minmax.singular_values";
constexpr const char* kBasis = "minmax.basis";
constexpr const char* kPrefixSums = "minmax.prefix_sums";
constexpr const char* kReconstructionError = "minmax.reconstruction_error";
constexpr const char* kRowGamma = "minmax.row_gamma";

enum StageIndex {
    kShadowMapsIndex = 0,
    kSurfaceIndex = 1,
    kRectifyIndex = 2,
    kMipmapIndex = 3,
    kTraverseIndex = 4,
    kComposeIndex = 5
};

// Shader permutations of minmax/*.comp: feature -> {define when enabled, define when disabled}.
const PermutationTable kDefines = {
    {"NEAR_EPIPOLE", {"NEAR_EPIPOLE", nullptr}},
    {"EPIPOLAR_POINT", {"EPIPOLAR_POINT", nullptr}},
    {"INTEGRAND_SVD", {"INTEGRAND_SVD", nullptr}},
    {"SPOT", {nullptr, "LIGHTS_NO_SPOT"}},
    {"COOKIE", {nullptr, "LIGHTS_NO_COOKIE"}},
    {"SHADOW_MAPS_CUBE", {nullptr, "SHADOW_NO_CUBE"}},
    {"SHADOW_MAPS_2D", {nullptr, "SHADOW_NO_2D"}},
};

// Lights with an epipolar path: spot and directional (2D maps), point (cube maps, per-row gamma ranges).
// Area lights (VPLs) are marched.
bool epipolarLight(const scene::Light& l) {
    return l.type == scene::LightType::Spot || l.type == scene::LightType::Directional ||
           l.type == scene::LightType::Point;
}

// Everything one epipolar light needs between the stages.
struct LightWork {
    int gpuIndex = 0;  // into GpuLights::lights()
    minmax::Setup setup;
    // Point light: the gamma range of each row, [0, hi_i], one float per row stored as its uint bits
    // (gamma_range.comp); read back only to publish minmax.row_gamma.
    gl::Buffer rowGamma;
    bool point() const { return setup.frame.kind == LightKind::Point; }
    gl::Texture rectified;  // r32f, columns x slices
    gl::Texture tree;       // rg32f, 2 columns x slices (Ahnentafel rows)
    int levelsBuilt = 0;
    // integrand=svd: the rank-N factorisation and the prefix sums of Gamma_i T (prefix.comp).
    minmax::LowRank lowRank;
    gl::Texture prefix;  // rgba32f array: (texels + 1) x rows x ceil(3 N / 4) layers
    int prefixRows = 0;
};

class MinmaxTechnique final : public Technique {
public:
    MinmaxTechnique() {
        mParams = {
            {"slices", "epipolar slices (rows of the rectified map); 0: automatic, every ray within 1/(2k) pixel "
                       "of a slice (k = slice_oversampling) up to 16384 slices; past that the run notes the gap",
             0, 0, minmax::kMaxSlices, true},
            {"slice_oversampling", "automatic slices: k puts every camera ray within 1/(2k) pixel of a slice", 2, 1,
             64, true},
            {"columns", "gamma texels per slice (rounded up to a power of two); 0: the shadow map's size", 0, 0,
             minmax::kMaxColumns, true},
            {"integrand", "analytic: the segment integral per lit run (closed form for suns, Gauss-Legendre panels for "
                          "point and spot lights); svd: rank-N approximation with prefix sums", 0, 0,
             1, true, {"analytic", "svd"}},
            {"rank", "singular vectors kept by integrand=svd", 4, 1, 8, true},
            {"texture_columns", "integrand=svd: gamma texels of the prefix-sum tables of Gamma_i T (the light "
                                "texture's own resolution, lower than the shadow map's)", 256, 16, 4096, true},
            {"traversal", "tree: min-max mipmap walk (Figure 5); linear: scan every texel of the row", 0, 0, 1, true,
             {"tree", "linear"}},
            {"point_lights", "epipolar: point lights rectified from their cube maps; march: marched per pixel "
                             "(the fallback before point lights had an epipolar path, for comparison)", 0, 0, 1, true,
             {"epipolar", "march"}},
            // Each piece is one pointSegment call; llvmpipe stops every loop of a shader invocation after
            // 65535 iterations in total (all loops together), which more pieces would exceed (README).
            {"spot_pieces", "spot lights: pieces across the cone, each with its own A_spot * cookie", 64, 1, 128,
             true},
            {"epipole_radius", "pixels around the (anti-)epipole marched by brute force", 4, 0, 1000, false},
            {"march_samples", "brute-force samples per ray (near the epipole, and lights without epipolar path)",
             512, 1, 16384, true},
            {"mip_levels", "mipmap passes to run (0: all); fewer stops the frame after the mipmap stage", 0, 0, 13,
             true},
            {"pick_x", "picked pixel (column, 0 = left) for the per-ray intermediates; -1: image centre", -1, -1,
             16384, true},
            {"pick_y", "picked pixel (row, 0 = top); -1: image centre", -1, -1, 16384, true},
            {"trace_steps", "picked pixel's walk: show its first k nodes (0: all); steps the traversal node by node",
             0, 0, 100000, true},
        };
        for (ParamInfo& p : render::SceneViewPasses::params()) mParams.push_back(std::move(p));
        mParams.push_back(forceFeaturesParam());
        mStages = {
            render::SceneViewPasses::shadowStage("minmax"),
            render::SceneViewPasses::surfaceStage("minmax"),
            {kStageRectify, "Rectify", "shadow map -> S[alpha, gamma] = beta of the occluder on each light ray "
             "(point lights: each slice's gamma range first, then their cube map); integrand=svd: SVD of "
             "I(beta, gamma) and prefix sums of Gamma_i T per slice",
             {"slices", "slice_oversampling", "columns", "integrand", "rank", "texture_columns", "point_lights"},
             {kRectified, kRectifiedView, kRowGamma, kSingularValues, kBasis, kPrefixSums, kReconstructionError}, 1},
            {kStageMipmap, "Min-max mipmap", "per row of S: a 1D min-max tree, one pass per level",
             {"mip_levels"}, {kTree, kPyramid}, 1, "mip_levels"},
            {kStageTraverse, "Traverse", "per pixel: walk the slice's tree, integrate the lit segments",
             {"integrand", "rank", "traversal", "point_lights", "spot_pieces", "epipole_radius", "march_samples",
              "pick_x", "pick_y", "trace_steps", "force_features"},
             {kAirlight, kVisited, kNearMask, kRayCoords, kTrace}, kTraceSubsteps, "trace_steps"},
            render::SceneViewPasses::composeStage("minmax"),
        };
    }

    // Stepping the mipmap level by level: mip_levels = 1 .. log2(columns) - 1, then 0 (all levels);
    // the traversal default (trace_steps 1 .. kTraceSubsteps - 1, then 0 = the whole walk) comes from
    // StageInfo.
    std::vector<double> substepValues(int stage, const Settings& s) const override {
        if (stage != kMipmapIndex) return Technique::substepValues(stage, s);
        const int wanted = int(s.at("columns")) > 0 ? int(s.at("columns")) : int(s.at("shadow_map"));
        const int columns = minmax::rectifiedColumns(wanted);
        const int levels = std::bit_width(unsigned(columns)) - 1;
        std::vector<double> values;
        for (int k = 1; k < levels; ++k) values.push_back(double(k));
        values.push_back(0.0);
        return values;
    }

    std::string id() const override { return "minmax"; }
    std::string description() const override {
        return "1D min-max mipmaps in epipolar space (Chen, Baran, Durand, Jarosz 2011)";
    }
    const std::vector<StageInfo>& stages() const override { return mStages; }
    const std::vector<ParamInfo>& params() const override { return mParams; }
    bool needsGl() const override { return true; }

    // Shadow-map size, slice count and rank (issue 9), cheapest first: the analytic integrand at growing
    // shadow maps and slice counts (with the spot pieces and brute-force samples that go with them), then
    // the SVD integrand at growing rank. Fewer spot pieces blur a cookie and fewer samples near the
    // epipole cost accuracy where the light is in view. The quick sweep keeps two points, a coarse grid
    // and rank 8 on a 1024 map: its share of `airlight report --quick` stays near 40 s on two cores.
    std::vector<QualitySetting> qualitySweep(bool quick) const override {
        std::vector<QualitySetting> sweep;
        auto grid = [&](int map, int slices, int pieces, int samples) {
            sweep.push_back({"map=" + std::to_string(map) + " slices=" + (slices ? std::to_string(slices) : "auto"),
                             {{"shadow_map", double(map)}, {"slices", double(slices)},
                              {"spot_pieces", double(pieces)}, {"march_samples", double(samples)}}});
        };
        auto svd = [&](int rank, int samples) {
            sweep.push_back({"svd rank=" + std::to_string(rank),
                             {{"integrand", 1.0}, {"rank", double(rank)}, {"shadow_map", 1024.0},
                              {"march_samples", double(samples)}}});
        };
        if (quick) {
            grid(256, 64, 32, 128);
            svd(8, 128);
            return sweep;
        }
        grid(256, 64, 32, 128);
        grid(512, 256, 32, 256);
        grid(1024, 512, 64, 256);
        grid(1024, 0, 64, 512);
        grid(2048, 0, 64, 512);
        grid(4096, 0, 128, 1024);
        for (int rank : {1, 2, 4, 8}) svd(rank, 512);
        return sweep;
    }

    // The accurate end of the knobs: every camera ray within 1/8 pixel of a slice (slice_oversampling 4),
    // 128 spot pieces, 1024 near-epipole samples; the analytic integrand (the SVD's own error is measured
    // by the quality sweep). Keeps the 21 cases at 33x25 within seconds.
    // Chen et al. 2011: the rank-4 SVD integrand with prefix sums, one slice per half pixel (k = 1).
    Settings paperSettings() const override {
        return {{"integrand", 1.0}, {"rank", 4.0}, {"slice_oversampling", 1.0}};
    }
    Settings stiffSettings() const override {
        return {{"slice_oversampling", 4.0}, {"spot_pieces", 128.0}, {"march_samples", 1024.0}};
    }

    // Measured by `airlight report --suite stiff` at 33x25 (table in README.md); bounds about twice the
    // worst case of each class.
    std::optional<StiffBound> stiffBound(const std::string& caseClass) const override {
        static const std::map<std::string, StiffBound> kBounds = {
            {"medium", {0.02, "closed-form segments are exact in sigma_t; thin media show only the shadow-map and "
                              "slice sampling"}},
            {"intensity", {0.015, "linear in the intensity: float S, trees and segments carry no absolute scale"}},
            {"scale", {0.015, "eye-relative frame, angles alpha, beta, gamma and distance-valued maps are scale-free"}},
            {"singular-ray", {0.03, "the light's own pixel and the rays within epipole_radius px are marched with the "
                                    "closed form per interval; elsewhere point lights take the epipolar path, and the "
                                    "grate's bars run parallel to the view axis, so their shadow edges are epipolar "
                                    "planes: four pixels whose rays lie within 1/8 px of such an edge take the slice "
                                    "on its other side (0.0148, was 0.00034 marched)"}},
            {"near-light", {1e-4, "the light's own pixel is marched with the closed form per interval, "
                                  "which keeps the ray's own distance from the light (9.3e-7)"}},
            {"epipole", {0.045, "rays within epipole_radius px of an epipole, and rays on the epipolar axis, are "
                               "marched; grazing sun is the worst (shadow-map bias across long light rays)"}},
            {"camera-placement", {0.008, "the frame is eye-relative; a closed box gives d small and S above beta"}},
            {"geometry", {0.05, "slice quantisation: a shadow edge along an epipolar plane is placed to the nearest "
                                "slice (centre line exact); slivers the rasteriser drops"}},
            {"leak", {0.045, "the rectified map reads the reconstructed depth but keeps the surface bias (its gamma "
                      "columns need it): a band under the grazing ceiling stays lit (0.019 measured)"}},
            {"depth-range", {0.022, "S stores angles beta, not depths: the 1e6 range costs no precision"}},
            {"phase", {0.04, "the HG lobe is inside the segment integral of each lit run; g = +-0.99 is the worst"}},
        };
        const auto it = kBounds.find(caseClass);
        return it == kBounds.end() ? std::nullopt : std::optional<StiffBound>(it->second);
    }

    Plan plan(const scene::Scene& scene, const Settings& settings) const override {
        Plan p;
        for (const StageInfo& s : mStages) p.stages.push_back({s.id, true, ""});
        const bool marchPoints = settings.at("point_lights") == 1.0;
        const auto epipolar = [&](const scene::Light& l) {
            return epipolarLight(l) && !(marchPoints && l.type == scene::LightType::Point);
        };
        const bool anyEpipolar = std::any_of(scene.lights.begin(), scene.lights.end(), epipolar);
        if (scene.medium.sigma_s == 0.0) {
            for (int i : {kRectifyIndex, kMipmapIndex, kTraverseIndex}) {
                p.stages[std::size_t(i)].runs = false;
                p.stages[std::size_t(i)].why = "sigma_s = 0: the medium scatters nothing, L_air = 0";
            }
        } else if (!anyEpipolar) {
            for (int i : {kRectifyIndex, kMipmapIndex}) {
                p.stages[std::size_t(i)].runs = false;
                p.stages[std::size_t(i)].why = "no spot or directional light and no point light: nothing to "
                                               "rectify (area lights' VPLs are marched by brute force in the "
                                               "traverse stage)";
            }
        }
        const bool svd = settings.at("integrand") == 1.0;
        p.features.push_back({"INTEGRAND_SVD", svd,
                              svd ? "rank-" + std::to_string(int(settings.at("rank"))) +
                                        " SVD of I(beta, gamma) with prefix sums of Gamma_i"
                                  : "integrand=analytic: closed form (airlight.glsl pointSegment / "
                                    "directionalSegment) per lit segment"});
        if (svd) {
            const bool spot = render::hasLightOfType(scene, scene::LightType::Spot);
            const bool sun = render::hasLightOfType(scene, scene::LightType::Directional);
            p.features.push_back(
                {"TEXTURED_PREFIX_SUMS", spot,
                 spot ? "spot: T = colour * I * A_spot * cookie varies with alpha: prefix sums of Gamma_i T per slice"
                      : "no spot light: T is the constant colour * I, one prefix-sum row shared by every slice"});
            if (sun && spot) p.features.back().why += "; directional lights share one row";
            if (render::hasLightOfType(scene, scene::LightType::Point) && !marchPoints)
                p.features.back().why += "; point lights: T is constant, but each slice has its own gamma range, "
                                         "so each has its own table too";
        }
        const bool linear = settings.at("traversal") == 1.0;
        p.features.push_back({"TREE_TRAVERSAL", !linear,
                              linear ? "traversal=linear: every texel of the row up to the ray's end (run-time branch)"
                                     : "stackless walk of Figure 5, climb <= 1 level, delayed update (run-time branch)"});
        // Near-epipole marching: only when an epipolar light's epipole or anti-epipole is on or near the
        // screen (within a quarter of the screen beyond its edges).
        bool near = false;
        std::string nearWhy = "no spot, directional or point light";
        for (const scene::Light& l : scene.lights) {
            if (!epipolar(l)) continue;
            const glm::dvec3 axis = minmax::epipolarAxis(l, scene.camera.position);
            if (minmax::epipoleNearScreen(scene.camera, axis, 0.25)) {
                near = true;
                nearWhy = "epipole of light '" + l.name + "' on or near the screen: brute-force march within " +
                          std::to_string(int(settings.at("epipole_radius"))) + " px of it";
            } else if (!near) {
                nearWhy = "epipole far off screen (more than a quarter screen beyond every edge): no pixel is "
                          "near it";
            }
        }
        if (settings.at("epipole_radius") <= 0.0 && near) {
            near = false;
            nearWhy = "epipole_radius = 0";
        }
        p.features.push_back({"NEAR_EPIPOLE", near, nearWhy});
        const bool hasSpot = render::hasLightOfType(scene, scene::LightType::Spot);
        const bool hasCookie = std::any_of(scene.lights.begin(), scene.lights.end(),
                                           [](const scene::Light& l) { return l.cookie >= 0; });
        p.features.push_back({"SPOT", hasSpot,
                              hasSpot ? "spot A_spot per gamma piece" : "no spot light in the scene"});
        p.features.push_back({"COOKIE", hasCookie,
                              hasCookie ? "cookie texture sampled per gamma piece" : "no light has a cookie"});
        const bool hasPoint = render::hasLightOfType(scene, scene::LightType::Point);
        std::string pointWhy = "no point light in the scene";
        if (hasPoint && marchPoints) {
            pointWhy = "point_lights=march: point lights are marched per pixel";
        } else if (hasPoint) {
            const auto it = std::find_if(scene.lights.begin(), scene.lights.end(),
                                         [](const scene::Light& l) { return l.type == scene::LightType::Point; });
            pointWhy = "point light '" + it->name + "': rectified from its cube map, each slice over the gamma "
                       "range [0, gamma(beta, d)] its pixels' rays reach (gamma_range.comp)";
        }
        p.features.push_back({"EPIPOLAR_POINT", hasPoint && !marchPoints, pointWhy});
        // Area lights are integrated over their emitter as VPLs (cube maps of their own, a different light
        // position per VPL): marched per pixel.
        const bool area = render::hasLightOfType(scene, scene::LightType::Area);
        const bool brute = area || (hasPoint && marchPoints);
        std::string bruteWhy = "every light has an epipolar path (spot, directional, point)";
        if (area)
            bruteWhy = "area lights: each VPL (a cube-mapped point-like light of its own) is marched per pixel, not "
                       "rectified";
        if (hasPoint && marchPoints) bruteWhy = (area ? bruteWhy + "; " : std::string()) + pointWhy;
        p.features.push_back({"BRUTE_FORCE_LIGHTS", brute, bruteWhy});
        const bool cubes = render::hasLightOfType(scene, scene::LightType::Point) ||
                           render::hasLightOfType(scene, scene::LightType::Area);
        p.features.push_back({"SHADOW_MAPS_CUBE", cubes,
                              cubes ? "point lights / VPLs need omnidirectional maps" : "no point or area light"});
        const bool maps2D = hasSpot || render::hasLightOfType(scene, scene::LightType::Directional);
        p.features.push_back({"SHADOW_MAPS_2D", maps2D, maps2D ? "spot / directional lights" : "no spot or directional light"});
        render::planCulledLights(scene, p);
        // force_features=1: every stage runs and every permutation pruned by the scene is compiled in (the
        // traverse shader then carries spot, cookie, cube-map and near-epipole code the scene does not use).
        forcePlan(p, settings.at("force_features") != 0.0,
                  {"NEAR_EPIPOLE", "EPIPOLAR_POINT", "SPOT", "COOKIE", "SHADOW_MAPS_CUBE", "SHADOW_MAPS_2D"});
        annotatePermutations(p, kDefines);
        return p;
    }

    FrameOutput run(const FrameInput& input) override {
        const scene::Scene& scene = *input.scene;
        const Settings& s = input.settings;
        mMarkCamera = scene.camera;
        mMarkSize = {input.width, input.height};
        FrameOutput out;
        out.plan = plan(scene, s);
        out.timing.clock = gl::StageClock::method();
        const int stop = input.stopAfterStage < 0 ? kComposeIndex : input.stopAfterStage;
        gl::StageClock clock;

        // ---- shadow maps and camera view ----
        mReuse.begin(input, out);
        if (!mReuse.substepOnly(kTraverseIndex)) mMarkTraversed = false;
        if (!mView.runSharedStages(input, stop, mStages, "minmax", out, mReuse)) return out;

        // The plan decides (sigma_s = 0 skips the epipolar stages unless force_features=1 runs them).
        const auto runs = [&](int stage) { return out.plan.stages[std::size_t(stage)].runs; };
        // ---- rectify ----
        const bool svd = s.at("integrand") == 1.0;
        if (mReuse.carries(kRectifyIndex)) {
            mReuse.carry(kRectifyIndex, out);
        } else {
            clock.begin();
            prepareLights(scene, input, out.notes);
            if (runs(kRectifyIndex)) {
                for (LightWork& w : mWork) {
                    if (w.point()) measureRowGamma(w, scene, input);
                    rectify(w);
                    if (svd) prefixSums(w, scene, input);
                }
            }
            out.timing.stages.push_back({kStageRectify, clock.endMilliseconds()});
            publishRectified(out, input);
            if (runs(kRectifyIndex)) publishRowGamma(out);
            if (svd && runs(kRectifyIndex)) publishLowRank(out);
            mReuse.ran(kRectifyIndex, out);
        }
        out.lastStageRun = kRectifyIndex;
        if (stop == kRectifyIndex) return out;

        // ---- mipmap ----
        bool complete = true;
        if (mReuse.carries(kMipmapIndex)) {
            mReuse.carry(kMipmapIndex, out);
            for (const LightWork& w : mWork) complete = complete && (!runs(kMipmapIndex) || w.levelsBuilt == levelCount(w));
        } else {
            clock.begin();
            const int wantedLevels = int(substepLimit(input, kMipmapIndex));
            if (runs(kMipmapIndex)) {
                for (LightWork& w : mWork) {
                    buildTree(w, wantedLevels);
                    complete = complete && w.levelsBuilt == levelCount(w);
                }
            }
            out.timing.stages.push_back({kStageMipmap, clock.endMilliseconds()});
            publishTree(out, input);
            mReuse.ran(kMipmapIndex, out);
        }
        out.lastStageRun = kMipmapIndex;
        if (stop == kMipmapIndex || !complete) return out;

        // ---- traverse ----
        // Stepping the picked pixel's walk (the cursor's sub-step alone changed): the traversal's images
        // stand; only the walk's view is drawn again.
        if (!mReuse.substepOnly(kTraverseIndex)) {
            clock.begin();
            allocateTargets(input.width, input.height);
            mAirlight.clear(glm::vec4(0.0f));
            mVisited.clear(glm::vec4(0.0f));
            mNearMask.clear(glm::vec4(0.0f));
            mRayCoords.clear(glm::vec4(0.0f));
            if (runs(kTraverseIndex)) {
                const gl::Program& program = traverseProgram(out.plan);
                for (std::size_t i = 0; i < mWork.size(); ++i)
                    traverse(program, scene, input, &mWork[i], mWork[i].gpuIndex, i == 0);
                for (int li : mBruteLights) traverse(program, scene, input, nullptr, li, false);
            }
            out.timing.stages.push_back({kStageTraverse, clock.endMilliseconds()});
            mMarkTraversed = runs(kTraverseIndex) && !mWork.empty();
        } else {
            clock.begin();
        }
        publishTraverse(out, input);
        if (mReuse.substepOnly(kTraverseIndex)) out.timing.stages.push_back({kStageTraverse, clock.endMilliseconds()});
        out.airlight = render::readRgb(mAirlight);
        mReuse.ran(kTraverseIndex, out);
        out.lastStageRun = kTraverseIndex;
        if (stop == kTraverseIndex) return out;

        clock.begin();
        out.final = mView.compose(scene, mAirlight, out.intermediates, "minmax");
        out.timing.stages.push_back({mStages[kComposeIndex].id, clock.endMilliseconds()});
        out.lastStageRun = kComposeIndex;
        return out;
    }

    // The pixel's epipolar slice (first epipolar light) as a row of the rectified map, its view and the
    // min-max tree; after the traversal also the columns the camera ray covers (gamma from the eye up to
    // its end column cEnd, the GPU's own value) as a segment on that row.
    // In every light's shadow map: the eye ray and its lit/shadow changes (render/shadow_map_markers.h).
    std::vector<ViewMarker> markersFor(glm::ivec2 pixel, const std::string& id) const override {
        if (render::shadowMapIndexOf(id, "minmax") >= 0) return mView.shadowMapMarkers(pixel, id, "minmax");
        const bool rectified = id == kRectified || id == kRectifiedView;
        if (mWork.empty() || (!rectified && id != kTree)) return {};
        if (pixel.x < 0 || pixel.y < 0 || pixel.x >= mMarkSize.x || pixel.y >= mMarkSize.y) return {};
        const auto f = minmax::toFloat(mWork.front().setup.frame);
        const glm::vec3 w = glm::vec3(scene::pixelRay(mMarkCamera, mMarkSize.x, mMarkSize.y, pixel.x, pixel.y));
        const int row = minmax::sliceRow(f, minmax::alphaOf(f, w));
        const float v = (float(row) + 0.5f) / float(std::max(1, f.slices));
        // Tree texels: leaves at columns .. 2 columns - 1 (Ahnentafel order) of a row 2 columns wide.
        const float x0 = rectified ? 0.0f : 0.5f, width = rectified ? 1.0f : 0.5f;
        const std::string label = "slice " + std::to_string(row);
        std::vector<ViewMarker> marks = {{{0.0f, v}, {1.0f, v}, label}};
        if (mMarkTraversed && mRayCoords && mRayCoords.size().x == mMarkSize.x && mRayCoords.size().y == mMarkSize.y) {
            float coords[4] = {0.0f, 0.0f, 0.0f, 0.0f}, near = 0.0f;
            const int glRow = mMarkSize.y - 1 - pixel.y;
            glGetTextureSubImage(mRayCoords.id(), 0, pixel.x, glRow, 0, 1, 1, 1, GL_RGBA, GL_FLOAT, sizeof coords, coords);
            glGetTextureSubImage(mNearMask.id(), 0, pixel.x, glRow, 0, 1, 1, 1, GL_RED, GL_FLOAT, sizeof near, &near);
            // Near the epipole the pixel is marched by brute force: there is no walk along the row.
            if (near < 0.5f && std::isfinite(coords[2])) {
                const float end = std::clamp(coords[2] / float(std::max(1, f.columns)), 0.0f, 1.0f);
                marks.push_back({{x0, v}, {x0 + width * end, v}, "ray: columns 0.." + std::to_string(int(coords[2]))});
            }
        }
        return marks;
    }

private:
    static int levelCount(const LightWork& w) { return std::bit_width(unsigned(w.setup.frame.columns)) - 1; }

    glm::ivec2 pickedPixel(const FrameInput& input) const {
        int x = int(input.settings.at("pick_x")), y = int(input.settings.at("pick_y"));
        if (x < 0) x = input.width / 2;
        if (y < 0) y = input.height / 2;
        return {std::min(x, input.width - 1), std::min(y, input.height - 1)};
    }

    // Epipolar setup of every spot, directional and point light with a shadow map; others are marched.
    // `notes` gets one line per light whose slices leave some camera ray farther from its slice than the
    // settings promise (the slice cap reached, or a fixed count too low for the image).
    void prepareLights(const scene::Scene& scene, const FrameInput& input, std::vector<std::string>& notes) {
        const auto& lights = mView.lights().lights();
        const int columns = int(input.settings.at("columns")) > 0 ? int(input.settings.at("columns"))
                                                                    : int(input.settings.at("shadow_map"));
        std::vector<LightWork> work;
        mBruteLights.clear();
        for (int i = 0; i < int(lights.size()); ++i) {
            const auto& L = lights[std::size_t(i)];
            const bool point = L.info.x == render::hd::kLightPoint && input.settings.at("point_lights") == 0.0;
            const bool epipolar = (L.info.x == render::hd::kLightSpot || L.info.x == render::hd::kLightDirectional ||
                                   point) &&
                                  L.info.z >= 0;
            if (!epipolar) {
                mBruteLights.push_back(i);
                continue;
            }
            LightWork w;
            w.gpuIndex = i;
            w.setup = minmax::setupLight({.light = &L, .camera = &scene.camera, .width = input.width,
                                          .height = input.height, .slices = int(input.settings.at("slices")),
                                          .columns = columns,
                                          .oversampling = int(input.settings.at("slice_oversampling"))});
            sliceGapNote(scene, L.info.w, input, w.setup, notes);
            // Reuse the previous textures when the sizes agree.
            const std::size_t k = work.size();
            if (k < mWork.size() && mWork[k].rectified &&
                mWork[k].rectified.size() == glm::ivec3(w.setup.frame.columns, w.setup.frame.slices, 1)) {
                w.rectified = std::move(mWork[k].rectified);
                w.tree = std::move(mWork[k].tree);
                w.rowGamma = std::move(mWork[k].rowGamma);
            } else {
                const int c = w.setup.frame.columns, r = w.setup.frame.slices;
                w.rectified = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_R32F, .size = {c, r, 1},
                                                   .levels = 1, .label = kRectified});
                w.tree = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_RG32F, .size = {2 * c, r, 1},
                                              .levels = 1, .label = kTree});
                w.rectified.setFilter(GL_NEAREST, GL_NEAREST);
                w.tree.setFilter(GL_NEAREST, GL_NEAREST);
            }
            const std::size_t rowGammaBytes = sizeof(std::uint32_t) * std::size_t(sliceCount(w));
            if (w.point() && (!w.rowGamma || w.rowGamma.bytes() != rowGammaBytes))
                w.rowGamma = gl::Buffer::create({.bytes = rowGammaBytes, .label = kRowGamma});
            work.push_back(std::move(w));
        }
        mWork = std::move(work);
    }

    static void sliceGapNote(const scene::Scene& scene, int light, const FrameInput& input, const minmax::Setup& setup,
                             std::vector<std::string>& notes) {
        const int fixed = int(input.settings.at("slices"));
        const int k = std::max(1, int(input.settings.at("slice_oversampling")));
        const double promised = fixed > 0 ? 1.0 : 1.0 / k;  // largest gap the setting stands for (pixels)
        if (setup.maxSliceGap <= promised * (1.0 + 1e-6)) return;
        const std::string name = light >= 0 && light < int(scene.lights.size()) ? scene.lights[std::size_t(light)].name
                                                                                  : "light";
        const std::string why = fixed > 0 ? "slices=" + std::to_string(fixed) + " is too few for this image"
                                          : "the cap of " + std::to_string(minmax::kMaxSlices) +
                                                " slices is reached (slice_oversampling " + std::to_string(k) +
                                                " asks for " + std::to_string(int(std::ceil(setup.maxSliceGap / promised *
                                                                                             setup.frame.slices))) + ")";
        char figure[160];
        std::snprintf(figure, sizeof figure, "%.2f px apart, so a ray may take a slice %.2f px away (promised %.2f)",
                      setup.maxSliceGap, 0.5 * setup.maxSliceGap, 0.5 * promised);
        notes.push_back("minmax, " + name + ": " + std::to_string(setup.frame.slices) + " slices at " +
                        std::to_string(input.width) + "x" + std::to_string(input.height) + " are up to " + figure +
                        ": shadow edges may shift by that much; " + why);
    }

    void setFrameUniforms(const gl::Program& p, const minmax::EpipolarFrame<float>& f) const {
        p.set("uKind", int(f.kind));
        p.set("uAxis", f.axis);
        p.set("uU", f.u);
        p.set("uV", f.v);
        p.set("uLightDistance", f.lightDistance);
        p.set("uSlices", f.slices);
        p.set("uColumns", f.columns);
        p.set("uWrap", f.wrap);
        p.set("uAlphaLo", f.alphaLo);
        p.set("uAlphaSpacing", f.alphaSpacing);
        p.set("uGammaLo", f.gammaLo);
        p.set("uGammaHi", f.gammaHi);
    }

    static int sliceCount(const LightWork& w) { return w.setup.frame.slices; }

    void setCameraUniforms(const gl::Program& p, const scene::Camera& cam, int width, int height) const {
        p.set("uSize", glm::ivec2(width, height));
        p.set("uForward", glm::vec3(cam.forward));
        p.set("uRight", glm::vec3(scene::cameraRight(cam)));
        p.set("uUp", glm::vec3(cam.up));
        p.set("uTanHalf", float(std::tan(cam.yfov * 0.5)));
        p.set("uAspect", float(scene::aspectOf(cam, width, height)));
    }

    // Point light: each row's largest gamma over its pixels' rays at their distance d (gamma_range.comp).
    void measureRowGamma(LightWork& w, const scene::Scene& scene, const FrameInput& input) {
        if (!mGammaRange)
            mGammaRange = gl::Program::compile({.stages = {"minmax/gamma_range.comp"},
                                                .defines = {{"EPIPOLAR_POINT", "1"}},
                                                .label = "minmax.gamma_range"});
        w.rowGamma.clearZero();
        mGammaRange.use();
        setFrameUniforms(mGammaRange, minmax::toFloat(w.setup.frame));
        setCameraUniforms(mGammaRange, scene.camera, input.width, input.height);
        w.rowGamma.bindBase(GL_SHADER_STORAGE_BUFFER, render::hd::kFirstFreeSsboBinding);
        mView.surface().distance().bindUnit(render::hd::kFirstFreeTextureUnit);
        const glm::ivec3 groups = gl::groupCount({input.width, input.height, 1}, mGammaRange.workGroupSize());
        glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }

    void rectify(LightWork& w) {
        if (!mRectify) mRectify = gl::Program::compile({.stages = {"minmax/rectify.comp"}, .label = kStageRectify});
        if (w.point() && !mRectifyPoint)
            mRectifyPoint = gl::Program::compile({.stages = {"minmax/rectify.comp"},
                                                  .defines = {{"EPIPOLAR_POINT", "1"}},
                                                  .label = kStageRectify});
        const gl::Program& program = w.point() ? mRectifyPoint : mRectify;
        const auto f = minmax::toFloat(w.setup.frame);
        program.use();
        setFrameUniforms(program, f);
        program.set("uLight", w.gpuIndex);
        mView.lights().bind();
        mView.shadows().bind();
        if (w.point()) w.rowGamma.bindBase(GL_SHADER_STORAGE_BUFFER, render::hd::kFirstFreeSsboBinding);
        w.rectified.bindImage(0, GL_WRITE_ONLY);
        const glm::ivec3 groups = gl::groupCount({f.columns, f.slices, 1}, program.workGroupSize());
        glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    }

    // integrand=svd: factorise I(beta, gamma) sin(beta) for this light's frame over the screen's betas, then
    // fill the prefix-sum tables of Gamma_i T (one row per slice for a spot, one shared row otherwise).
    void prefixSums(LightWork& w, const scene::Scene& scene, const FrameInput& input) {
        const Settings& s = input.settings;
        const auto& f = w.setup.frame;
        const int rank = int(s.at("rank"));
        w.lowRank = minmax::lowRankIntegrand(f, w.setup.betaLo, w.setup.betaHi, scene.medium.sigma_s,
                                             scene.medium.sigma_t(), scene.medium.g, rank);
        const int texels = int(s.at("texture_columns"));
        // Spot: T varies with alpha; point: every row has its own gamma range. Both need a table per slice.
        const bool perRow = f.kind != LightKind::Directional;
        const int rows = perRow ? f.slices : 1;
        const int layers = (3 * rank + 3) / 4;
        if (!w.prefix || w.prefix.size() != glm::ivec3(texels + 1, rows, layers)) {
            w.prefix = gl::Texture::create({.target = GL_TEXTURE_2D_ARRAY, .format = GL_RGBA32F,
                                            .size = {texels + 1, rows, layers}, .levels = 1, .label = kPrefixSums});
            w.prefix.setFilter(GL_LINEAR, GL_LINEAR);
            w.prefix.setWrap(GL_CLAMP_TO_EDGE);
        }
        w.prefixRows = rows;
        if (!mPrefix) mPrefix = gl::Program::compile({.stages = {"minmax/prefix.comp"}, .label = "minmax.prefix"});
        if (w.point() && !mPrefixPoint)
            mPrefixPoint = gl::Program::compile({.stages = {"minmax/prefix.comp"},
                                                 .defines = {{"EPIPOLAR_POINT", "1"}},
                                                 .label = "minmax.prefix"});
        const gl::Program& program = w.point() ? mPrefixPoint : mPrefix;
        program.use();
        setFrameUniforms(program, minmax::toFloat(f));
        program.set("uLight", w.gpuIndex);
        program.set("uRows", rows);
        program.set("uTexels", texels);
        program.set("uRank", rank);
        program.set("uSharedRow", !perRow);
        glProgramUniform1fv(program.id(), program.location("uGammaBasis[0]"), GLsizei(w.lowRank.basisGamma.size()),
                            w.lowRank.basisGamma.data());
        mView.lights().bind();
        if (w.point()) w.rowGamma.bindBase(GL_SHADER_STORAGE_BUFFER, render::hd::kFirstFreeSsboBinding);
        w.prefix.bindImage(0, GL_WRITE_ONLY);
        const glm::ivec3 groups = gl::groupCount({rows, 1, 1}, program.workGroupSize());
        glDispatchCompute(GLuint(groups.x), 1, 1);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    }

    // Leaves, then levels L-1 .. 0 (one pass each); `wanted` > 0 stops after that many level passes.
    void buildTree(LightWork& w, int wanted) {
        if (!mMipmap) mMipmap = gl::Program::compile({.stages = {"minmax/mipmap.comp"}, .label = kStageMipmap});
        const auto& f = w.setup.frame;
        const int levels = levelCount(w);
        mMipmap.use();
        mMipmap.set("uLeaves", f.columns);
        mMipmap.set("uSlices", f.slices);
        w.rectified.bindImage(0, GL_READ_ONLY);
        w.tree.bindImage(1, GL_READ_WRITE);
        const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        w.tree.clear(GL_RGBA, GL_FLOAT, zero);
        auto pass = [&](int level, int count) {
            mMipmap.set("uLevel", level);
            const glm::ivec3 groups = gl::groupCount({count, f.slices, 1}, mMipmap.workGroupSize());
            glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
            glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
        };
        pass(-1, f.columns);
        w.levelsBuilt = 0;
        for (int level = levels - 1; level >= 0; --level) {
            if (wanted > 0 && w.levelsBuilt >= wanted) break;
            pass(level, 1 << level);
            ++w.levelsBuilt;
        }
    }

    void allocateTargets(int width, int height) {
        if (mAirlight && mAirlight.size().x == width && mAirlight.size().y == height) return;
        auto make = [&](GLenum format, const char* label) {
            return gl::Texture::create({.target = GL_TEXTURE_2D, .format = format, .size = {width, height, 1},
                                        .levels = 1, .label = label});
        };
        mAirlight = make(GL_RGBA32F, kAirlight);
        mVisited = make(GL_R32F, kVisited);
        mNearMask = make(GL_R32F, kNearMask);
        mRayCoords = make(GL_RGBA32F, kRayCoords);
    }

    const gl::Program& traverseProgram(const Plan& plan) {
        std::string key;
        const gl::ShaderDefines defines = permutationDefines(plan, kDefines, &key);
        if (key != mProgramKey || !mTraverse) {
            mTraverse = gl::Program::compile(
                {.stages = {"minmax/traverse.comp"}, .defines = defines, .label = kStageTraverse});
            mProgramKey = key;
        }
        return mTraverse;
    }

    // One light (index into GpuLights): the epipolar walk (work != nullptr) or the brute-force march.
    void traverse(const gl::Program& program, const scene::Scene& scene, const FrameInput& input,
                  const LightWork* work, int gpuIndex, bool writeCoords) {
        const scene::Camera& cam = scene.camera;
        const Settings& s = input.settings;
        program.use();
        setCameraUniforms(program, cam, input.width, input.height);
        program.set("uSigmaS", float(scene.medium.sigma_s));
        program.set("uSigmaT", float(scene.medium.sigma_t()));
        program.set("uG", float(scene.medium.g));
        program.set("uLinear", s.at("traversal") == 1.0);
        program.set("uPieces", int(s.at("spot_pieces")));
        program.set("uMarchSamples", int(s.at("march_samples")));
        program.set("uEpipoleRadius", float(s.at("epipole_radius")));
        program.set("uWriteCoords", writeCoords);
        glm::vec4 epipoles(-1e9f);
        if (work) {
            program.set("uMode", 0);
            program.set("uLight", gpuIndex);
            setFrameUniforms(program, minmax::toFloat(work->setup.frame));
            const auto e = minmax::screenEpipoles(cam, input.width, input.height, work->setup.frame.axis);
            if (e.epipole.valid) epipoles = glm::vec4(glm::vec2(e.epipole.pixel), epipoles.z, epipoles.w);
            if (e.antiEpipole.valid) epipoles = glm::vec4(epipoles.x, epipoles.y, glm::vec2(e.antiEpipole.pixel));
            work->tree.bindUnit(render::hd::kFirstFreeTextureUnit + 1);
            if (work->point()) work->rowGamma.bindBase(GL_SHADER_STORAGE_BUFFER, render::hd::kFirstFreeSsboBinding);
            if (s.at("integrand") == 1.0 && work->prefix) {
                const minmax::LowRank& lr = work->lowRank;
                program.set("uRank", lr.rank);
                program.set("uPrefixTexels", work->prefix.size().x - 1);
                program.set("uPrefixRows", work->prefixRows);
                program.set("uBetaLo", float(lr.betaLo));
                program.set("uBetaHi", float(lr.betaHi));
                glProgramUniform1fv(program.id(), program.location("uBetaBasis[0]"), GLsizei(lr.basisB.size()),
                                    lr.basisB.data());
                work->prefix.bindUnit(render::hd::kFirstFreeTextureUnit + 2);
            }
        } else {
            program.set("uMode", 1);
            program.set("uLight", gpuIndex);
            program.set("uColumns", 1);
            program.set("uSlices", 1);
            program.set("uGammaHi", 1.0f);
        }
        program.set("uEpipoles", epipoles);
        mView.lights().bind();
        mView.shadows().bind();
        mView.surface().distance().bindUnit(render::hd::kFirstFreeTextureUnit);
        mAirlight.bindImage(0, GL_READ_WRITE);
        mVisited.bindImage(1, GL_READ_WRITE);
        mNearMask.bindImage(2, GL_READ_WRITE);
        mRayCoords.bindImage(3, GL_WRITE_ONLY);
        const glm::ivec3 groups = gl::groupCount({input.width, input.height, 1}, program.workGroupSize());
        glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                        GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }

    // ---- intermediates ----

    // Row `row` of a float texture (GL row index) as `channels` floats per texel.
    static std::vector<float> readRow(const gl::Texture& t, int row, int channels) {
        const int width = t.size().x;
        std::vector<float> v(std::size_t(width * channels));
        glGetTextureSubImage(t.id(), 0, 0, row, 0, width, 1, 1, channels == 1 ? GL_RED : GL_RG, GL_FLOAT,
                             GLsizei(v.size() * sizeof(float)), v.data());
        return v;
    }

    // The slice row of the picked pixel for the first epipolar light (computed on the CPU like the shader).
    int pickedRow(const FrameInput& input) const {
        const glm::ivec2 px = pickedPixel(input);
        const auto f = minmax::toFloat(mWork.front().setup.frame);
        const glm::vec3 w = glm::vec3(scene::pixelRay(input.scene->camera, input.width, input.height, px.x, px.y));
        return minmax::sliceRow(f, minmax::alphaOf(f, w));
    }

    void publishRectified(FrameOutput& out, const FrameInput& input) const {
        if (mWork.empty() || input.scene->medium.sigma_s == 0.0) return;
        const LightWork& w = mWork.front();
        out.intermediates.push_back(render::textureIntermediate(
            kRectified, "Rectified shadow map S", "rows: slices alpha; columns: light rays gamma; value: beta of the "
            "occluder (4 = unblocked, -1 = outside the cone)", "radians", ViewKind::Scalar, 0.0f,
            float(std::numbers::pi), w.rectified));
        out.intermediates.back().sentinels = outsideAndUnblocked();
        const gl::Texture& t = w.rectified;
        auto img = std::make_shared<Image>(minmax::rectifiedView([&](int r) { return readRow(t, r, 1); }, t.size().x,
                                                                 t.size().y, pickedRow(input)));
        out.intermediates.push_back(minmax::imageIntermediate(
            kRectifiedView, "Rectified map, picked row",
            "S / pi as grey (row 0 at the top = slice 0; nearest rows and columns when larger than 1024), the "
            "picked pixel's slice in red", ViewKind::Color, img));
        out.intermediates.back().picture = true;
    }

    // Singular values, B_i(beta) and Gamma_i(gamma) as plots, the rank-N reconstruction error and the
    // prefix-sum tables of the first epipolar light.
    void publishLowRank(FrameOutput& out) const {
        if (mWork.empty()) return;
        const LightWork& w = mWork.front();
        const minmax::LowRank& lr = w.lowRank;
        char note[160];
        std::snprintf(note, sizeof note, "log10 bars over 12 decades, kept in green; rank-%d reconstruction error of "
                      "I sin(beta) on the 64x64 grid: %.3g", lr.rank, lr.reconstructionError);
        out.intermediates.push_back(minmax::imageIntermediate(kSingularValues, "Singular values of I", note,
                                                              ViewKind::Color,
                                                              std::make_shared<Image>(minmax::singularValuesView(lr))));
        out.intermediates.back().plots = {minmax::singularValuesPlot(lr)};
        out.intermediates.push_back(minmax::imageIntermediate(
            kBasis, "B_i(beta) and Gamma_i(gamma)",
            "top: B_i over the screen's beta range; bottom: Gamma_i over [gammaLo, gammaHi]; each half scaled to its "
            "largest magnitude, zero in the middle; i = 1.. in red, green, blue, yellow, ...",
            ViewKind::Color, std::make_shared<Image>(minmax::basisView(lr))));
        out.intermediates.back().plots = minmax::basisPlots(lr, w.setup.frame.kind == minmax::LightKind::Directional);
        auto error = std::make_shared<Image>(1, 1, 1);
        error->at(0, 0) = float(lr.reconstructionError);
        out.intermediates.push_back(minmax::imageIntermediate(
            kReconstructionError, "Rank-N reconstruction error",
            "||I - I_N|| / ||I|| (Frobenius) of I sin(beta) on the 64 x 64 grid, first epipolar light",
            ViewKind::Scalar, error));
        out.intermediates.push_back(render::textureIntermediate(
            kPrefixSums, "Prefix sums of Gamma_i T", "x: gamma texel boundary k; y: slice (one row when shared); "
            "layer q / 4, channel q % 4 holds rank i = q / 3, colour q % 3", "", ViewKind::Color, 0.0f, 1.0f,
            w.prefix));
    }

    // The gamma range of every row of the first point light, as a 1 x slices image (image row i = slice i).
    void publishRowGamma(FrameOutput& out) const {
        const auto it = std::find_if(mWork.begin(), mWork.end(), [](const LightWork& w) { return w.point(); });
        if (it == mWork.end()) return;
        const std::vector<std::uint32_t> bits = it->rowGamma.download<std::uint32_t>();
        auto img = std::make_shared<Image>(1, int(bits.size()), 1);
        for (std::size_t i = 0; i < bits.size(); ++i) img->at(0, int(i), 0) = std::bit_cast<float>(bits[i]);
        out.intermediates.push_back(minmax::imageIntermediate(
            kRowGamma, "Gamma range per slice (point light)",
            "row i = slice i: gamma_hi, the largest angle at the light (between light->eye and light->point) that "
            "the slice's pixels' rays reach at their distance d; the row's columns cover [0, gamma_hi] (0: no "
            "pixel in the slice)", ViewKind::Scalar, img));
    }

    // Row `row` of a light's trees as nodes (x = min, y = max).
    static std::vector<glm::vec2> readTreeRow(const gl::Texture& tree, int row) {
        const std::vector<float> raw = readRow(tree, row, 2);
        std::vector<glm::vec2> nodes(raw.size() / 2);
        for (std::size_t k = 0; k < nodes.size(); ++k) nodes[k] = {raw[2 * k], raw[2 * k + 1]};
        return nodes;
    }

    void publishTree(FrameOutput& out, const FrameInput& input) const {
        if (mWork.empty() || input.scene->medium.sigma_s == 0.0) return;
        const LightWork& w = mWork.front();
        out.intermediates.push_back(render::textureIntermediate(
            kTree, "Min-max mipmaps", "row = slice, x = Ahnentafel node (1 = root, leaves at columns..2 columns-1); "
            "r = min, g = max of S below the node", "radians", ViewKind::Color, 0.0f, float(std::numbers::pi),
            w.tree));
        out.intermediates.back().sentinels = outsideAndUnblocked();
        out.intermediates.back().channels = {{"min S below the node", "radians", ViewKind::Scalar, 0.0f, float(std::numbers::pi)},
                                             {"max S below the node", "radians", ViewKind::Scalar, 0.0f, float(std::numbers::pi)}};
        out.intermediates.push_back(minmax::imageIntermediate(
            kPyramid, "Min-max pyramid, picked row",
            "level 0 (root) at the top; each band: min (upper half), max (lower half) as beta / pi; blue = level "
            "not built yet (mip_levels)", ViewKind::Color,
            std::make_shared<Image>(minmax::pyramidView(readTreeRow(w.tree, pickedRow(input)), w.levelsBuilt))));
        out.intermediates.back().picture = true;
    }

    void publishTraverse(FrameOutput& out, const FrameInput& input) {
        out.intermediates.push_back(render::textureIntermediate(
            kAirlight, "L_air", "single-scattered light reaching the eye", "radiance", ViewKind::Color, 0.0f, 1.0f,
            mAirlight));
        out.intermediates.push_back(render::textureIntermediate(
            kVisited, "Nodes visited", "tree nodes (or texels, traversal=linear) processed per pixel, all lights",
            "nodes", ViewKind::Scalar, 0.0f, 64.0f, mVisited));
        out.intermediates.push_back(render::textureIntermediate(
            kNearMask, "Near-epipole mask", "1: marched by brute force near the epipole", "", ViewKind::Mask, 0.0f,
            1.0f, mNearMask));
        out.intermediates.push_back(render::textureIntermediate(
            kRayCoords, "Ray coordinates", "first epipolar light: (slice row, beta, end column cEnd, d) per pixel",
            "", ViewKind::Color, 0.0f, 1.0f, mRayCoords));
        const glm::ivec3 map = mWork.empty() ? glm::ivec3(1) : mWork.front().rectified.size();  // columns x slices
        out.intermediates.back().channels = {
            {"slice row", "rows", ViewKind::Scalar, 0.0f, float(std::max(1, map.y))},
            {"beta", "radians", ViewKind::Scalar, 0.0f, float(std::numbers::pi)},
            {"end column cEnd", "columns", ViewKind::Scalar, 0.0f, float(std::max(1, map.x))},
            {"distance d", "scene units", ViewKind::Depth, 0.0f, float(input.scene->camera.zfar)}};
        if (mWork.empty() || input.scene->medium.sigma_s == 0.0) return;
        // The picked ray against its row's heightfield (Figure 4), from the GPU's own (row, beta, cEnd).
        const LightWork& w = mWork.front();
        const glm::ivec2 px = pickedPixel(input);
        float coords[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        glGetTextureSubImage(mRayCoords.id(), 0, px.x, input.height - 1 - px.y, 0, 1, 1, 1, GL_RGBA, GL_FLOAT,
                             sizeof coords, coords);
        const int row = std::clamp(int(coords[0]), 0, w.setup.frame.slices - 1);
        out.intermediates.push_back(minmax::imageIntermediate(
            kTrace, "Picked ray vs heightfield",
            "top: S of the picked pixel's slice as a heightfield over columns (grey; a ray is lit where it passes "
            "below it: beta < S; vertical range fitted to the row and the ray), the ray's beta in yellow up to its "
            "end; below: the nodes the walk visited (CPU mirror of the shader, first trace_steps), one band per "
            "level, green lit, red shadowed, grey mixed. A pixel marched near the epipole has no walk (row 0, "
            "beta 0 shown)", ViewKind::Color,
            std::make_shared<Image>(minmax::traceView(readTreeRow(w.tree, row), coords[1], coords[2],
                                                      int(substepLimit(input, kTraverseIndex))))));
        out.intermediates.back().rayView = true;
        out.intermediates.back().picture = true;
    }

    std::vector<ParamInfo> mParams;
    std::vector<StageInfo> mStages;
    render::SceneViewPasses mView;
    StageReuse mReuse;  // stages carried over from the last run (FrameInput::resumeAtStage)
    std::vector<LightWork> mWork;
    std::vector<int> mBruteLights;  // GpuLights indices marched by brute force
    gl::Program mRectify, mRectifyPoint, mGammaRange, mMipmap, mTraverse, mPrefix, mPrefixPoint;
    std::string mProgramKey;
    gl::Texture mAirlight, mVisited, mNearMask, mRayCoords;
    // What markersFor needs of the last run.
    scene::Camera mMarkCamera;
    glm::ivec2 mMarkSize{0};
    bool mMarkTraversed = false;
};

}  // namespace

std::unique_ptr<Technique> makeMinmaxTechnique() { return std::make_unique<MinmaxTechnique>(); }

}  // namespace viz
