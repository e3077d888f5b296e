#include "techniques/vsv/vsv.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "gl/program.h"
#include "gl/stage_clock.h"
#include "gl/texture.h"
#include "render/host_device.h"
#include "render/intermediates.h"
#include "render/light_culling.h"
#include "render/scene_view.h"
#include "render/shadow_map_markers.h"
#include "scene/camera.h"
#include "techniques/vsv/add_airlight.h"
#include "techniques/vsv/bits128.h"
#include "techniques/vsv/epipolar_setup.h"
#include "techniques/vsv/grid_readback.h"
#include "techniques/vsv/ivsv.h"
#include "techniques/vsv/stiff_bounds.h"

namespace viz {
namespace {

// ---- ids (stable: lessons and tests use them) ----
constexpr const char* kStageVoxelize = "vsv.voxelize";
constexpr const char* kStageScan = "vsv.scan";
constexpr const char* kStageGather = "vsv.gather";
constexpr const char* kOccluder = "vsv.occluder_alpha";
constexpr const char* kVoxelSlice = "vsv.voxels";
constexpr const char* kScanSlice = "vsv.scanned";
constexpr const char* kColumn = "vsv.column";
constexpr const char* kAirlight = "vsv.airlight";
constexpr const char* kVisibility = "vsv.visibility";

enum StageIndex {
    kShadowMapsIndex = 0,
    kSurfaceIndex = 1,
    kVoxelizeIndex = 2,
    kScanIndex = 3,
    kGatherIndex = 4,
    kComposeIndex = 5
};

constexpr int kMaxScanPasses = 10;  // 2^10 = 1024 alpha cells, the largest `voxels`

// Shader permutations: feature -> {define when enabled, define when disabled}.
const std::map<std::string, std::pair<const char*, const char*>> kDefines = {
    {"COMBINE_EXACT", {"COMBINE_EXACT", nullptr}},
    {"INTERP", {"INTERP", nullptr}},
    {"EPIPOLE", {"EPIPOLE", nullptr}},
    {"SPOT", {nullptr, "LIGHTS_NO_SPOT"}},
    {"COOKIE", {nullptr, "LIGHTS_NO_COOKIE"}},
    {"SHADOW_MAPS_CUBE", {nullptr, "SHADOW_NO_CUBE"}},
    {"SHADOW_MAPS_2D", {nullptr, "SHADOW_NO_2D"}},
};

struct GridSize {
    int alpha = 128, theta = 128, phi = 128;
};

GridSize gridSize(const Settings& s) {
    const int n = int(s.at("voxels"));
    GridSize g{n, n, n};
    if (s.at("voxels_alpha") > 0) g.alpha = int(s.at("voxels_alpha"));
    if (s.at("voxels_theta") > 0) g.theta = int(s.at("voxels_theta"));
    if (s.at("voxels_phi") > 0) g.phi = int(s.at("voxels_phi"));
    if (g.phi % 32 != 0)
        throw InputError("vsv: the phi resolution (" + std::to_string(g.phi) +
                         ") must be a multiple of 32 (phi bits are packed in 32-bit words)");
    return g;
}

// The scene lights vsv shades itself: point, spot, directional, except those culled because their lit
// volume misses the view (render/light_culling.h: they have no GPU light and add nothing). Area lights
// go to an inner ivsv.
std::vector<int> shadedLights(const scene::Scene& scene) {
    std::vector<int> out;
    for (int i = 0; i < int(scene.lights.size()); ++i) {
        const scene::Light& l = scene.lights[std::size_t(i)];
        if (l.type != scene::LightType::Area && render::lightReachesView(l, scene.camera)) out.push_back(i);
    }
    return out;
}

scene::Scene onlyAreaLights(const scene::Scene& scene) {
    scene::Scene out = scene;
    out.lights.clear();
    for (const scene::Light& l : scene.lights)
        if (l.type == scene::LightType::Area) out.lights.push_back(l);
    return out;
}

using vsv::scanPassCount;

using vsv::cpuIntermediate;

class VsvTechnique final : public Technique {
public:
    VsvTechnique() {
        mParams = {
            {"voxels", "epipolar grid cells per axis (alpha, theta, phi), or AxBxC per axis; phi a multiple of 32",
             128, 32, 1024, true, {}, {"voxels_alpha", "voxels_theta", "voxels_phi"}},
            {"voxels_alpha", "alpha cells (0: `voxels`)", 0, 0, 1024, true},
            {"voxels_theta", "theta cells (0: `voxels`)", 0, 0, 1024, true},
            {"voxels_phi", "phi bits (0: `voxels`; a multiple of 32)", 0, 0, 1024, true},
            {"combine", "fraction: lit fraction x unshadowed airlight; exact: sum of airlight over lit runs", 1, 0,
             1, true, {"fraction", "exact"}},
            {"alpha_bias", "occluder alpha offset in cells (negative: shadow starts further from the light; the "
                           "paper's -2.25)",
             0, -16, 16, false},
            {"phi_bias", "light-ray phi offset in cells (negative: shadow moves away from the eye; the paper's -1)", 0,
             -16, 16, false},
            {"interp", "1: two texels along theta; 0: nearest", 1, 0, 1, true},
            {"dynamic_range", "1: the grid covers only the visible part of epipolar space; 0: all of it", 1, 0, 1,
             true},
            {"epipole", "1: near an epipole compare the fragment with the light instead of reading the grid", 1, 0, 1,
             true},
            {"direct_bins", "rays crossing fewer phi bins than this test the shadow map directly (0: only rays at "
                            "an epipole)",
             4, 0, 1024, false},
            {"direct_segments", "shadow-map tests along a direct ray (epipole or too few phi bins)", 128, 1, 4096,
             true},
            {"run_bins", "longest run of phi bins per airlight segment (spot falloff averaged over it)", 8, 1, 1024,
             true},
            {"scan_passes", "stop the alpha scan after this many passes (-1: all; stepping)", -1, -1, kMaxScanPasses,
             true},
            {"pick_x", "pixel whose voxel column is shown (-1: image centre)", -1, -1, 1e6, true},
            {"pick_y", "pixel row (0 = top) whose voxel column is shown (-1: image centre)", -1, -1, 1e6, true},
            {"pick_theta", "theta cell of the unwrapped alpha x phi slices (-1: that of the picked pixel)", -1, -1,
             1024, true},
            {"light", "which light's grid the intermediates show (index among the scene's lights)", 0, 0, 255, true},
        };
        for (ParamInfo& p : render::SceneViewPasses::params()) mParams.push_back(std::move(p));
        mParams.push_back(forceFeaturesParam());
        mStages = {
            render::SceneViewPasses::shadowStage("vsv"),
            render::SceneViewPasses::surfaceStage("vsv"),
            {kStageVoxelize, "Voxelize",
             "resample each light's shadow map into its epipolar grid: the first occluder's alpha per (theta, phi)",
             {"voxels", "voxels_alpha", "voxels_theta", "voxels_phi", "alpha_bias", "phi_bias", "dynamic_range",
              "pick_theta"},
             {kOccluder, kVoxelSlice}, 1},
            {kStageScan, "Extrude (scan)",
             "prefix OR along alpha in log2(alpha cells) ping-pong passes: occlusion extends away from the light",
             {"scan_passes", "pick_theta"}, {kScanSlice}, kMaxScanPasses, "scan_passes"},
            {kStageGather, "Gather",
             "per pixel: one texel per eye ray, its phi bits up to the fragment, combined with the airlight",
             {"combine", "interp", "epipole", "direct_bins", "direct_segments", "run_bins", "pick_x", "pick_y",
              "force_features"}, {kColumn, kAirlight, kVisibility}, 1},
            render::SceneViewPasses::composeStage("vsv"),
        };
    }

    // Stepping the scan pass by pass: scan_passes = 0 (the voxelized grid before any pass), 1, ...,
    // then -1 (all log2(alpha cells) passes).
    std::vector<double> substepValues(int stage, const Settings& s) const override {
        if (stage != kScanIndex) return Technique::substepValues(stage, s);
        const int alpha = s.at("voxels_alpha") > 0 ? int(s.at("voxels_alpha")) : int(s.at("voxels"));
        std::vector<double> values;
        for (int k = 0; k < scanPassCount(alpha); ++k) values.push_back(double(k));
        values.push_back(-1.0);
        return values;
    }

    std::string id() const override { return "vsv"; }
    std::string description() const override {
        return "voxelized shadow volumes (Wyman 2011): epipolar voxel grid, prefix-OR extrusion, one texel per ray";
    }
    const std::vector<StageInfo>& stages() const override { return mStages; }
    const std::vector<ParamInfo>& params() const override { return mParams; }
    bool needsGl() const override { return true; }

    // Voxel resolution per axis, the one quality knob (issue 9): the grid's alpha, theta and phi cells
    // bound how finely shadow edges and the light's falloff along each ray are resolved.
    std::vector<QualitySetting> qualitySweep(bool quick) const override {
        std::vector<QualitySetting> sweep;
        const std::vector<int> sizes = quick ? std::vector<int>{64, 128} : std::vector<int>{32, 64, 128, 256, 512};
        for (int n : sizes) sweep.push_back({"voxels=" + std::to_string(n), {{"voxels", double(n)}}});
        return sweep;
    }

    Settings stiffSettings() const override { return {{"voxels", 512.0}, {"combine", 1.0}}; }
    // Wyman 2011: the lit fraction times the unshadowed airlight, alpha and phi biases of -2.25 and -1
    // cells.
    Settings paperSettings() const override {
        return {{"combine", 0.0}, {"alpha_bias", -2.25}, {"phi_bias", -1.0}};
    }

    std::optional<StiffBound> stiffBound(const std::string& caseClass) const override {
        return vsv::stiffBound(caseClass);
    }

    Plan plan(const scene::Scene& scene, const Settings& settings) const override {
        // Without an image size, the camera's aspect ratio (or 4:3) decides what is in view.
        const int h = 120;
        const int w = scene.camera.aspectRatio > 0.0 ? int(std::lround(h * scene.camera.aspectRatio)) : 160;
        return planFor(scene, settings, w, h);
    }

    FrameOutput run(const FrameInput& input) override {
        const scene::Scene& scene = *input.scene;
        const Settings& s = input.settings;
        FrameOutput out;
        out.plan = planFor(scene, s, input.width, input.height);
        out.timing.clock = gl::StageClock::method();
        const int stop = input.stopAfterStage < 0 ? kComposeIndex : input.stopAfterStage;
        const std::vector<int> lights = shadedLights(scene);
        const GridSize size = gridSize(s);
        gl::StageClock clock;
        mMark.reset();

        // ---- shadow maps and camera view ----
        mReuse.begin(input, out);
        if (!mView.runSharedStages(input, stop, mStages, "vsv", out, mReuse)) return out;

        // One grid per light; the stages below run light after light and time the sum. The intermediates
        // show the light chosen by `light`.
        const int shown = std::clamp(int(s.at("light")), 0, std::max(0, int(lights.size()) - 1));
        const bool dynamic = s.at("dynamic_range") != 0.0;
        std::vector<vsv::EpipolarGrid> grids;
        for (int li : lights)
            grids.push_back(vsv::gridForLight(scene, scene.lights[std::size_t(li)], input.width, input.height,
                                              size.alpha, size.theta, size.phi, dynamic));
        allocate(size, input.width, input.height, int(lights.size()));
        const bool gatherRuns = out.plan.stages[kGatherIndex].runs;
        const int pickX = s.at("pick_x") < 0 ? input.width / 2 : std::min(int(s.at("pick_x")), input.width - 1);
        const int pickY = s.at("pick_y") < 0 ? input.height / 2 : std::min(int(s.at("pick_y")), input.height - 1);
        int pickTheta = 0;
        if (!lights.empty()) {
            const vsv::EpipolarGrid& g = grids[std::size_t(shown)];
            const vsv::EpipolarFrame f = vsv::frameForLight(scene, scene.lights[std::size_t(lights[std::size_t(shown)])]);
            const glm::dvec3 ray = scene::pixelRay(scene.camera, input.width, input.height, pickX, pickY);
            pickTheta = std::clamp(int(std::floor(vsv::thetaCoord(g, vsv::thetaOf(f, ray)))), 0, g.nTheta - 1);
            if (s.at("pick_theta") >= 0) pickTheta = std::min(int(s.at("pick_theta")), g.nTheta - 1);
            mMark = MarkState{f, g, scene.camera, {input.width, input.height}, pickTheta};
        }

        // ---- voxelize ----
        clock.begin();
        for (std::size_t i = 0; i < lights.size(); ++i) voxelize(scene, s, lights[i], grids[i], int(i));
        out.timing.stages.push_back({kStageVoxelize, clock.endMilliseconds()});
        if (!lights.empty()) {
            out.intermediates.push_back(render::textureIntermediate(
                kOccluder, "Occluder alpha",
                "per light ray (x = phi bit, y = theta cell): alpha cell of its first occluder (-1: none in the grid)",
                "cells", ViewKind::Scalar, 0.0f, float(size.alpha), mOccluder[std::size_t(shown)]));
            out.intermediates.back().sentinels = {{-1.0f, "no occluder in the grid"}};
            out.intermediates.push_back(cpuIntermediate(
                kVoxelSlice, "Voxels (before scan)",
                "alpha (x) x phi (y, eye at the top) slice at theta cell " + std::to_string(pickTheta) +
                    ": white = occluder voxel",
                ViewKind::BitField, vsv::sliceImage(mGrid[std::size_t(shown)], 0, size.alpha, pickTheta, size.phi)));
        }
        out.lastStageRun = kVoxelizeIndex;
        if (stop == kVoxelizeIndex) return out;

        // The picked pixel's column as voxelized, for the gather's column view (the scan overwrites the
        // grid): one texel per 128 phi bits, read only when the gather will run.
        if (!lights.empty() && stop != kScanIndex) {
            const glm::ivec2 cell = pickedCell(scene, input, lights[std::size_t(shown)], grids[std::size_t(shown)], pickX, pickY);
            mPreScanColumn = vsv::readGridRow(mGrid[std::size_t(shown)], cell.x, 1, cell.y);
        }

        // ---- scan ----
        clock.begin();
        const int passSetting = int(substepLimit(input, kScanIndex));
        const int passLimit = passSetting < 0 ? kMaxScanPasses : passSetting;
        for (std::size_t i = 0; i < lights.size(); ++i) scan(int(i), size, passLimit);
        out.timing.stages.push_back({kStageScan, clock.endMilliseconds()});
        if (!lights.empty()) {
            const int passes = std::min(passLimit, scanPassCount(size.alpha));
            out.intermediates.push_back(cpuIntermediate(
                kScanSlice, "Voxels after " + std::to_string(passes) + " scan passes",
                "alpha x phi slice at theta cell " + std::to_string(pickTheta) +
                    ": white = shadowed (after all passes: one run from the occluder to the end of alpha)",
                ViewKind::BitField, vsv::sliceImage(*mResult[std::size_t(shown)], 0, size.alpha, pickTheta, size.phi)));
        }
        out.lastStageRun = kScanIndex;
        if (stop == kScanIndex) return out;

        // ---- gather ----
        clock.begin();
        mAirlight.clear(glm::vec4(0.0f));
        mVisibility.clear(glm::vec4(1.0f, 1.0f, 0.0f, 0.0f));
        if (gatherRuns) {
            if (!lights.empty()) {
                const gl::Program& program = gatherProgram(out.plan);
                for (std::size_t i = 0; i < lights.size(); ++i)
                    gather(program, scene, input, lights[i], grids[i], int(i));
            }
            if (featureEnabled(out.plan, "AREA_LIGHTS_BY_IVSV")) addAreaLights(input);
        }
        out.timing.stages.push_back({kStageGather, clock.endMilliseconds()});
        if (!lights.empty()) {
            out.intermediates.push_back(cpuIntermediate(
                kColumn, "Voxel column of pixel (" + std::to_string(pickX) + ", " + std::to_string(pickY) + ")",
                "the 128 phi bits its eye ray reads; top row as voxelized (1 occluder), bottom row after the scan "
                "(1 shadowed, 0 lit); 0.5 beyond the fragment (not read)",
                ViewKind::BitField,
                columnImage(scene, input, lights[std::size_t(shown)], grids[std::size_t(shown)], shown, pickX,
                            pickY)));
            out.intermediates.back().rayView = true;
        }
        out.intermediates.push_back(render::textureIntermediate(
            kAirlight, "L_air", "single-scattered light reaching the eye", "radiance", ViewKind::Color, 0.0f, 1.0f,
            mAirlight));
        out.intermediates.push_back(render::textureIntermediate(
            kVisibility, "Visibility",
            "r: phi-uniform lit fraction of the ray's bits; g: interpolated visibility of the fragment's voxel; "
            "b: alpha cell; a: theta cell, -1 where the epipole case replaced the grid",
            "", ViewKind::Scalar, 0.0f, 1.0f, mVisibility));
        out.intermediates.back().sentinels = {{-1.0f, "epipole case: a direct ray replaced the grid"}};
        out.intermediates.back().channels = {{"lit fraction of the ray", "", ViewKind::Scalar, 0.0f, 1.0f},
                                             {"visibility of the fragment", "", ViewKind::Scalar, 0.0f, 1.0f},
                                             {"alpha cell", "cells", ViewKind::Scalar, 0.0f, float(size.alpha)},
                                             {"theta cell", "cells", ViewKind::Scalar, 0.0f, float(size.theta)}};
        out.airlight = render::readRgb(mAirlight);
        out.lastStageRun = kGatherIndex;
        if (stop == kGatherIndex) return out;

        // ---- compose ----
        clock.begin();
        out.final = mView.compose(scene, mAirlight, out.intermediates, "vsv");
        out.timing.stages.push_back({mStages[kComposeIndex].id, clock.endMilliseconds()});
        out.lastStageRun = kComposeIndex;
        return out;
    }

    // A screen pixel in the grid of the shown light: its eye ray's theta cell as a row of the occluder
    // map (x = phi bit, y = theta cell), and in the alpha x phi voxel slices, when the slice shown is
    // the pixel's (theta cell = pick_theta's), its eye ray as the column at its alpha.
    // In every light's shadow map: the eye ray and its lit/shadow changes (render/shadow_map_markers.h).
    std::vector<ViewMarker> markersFor(glm::ivec2 pixel, const std::string& id) const override {
        if (render::shadowMapIndexOf(id, "vsv") >= 0) return mView.shadowMapMarkers(pixel, id, "vsv");
        if (!mMark || (id != kOccluder && id != kVoxelSlice && id != kScanSlice)) return {};
        const MarkState& m = *mMark;
        if (pixel.x < 0 || pixel.y < 0 || pixel.x >= m.size.x || pixel.y >= m.size.y) return {};
        const glm::dvec3 ray = scene::pixelRay(m.camera, m.size.x, m.size.y, pixel.x, pixel.y);
        const int theta = int(std::floor(vsv::thetaCoord(m.grid, vsv::thetaOf(m.frame, ray))));
        if (theta < 0 || theta >= m.grid.nTheta) return {};  // outside the grid (near the epipole)
        if (id == kOccluder) {
            const float v = (float(theta) + 0.5f) / float(m.grid.nTheta);
            return {{{0.0f, v}, {1.0f, v}, "theta cell " + std::to_string(theta)}};
        }
        if (theta != m.pickTheta) return {};
        const double alpha = vsv::alphaCoord(m.grid, vsv::alphaOf(m.frame, ray));
        if (alpha < 0.0 || alpha >= double(m.grid.nAlpha)) return {};
        const float u = float(alpha) / float(m.grid.nAlpha);
        return {{{u, 0.0f}, {u, 1.0f}, "eye ray, alpha cell " + std::to_string(int(alpha))}};
    }

private:
    struct MarkState {
        vsv::EpipolarFrame frame;
        vsv::EpipolarGrid grid;
        scene::Camera camera;
        glm::ivec2 size{0};
        int pickTheta = 0;
    };
    std::optional<MarkState> mMark;  // the shown light's grid in the last run, for markersFor

    Plan planFor(const scene::Scene& scene, const Settings& settings, int width, int height) const {
        Plan p;
        for (const StageInfo& st : mStages) p.stages.push_back({st.id, true, ""});
        const std::vector<int> lights = shadedLights(scene);
        const bool hasArea = render::hasLightOfType(scene, scene::LightType::Area);
        if (lights.empty()) {
            for (int i : {kVoxelizeIndex, kScanIndex}) {
                p.stages[std::size_t(i)].runs = false;
                p.stages[std::size_t(i)].why = "no point, spot or directional light";
            }
        }
        if (scene.medium.sigma_s == 0.0) {
            p.stages[kGatherIndex].runs = false;
            p.stages[kGatherIndex].why = "sigma_s = 0: the medium scatters nothing, L_air = 0";
        }
        const GridSize size = gridSize(settings);
        if (!lights.empty())
            p.stages[kScanIndex].why = std::to_string(scanPassCount(size.alpha)) + " passes for " +
                                       std::to_string(size.alpha) + " alpha cells";
        const bool exact = settings.at("combine") != 0.0;
        const bool interp = settings.at("interp") != 0.0;
        bool epipoleInView = false;
        for (int li : lights) {
            const vsv::EpipolarGrid g = vsv::gridForLight(scene, scene.lights[std::size_t(li)], width, height,
                                                          size.alpha, size.theta, size.phi, true);
            epipoleInView = epipoleInView || g.epipoleToward || g.epipoleAway;
        }
        const bool epipole = epipoleInView && settings.at("epipole") != 0.0;
        // Over the lights vsv shades (culled ones have no GPU light, no shadow map, no cookie lookup).
        const auto shaded = [&](auto predicate) {
            return std::any_of(lights.begin(), lights.end(),
                               [&](int i) { return predicate(scene.lights[std::size_t(i)]); });
        };
        const bool hasSpot = shaded([](const scene::Light& l) { return l.type == scene::LightType::Spot; });
        const bool hasPoint = shaded([](const scene::Light& l) { return l.type == scene::LightType::Point; });
        const bool hasSun = shaded([](const scene::Light& l) { return l.type == scene::LightType::Directional; });
        const bool hasCookie = shaded([](const scene::Light& l) { return l.cookie >= 0; });
        p.features.push_back({"COMBINE_EXACT", exact,
                              exact ? "combine=exact: airlight summed over lit runs of phi bins (pointSegment)"
                                    : "combine=fraction: lit fraction x unshadowed airlight (the paper's factorisation)"});
        p.features.push_back({"INTERP", interp,
                              interp ? "two texels along theta (the fragment's own bit-level phi fraction fills only "
                                       "the debug channel vsv.visibility.g)"
                                     : "interp=0: nearest texel"});
        p.features.push_back(
            {"EPIPOLE", epipole,
             epipole ? "an epipole is in view: rays within one alpha cell of it test the shadow map directly"
                     : (epipoleInView ? "epipole=0: the grid is read even at the epipole"
                                      : "no epipole in view (the light and its antipode are off screen)")});
        p.features.push_back({"DYNAMIC_RANGE", settings.at("dynamic_range") != 0.0,
                              settings.at("dynamic_range") != 0.0
                                  ? "alpha, theta, phi ranges cover only the visible part (a run-time choice)"
                                  : "the grid spans alpha, phi in [0, pi], theta in (-pi, pi]"});
        p.features.push_back({"SPOT", hasSpot, hasSpot ? "spot falloff and cone band in phi" : "no spot light"});
        p.features.push_back({"COOKIE", hasCookie, hasCookie ? "cookie texture" : "no light has a cookie"});
        p.features.push_back({"SHADOW_MAPS_CUBE", hasPoint,
                              hasPoint ? "point lights voxelize from cube maps" : "no point light: no cube map"});
        p.features.push_back({"SHADOW_MAPS_2D", hasSpot || hasSun,
                              hasSpot || hasSun ? "spot and directional lights voxelize from 2D maps"
                                                : "no spot or directional light"});
        p.features.push_back({"DIRECTIONAL", hasSun,
                              hasSun ? "light lines at offset y replace light-ray angles (a run-time branch)"
                                     : "no directional light"});
        p.features.push_back({"AREA_LIGHTS_BY_IVSV", hasArea,
                              hasArea ? "the area light is shaded by an inner ivsv (its defaults) in the gather stage"
                                      : "no area light"});
        render::planCulledLights(scene, p);
        // Scene-pruned features (force_features=1 turns them on; the image must not change): light types
        // and cookies compiled out, the epipole rays when no epipole is in view (the grid flags then keep
        // every ray on the grid), the inner ivsv without an area light (it adds zero).
        std::vector<std::string> pruned = {"SPOT", "COOKIE", "SHADOW_MAPS_CUBE", "SHADOW_MAPS_2D", "AREA_LIGHTS_BY_IVSV"};
        if (settings.at("epipole") != 0.0) pruned.push_back("EPIPOLE");
        forcePlan(p, settings.at("force_features") != 0.0, pruned);
        for (FeaturePlan& f : p.features) {
            const auto it = kDefines.find(f.feature);
            const char* define = it == kDefines.end() ? nullptr : (f.enabled ? it->second.first : it->second.second);
            if (define) f.why += std::string(f.enabled ? " (compiled in: " : " (compiled out: ") + define + ")";
        }
        return p;
    }

    void allocate(const GridSize& size, int width, int height, int lightCount) {
        const int layers = (size.phi + 127) / 128;
        const glm::ivec3 grid(size.alpha, size.theta, layers);
        if (mGridSize != grid || int(mGrid.size()) != lightCount) {
            mGrid.clear();
            mPong.clear();
            mOccluder.clear();
            for (int i = 0; i < lightCount; ++i) {
                mGrid.push_back(gl::Texture::create({.target = GL_TEXTURE_2D_ARRAY, .format = GL_RGBA32UI,
                                                     .size = grid, .levels = 1, .label = "vsv.grid"}));
                mPong.push_back(gl::Texture::create({.target = GL_TEXTURE_2D_ARRAY, .format = GL_RGBA32UI,
                                                     .size = grid, .levels = 1, .label = "vsv.grid_pong"}));
                mOccluder.push_back(gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_R32F,
                                                         .size = {size.phi, size.theta, 1}, .levels = 1,
                                                         .label = kOccluder}));
            }
            mWords = gl::Texture::create({.target = GL_TEXTURE_2D_ARRAY, .format = GL_R32UI,
                                          .size = {size.alpha, size.theta, 4 * layers}, .levels = 1,
                                          .label = "vsv.words"});
            mResult.assign(std::size_t(lightCount), nullptr);
            mGridSize = grid;
        }
        if (!mAirlight || mAirlight.size().x != width || mAirlight.size().y != height) {
            mAirlight = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_RGBA32F, .size = {width, height, 1},
                                             .levels = 1, .label = kAirlight});
            mVisibility = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_RGBA32F,
                                               .size = {width, height, 1}, .levels = 1, .label = kVisibility});
        }
        if (!mVoxelize) {
            mVoxelize = gl::Program::compile({.stages = {"vsv/voxelize.comp"}, .label = "vsv.voxelize"});
            mPack = gl::Program::compile({.stages = {"vsv/pack.comp"}, .label = "vsv.pack"});
            mScan = gl::Program::compile({.stages = {"vsv/scan.comp"}, .label = "vsv.scan"});
        }
    }

    // Area lights through ivsv (its defaults, this run's `voxels` for alpha and theta), added to L_air.
    void addAreaLights(const FrameInput& input) {
        const scene::Scene areas = onlyAreaLights(*input.scene);
        if (!mIvsv) mIvsv = makeIvsvTechnique();
        FrameInput in;
        in.scene = &areas;
        in.width = input.width;
        in.height = input.height;
        in.settings = completeSettings(*mIvsv, {{"voxels", std::min(512.0, input.settings.at("voxels"))}});
        in.stopAfterStage = 5;  // ivsv.gather: L_air exists, no compose needed
        const FrameOutput extra = mIvsv->run(in);
        vsv::addAirlight(mAirlight, extra.airlight);
    }

    int gpuLightIndex(int sceneLight) const {
        const auto& gpu = mView.lights().lights();
        for (int i = 0; i < int(gpu.size()); ++i)
            if (gpu[std::size_t(i)].info.w == sceneLight) return i;
        VIZ_CHECK(false, "scene light without a GPU light");
        return -1;
    }

    static void setEpipolar(const gl::Program& program, const vsv::EpipolarFrame& f, const vsv::EpipolarGrid& g) {
        program.set("uEpiB", glm::vec3(f.b));
        program.set("uEpiU", glm::vec3(f.u));
        program.set("uEpiV", glm::vec3(f.v));
        program.set("uEpiD", float(f.D));
        program.set("uEpiCells", glm::ivec3(g.nAlpha, g.nTheta, g.nPhi));
        program.set("uEpiAlpha", glm::vec2(float(g.alpha0), float(g.dAlpha())));
        program.set("uEpiTheta", glm::vec3(float(g.thetaCentre), float(g.thetaHalf), float(g.dTheta())));
        program.set("uEpiPhi", glm::vec2(float(g.phi0), float(g.dPhi())));
        program.set("uEpiThetaFull", g.thetaFull ? 1 : 0);
    }

    void voxelize(const scene::Scene& scene, const Settings& s, int sceneLight, const vsv::EpipolarGrid& g, int slot) {
        const vsv::EpipolarFrame f = vsv::frameForLight(scene, scene.lights[std::size_t(sceneLight)]);
        const GLuint zero = 0;
        mWords.clear(GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
        mView.lights().bind();
        mView.shadows().bind();
        mVoxelize.use();
        setEpipolar(mVoxelize, f, g);
        mVoxelize.set("uLight", gpuLightIndex(sceneLight));
        mVoxelize.set("uAlphaBias", float(s.at("alpha_bias")));
        mVoxelize.set("uPhiBias", float(s.at("phi_bias")));
        mWords.bindImage(0, GL_READ_WRITE);
        mOccluder[std::size_t(slot)].bindImage(1, GL_WRITE_ONLY);
        glm::ivec3 groups = gl::groupCount({g.nPhi, g.nTheta, 1}, mVoxelize.workGroupSize());
        glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);

        const gl::Texture& grid = mGrid[std::size_t(slot)];
        mPack.use();
        mPack.set("uSize", grid.size());
        mPack.set("uOrigin", glm::ivec2(0));
        mWords.bindImage(0, GL_READ_ONLY);
        grid.bindImage(1, GL_WRITE_ONLY);
        groups = gl::groupCount(grid.size(), mPack.workGroupSize());
        glDispatchCompute(GLuint(groups.x), GLuint(groups.y), GLuint(groups.z));
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
        mResult[std::size_t(slot)] = &grid;
    }

    // Hillis-Steele passes with offsets 1, 2, 4, ...: ping-pong between the grid and its partner; the
    // result pointer follows the last pass written.
    void scan(int slot, const GridSize& size, int passLimit) {
        const gl::Texture* src = &mGrid[std::size_t(slot)];
        const gl::Texture* dst = &mPong[std::size_t(slot)];
        const int passes = std::min(passLimit, scanPassCount(size.alpha));
        mScan.use();
        mScan.set("uSize", src->size());
        mScan.set("uSegment", 0);
        mScan.set("uOrigin", glm::ivec2(0));
        const glm::ivec3 groups = gl::groupCount(src->size(), mScan.workGroupSize());
        for (int p = 0; p < passes; ++p) {
            mScan.set("uOffset", 1 << p);
            src->bindImage(0, GL_READ_ONLY);
            dst->bindImage(1, GL_WRITE_ONLY);
            glDispatchCompute(GLuint(groups.x), GLuint(groups.y), GLuint(groups.z));
            glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
            std::swap(src, dst);
        }
        mResult[std::size_t(slot)] = src;
    }

    const gl::Program& gatherProgram(const Plan& plan) {
        gl::ShaderDefines defines;
        std::string key;
        for (const FeaturePlan& f : plan.features) {
            const auto it = kDefines.find(f.feature);
            if (it == kDefines.end()) continue;
            const char* define = f.enabled ? it->second.first : it->second.second;
            if (!define) continue;
            defines.push_back({define, "1"});
            key += std::string(define) + ";";
        }
        if (key != mGatherKey || !mGather) {
            mGather = gl::Program::compile({.stages = {"vsv/gather.comp"}, .defines = defines, .label = "vsv.gather"});
            mGatherKey = key;
        }
        return mGather;
    }

    void gather(const gl::Program& program, const scene::Scene& scene, const FrameInput& input, int sceneLight,
                const vsv::EpipolarGrid& g, int slot) {
        const scene::Camera& cam = scene.camera;
        const vsv::EpipolarFrame f = vsv::frameForLight(scene, scene.lights[std::size_t(sceneLight)]);
        program.use();
        setEpipolar(program, f, g);
        program.set("uSize", glm::ivec2(input.width, input.height));
        program.set("uForward", glm::vec3(cam.forward));
        program.set("uRight", glm::vec3(scene::cameraRight(cam)));
        program.set("uUp", glm::vec3(cam.up));
        program.set("uTanHalf", float(std::tan(cam.yfov * 0.5)));
        program.set("uAspect", float(scene::aspectOf(cam, input.width, input.height)));
        program.set("uLight", gpuLightIndex(sceneLight));
        program.set("uSigmaS", float(scene.medium.sigma_s));
        program.set("uSigmaT", float(scene.medium.sigma_t()));
        program.set("uG", float(scene.medium.g));
        program.set("uRunBins", int(input.settings.at("run_bins")));
        program.set("uAccumulate", slot > 0 ? 1 : 0);
        program.set("uEpipoleToward", g.epipoleToward && g.alpha0 == 0.0 ? 1 : 0);
        program.set("uEpipoleAway", g.epipoleAway && g.alpha1 >= 3.141592653589793 ? 1 : 0);
        program.set("uDirectBins", float(input.settings.at("direct_bins")));
        program.set("uDirectSegments", int(input.settings.at("direct_segments")));
        mView.lights().bind();
        mView.shadows().bind();
        mView.surface().distance().bindUnit(render::hd::kFirstFreeTextureUnit);
        mResult[std::size_t(slot)]->bindImage(0, GL_READ_ONLY);
        mAirlight.bindImage(1, GL_READ_WRITE);
        mVisibility.bindImage(2, GL_WRITE_ONLY);
        const glm::ivec3 groups = gl::groupCount({input.width, input.height, 1}, program.workGroupSize());
        glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                        GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }

    // The phi bits the picked pixel's eye ray reads (nearest theta cell), marked 0.5 beyond its fragment.
    // The alpha cell (x) and theta cell (y) of pixel (x, y)'s eye ray in light `sceneLight`'s grid.
    static glm::ivec2 pickedCell(const scene::Scene& scene, const FrameInput& input, int sceneLight,
                                 const vsv::EpipolarGrid& g, int x, int y) {
        const vsv::EpipolarFrame f = vsv::frameForLight(scene, scene.lights[std::size_t(sceneLight)]);
        const glm::dvec3 ray = scene::pixelRay(scene.camera, input.width, input.height, x, y);
        return {std::clamp(int(std::floor(vsv::alphaCoord(g, vsv::alphaOf(f, ray)))), 0, g.nAlpha - 1),
                std::clamp(int(std::floor(vsv::thetaCoord(g, vsv::thetaOf(f, ray)))), 0, g.nTheta - 1)};
    }

    // Two rows of phi bits along pixel (x, y)'s column: row 0 as voxelized (mPreScanColumn), row 1 after the
    // scan; 0.5 beyond the pixel's fragment (the gather does not read them).
    std::shared_ptr<Image> columnImage(const scene::Scene& scene, const FrameInput& input, int sceneLight,
                                       const vsv::EpipolarGrid& g, int slot, int x, int y) const {
        const vsv::EpipolarFrame f = vsv::frameForLight(scene, scene.lights[std::size_t(sceneLight)]);
        const glm::ivec2 cell = pickedCell(scene, input, sceneLight, g, x, y);
        const double alpha = vsv::alphaOf(f, scene::pixelRay(scene.camera, input.width, input.height, x, y));
        float d = 0.0f;
        glGetTextureSubImage(mView.surface().distance().id(), 0, x, input.height - 1 - y, 0, 1, 1, 1, GL_RED,
                             GL_FLOAT, sizeof(float), &d);
        const double kEnd = vsv::phiCoord(g, vsv::phiOnEyeRay(f, alpha, double(d)));
        const std::vector<vsv::Bits128> after = vsv::readGridRow(*mResult[std::size_t(slot)], cell.x, 1, cell.y);
        auto image = std::make_shared<Image>(g.nPhi, 2, 1);
        for (int row = 0; row < 2; ++row) {
            const std::vector<vsv::Bits128>& bits = row == 0 ? mPreScanColumn : after;
            for (int k = 0; k < g.nPhi; ++k) {
                const std::size_t at = std::size_t(k >> 7);  // one texel per 128 bits, layer by layer
                const bool set = at < bits.size() && vsv::testBitPlain(bits[at], k & 127);
                image->at(k, row) = double(k) >= kEnd ? 0.5f : (set ? 1.0f : 0.0f);
            }
        }
        return image;
    }

    std::vector<ParamInfo> mParams;
    std::vector<StageInfo> mStages;
    render::SceneViewPasses mView;
    StageReuse mReuse;  // stages carried over from the last run (FrameInput::resumeAtStage)
    gl::Program mVoxelize, mPack, mScan, mGather;
    std::string mGatherKey;
    glm::ivec3 mGridSize{0};
    std::vector<gl::Texture> mGrid, mPong, mOccluder;  // per light
    std::vector<const gl::Texture*> mResult;           // per light: where the scan left the grid
    std::vector<vsv::Bits128> mPreScanColumn;           // the picked pixel's texels before the scan
    gl::Texture mWords;                                // voxelization scratch, one light at a time
    gl::Texture mAirlight, mVisibility;
    std::unique_ptr<Technique> mIvsv;  // the scene's area lights
};

}  // namespace

std::unique_ptr<Technique> makeVsvTechnique() { return std::make_unique<VsvTechnique>(); }

}  // namespace viz
