#include "techniques/vsv/ivsv.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
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
#include "techniques/vsv/add_airlight.h"
#include "techniques/vsv/bits128.h"
#include "techniques/vsv/epipolar_setup.h"
#include "techniques/vsv/grid_readback.h"
#include "techniques/vsv/stiff_bounds.h"
#include "techniques/vsv/vpl_sampling.h"
#include "techniques/vsv/vsv.h"

namespace viz {
namespace {

// ---- ids (stable: lessons and tests use them) ----
constexpr const char* kStageVpls = "ivsv.vpls";
constexpr const char* kStageShadows = "ivsv.shadow_maps";
constexpr const char* kStageSurface = "ivsv.surface";
constexpr const char* kStageVoxelize = "ivsv.voxelize";
constexpr const char* kStageScan = "ivsv.scan";
constexpr const char* kStageGather = "ivsv.gather";
constexpr const char* kVplImage = "ivsv.vpl_positions";
constexpr const char* kPointCloud = "ivsv.point_cloud";
constexpr const char* kIsmRaw = "ivsv.ism_splatted";
constexpr const char* kIsm = "ivsv.ism";
constexpr const char* kVoxelSlice = "ivsv.voxels";
constexpr const char* kScanSlice = "ivsv.scanned";
constexpr const char* kColumn = "ivsv.column";
constexpr const char* kAirlight = "ivsv.airlight";
constexpr const char* kVisibility = "ivsv.visibility";
constexpr const char* kPerVpl = "ivsv.pixel_vpls";
constexpr const char* kInterleave = "ivsv.interleave";

enum StageIndex {
    kVplsIndex = 0,
    kShadowsIndex = 1,
    kSurfaceIndex = 2,
    kVoxelizeIndex = 3,
    kScanIndex = 4,
    kGatherIndex = 5,
    kComposeIndex = 6
};

constexpr int kPhiBits = 128;  // one texel per eye ray, as the paper's implementation
constexpr int kMaxVpls = 256;
constexpr int kMaxScanPasses = 9;
constexpr double kVplOffset = 5e-3;  // VPLs sit this far in front of the emitter (scene units)

enum GatherMode { kGatherFull = 0, kGatherInterleaved = 1, kGatherQuarter = 2 };

// One VPL and its epipolar space, std430 (shaders/vsv/ivsv_vpls.glsl).
struct GpuVpl {
    glm::vec4 position, normal, tangent, bitangent, weight;
    glm::vec4 epiB, epiU, epiV, epiAlpha, epiTheta, epiPhi;
    glm::ivec4 tile, extra;
};
static_assert(sizeof(GpuVpl) == 13 * 16);

const std::map<std::string, std::pair<const char*, const char*>> kDefines = {
    {"COMBINE_EXACT", {"COMBINE_EXACT", nullptr}},
    {"INTERP", {"INTERP", nullptr}},
};

using vsv::scanPassCount;

// The scene's area light (ivsv shades one), or nullptr; every other light goes to an inner vsv.
const scene::Light* areaLightOf(const scene::Scene& scene) {
    const scene::Light* area = nullptr;
    for (const scene::Light& l : scene.lights) {
        if (l.type != scene::LightType::Area) continue;
        if (area) throw InputError("ivsv: the scene has more than one area light ('" + area->name + "', '" + l.name +
                                   "'); ivsv shades one");
        area = &l;
    }
    return area;
}

// The scene with only its point, spot and directional lights (shaded by vsv inside ivsv).
scene::Scene withoutAreaLights(const scene::Scene& scene) {
    scene::Scene out = scene;
    out.lights.clear();
    for (const scene::Light& l : scene.lights)
        if (l.type != scene::LightType::Area) out.lights.push_back(l);
    return out;
}

class IvsvTechnique final : public Technique {
public:
    IvsvTechnique() {
        mParams = {
            {"vpls", "virtual point lights on the area light (Halton points)", 64, 1, kMaxVpls, true},
            {"voxels", "alpha and theta cells per VPL grid (phi is 128 bits)", 128, 16, 512, true},
            {"combine", "fraction: lit fraction x unshadowed airlight; exact: each quadrature node weighted by the "
                        "visibility of its own bits",
             1, 0, 1, true, {"fraction", "exact"}},
            {"gather", "full: every pixel x every VPL; interleaved: 1/9 of the VPLs per pixel + 3x3 bilateral; "
                       "quarter: half width and height + bilateral upsampling",
             0, 0, 2, true, {"full", "interleaved", "quarter"}},
            {"mode", "imperfect: ISMs and one pass per step for all VPLs; naive: cube shadow maps and a full VSV "
                     "per VPL",
             0, 0, 1, true, {"imperfect", "naive"}},
            {"points", "point cloud size for the imperfect shadow maps (split among the VPLs)", 1 << 20, 1024,
             1 << 23, true},
            {"fill_levels", "push-pull fills a hole only from a sample within 2^k texels of it (k levels up the "
                            "pyramid); wider holes stay empty, so directions that see nothing (open sky) stay lit",
             2, 0, 12, true},
            {"alpha_bias", "occluder alpha offset in cells (negative: shadow starts further from the light)", -2.25,
             -16, 16, false},
            {"phi_bias", "light-ray phi offset in cells (negative: shadow moves away from the eye)", -1, -16, 16,
             false},
            {"interp", "1: two texels along theta; 0: nearest", 1, 0, 1, true},
            {"chunk_bits", "phi bits per quadrature node of the airlight (1, 2, 4, ..., 128)", 8, 1, 128, true},
            {"vpl_disc", "near the emitter each VPL acts as a disc of this many times its area (bounds the 1/r^2 "
                         "spike of rays grazing it); 0: points",
             1, 0, 16, false},
            {"bilateral_sigma", "distance tolerance of the bilateral filters, relative to d", 0.1, 0.001, 10, false},
            {"scan_passes", "stop the segmented alpha scan after this many passes (-1: all; stepping)", -1, -1,
             kMaxScanPasses, true},
            {"vpl_step", "gather only VPLs 0 .. k (-1: all; stepping VPL by VPL)", -1, -1, kMaxVpls - 1, true},
            {"pick_vpl", "VPL whose shadow map, grid and column the intermediates show", 0, 0, kMaxVpls - 1, true},
            {"pick_x", "pixel whose voxel column and per-VPL contributions are shown (-1: centre)", -1, -1, 1e6, true},
            {"pick_y", "pixel row (0 = top) (-1: centre)", -1, -1, 1e6, true},
            {"pick_theta", "theta cell of the unwrapped alpha x phi slices (-1: that of the picked pixel)", -1, -1, 512,
             true},
        };
        for (ParamInfo p : render::SceneViewPasses::params()) {
            if (p.name == "shadow_map") {
                p.help = "imperfect shadow-map tile / naive cube-face size in texels (power of two <= 512)";
                p.defaultValue = 128;
            }
            mParams.push_back(std::move(p));
        }
        mParams.push_back(forceFeaturesParam());
        mStages = {
            {kStageVpls, "VPLs", "Halton points on the area light: position, normal, L_e dA from the emission texture",
             {"vpls"}, {kVplImage}, 1},
            {kStageShadows, "Shadow maps",
             "imperfect: point cloud subsets splatted into one paraboloid tile per VPL, push-pull hole filling; "
             "naive: a cube shadow map per VPL",
             {"mode", "points", "fill_levels", "shadow_map"}, {kPointCloud, kIsmRaw, kIsm, "ivsv.naive.shadow_map"}, 1},
            {kStageSurface, "Camera view",
             "the shared surface term: its own shadow maps, distance d and surface radiance", {"area_samples"},
             {"ivsv.shadow_map", "ivsv.distance", "ivsv.surface"}, 1},
            {kStageVoxelize, "Rectify",
             "every VPL's shadow map resampled into its own epipolar grid tile (one pass, or one per VPL for naive)",
             {"voxels", "alpha_bias", "phi_bias", "pick_vpl", "pick_theta"}, {kVoxelSlice}, 1},
            {kStageScan, "Extrude (segmented scan)", "prefix OR along alpha restarting at every tile boundary",
             {"scan_passes"}, {kScanSlice}, kMaxScanPasses, "scan_passes"},
            {kStageGather, "Gather", "per pixel: sum over VPLs of visibility x airlight (full, interleaved, quarter)",
             {"combine", "gather", "interp", "chunk_bits", "vpl_disc", "bilateral_sigma", "vpl_step", "pick_x", "pick_y",
              "force_features"},
             {kColumn, kPerVpl, kInterleave, kAirlight, kVisibility}, 1, "vpl_step"},
            render::SceneViewPasses::composeStage("ivsv"),
        };
    }

    // Stepping: the segmented scan pass by pass (scan_passes = 0 before any pass, 1, ..., then -1 = all),
    // and the gather VPL by VPL (vpl_step = 0 gathers VPL 0 only, 1 adds VPL 1, ..., then -1 = all).
    std::vector<double> substepValues(int stage, const Settings& s) const override {
        std::vector<double> values;
        if (stage == kScanIndex) {
            for (int k = 0; k < scanPassCount(int(s.at("voxels"))); ++k) values.push_back(double(k));
        } else if (stage == kGatherIndex) {
            for (int k = 0; k + 1 < int(s.at("vpls")); ++k) values.push_back(double(k));
        } else {
            return Technique::substepValues(stage, s);
        }
        values.push_back(-1.0);
        return values;
    }

    std::string id() const override { return "ivsv"; }
    std::string description() const override {
        return "imperfect voxelized shadow volumes (Wyman and Dai 2013): area lights as many VPL shadow volumes";
    }
    const std::vector<StageInfo>& stages() const override { return mStages; }
    const std::vector<ParamInfo>& params() const override { return mParams; }
    bool needsGl() const override { return true; }

    // VPL count (the area light's sampling) and voxel resolution (each VPL grid's), issue 9's knobs:
    // cheapest first. On a scene without an area light only `voxels` matters (the inner vsv).
    std::vector<QualitySetting> qualitySweep(bool quick) const override {
        const std::vector<std::pair<int, int>> steps =
            quick ? std::vector<std::pair<int, int>>{{4, 64}, {16, 128}, {64, 128}}
                  : std::vector<std::pair<int, int>>{{4, 64}, {16, 64}, {16, 128}, {64, 128}, {256, 128}, {256, 256}};
        std::vector<QualitySetting> sweep;
        for (const auto& [vpls, voxels] : steps)
            sweep.push_back({"vpls=" + std::to_string(vpls) + " voxels=" + std::to_string(voxels),
                             {{"vpls", double(vpls)}, {"voxels", double(voxels)}}});
        return sweep;
    }

    // The stiff cases have no area light: ivsv hands every light to its inner vsv at this resolution.
    Settings stiffSettings() const override { return {{"voxels", 512.0}, {"vpls", 256.0}}; }
    // Wyman and Dai 2013: 256 VPLs with imperfect shadow maps, the lit fraction, the 3x3 interleaved
    // gather with its bilateral filter (ours offers it or the quarter-size gather, not both at once).
    Settings paperSettings() const override {
        return {{"vpls", 256.0}, {"mode", 0.0}, {"combine", 0.0}, {"gather", 1.0}};
    }
    std::optional<StiffBound> stiffBound(const std::string& caseClass) const override {
        return vsv::stiffBound(caseClass);
    }

    Plan plan(const scene::Scene& scene, const Settings& settings) const override {
        const bool hasArea = areaLightOf(scene) != nullptr;
        const bool hasOthers = int(scene.lights.size()) > (hasArea ? 1 : 0);
        checkTileSize(settings);
        Plan p;
        for (const StageInfo& st : mStages) p.stages.push_back({st.id, true, ""});
        if (!hasArea) {
            for (int i : {kVplsIndex, kShadowsIndex, kVoxelizeIndex, kScanIndex}) {
                p.stages[std::size_t(i)].runs = false;
                p.stages[std::size_t(i)].why = "no area light: nothing to split into VPLs";
            }
        }
        const bool naive = settings.at("mode") != 0.0;
        const int vpls = int(settings.at("vpls"));
        if (scene.medium.sigma_s == 0.0) {
            p.stages[kGatherIndex].runs = false;
            p.stages[kGatherIndex].why = "sigma_s = 0: the medium scatters nothing, L_air = 0";
        }
        if (hasArea) {
            p.stages[kShadowsIndex].why = naive ? std::to_string(vpls) + " cube shadow maps, one per VPL"
                                                : "one ISM atlas of " + std::to_string(vpls) + " tiles";
            p.stages[kScanIndex].why = std::to_string(scanPassCount(int(settings.at("voxels")))) + " passes" +
                                       (naive ? " per VPL" : " over all tiles at once");
        }
        const bool exact = settings.at("combine") != 0.0;
        const bool interp = settings.at("interp") != 0.0;
        const int gather = int(settings.at("gather"));
        p.features.push_back({"VPL_PIPELINE", hasArea,
                              hasArea ? "the area light becomes " + std::to_string(vpls) + " VPLs" : "no area light"});
        p.features.push_back({"OTHER_LIGHTS_BY_VSV", hasOthers,
                              hasOthers ? "point, spot and directional lights: one vsv grid each (in the gather stage)"
                                        : "the scene has only its area light"});
        p.features.push_back({"IMPERFECT_SHADOW_MAPS", !naive,
                              naive ? "mode=naive: rasterized cube maps per VPL (compiled in: CUBE)"
                                    : "point-cloud splats + push-pull (the rectification reads the atlas)"});
        p.features.push_back({"BATCHED_PASSES", !naive,
                              naive ? "mode=naive: voxelize, scan and gather run once per VPL"
                                    : "one rectification, one segmented scan and one gather for all VPLs"});
        p.features.push_back({"COMBINE_EXACT", exact,
                              exact ? "each phi quadrature node weighted by the lit fraction of its own bits"
                                    : "combine=fraction: lit fraction x unshadowed airlight per VPL"});
        p.features.push_back({"INTERP", interp, interp ? "two texels along theta" : "nearest texel"});
        p.features.push_back({"INTERLEAVED_GATHER", gather == kGatherInterleaved,
                              gather == kGatherInterleaved ? "1/9 of the VPLs per pixel, 3x3 bilateral filter"
                                                           : "every pixel gathers its VPLs"});
        p.features.push_back({"QUARTER_GATHER", gather == kGatherQuarter,
                              gather == kGatherQuarter ? "half width and height, bilateral upsampling"
                                                       : "full-resolution gather"});
        render::planCulledLights(scene, p);
        // Scene-pruned: the inner vsv without other lights (force_features=1 runs it on none: it adds zero).
        forcePlan(p, settings.at("force_features") != 0.0, {"OTHER_LIGHTS_BY_VSV"});
        for (FeaturePlan& f : p.features) {
            const auto it = kDefines.find(f.feature);
            const char* define = it == kDefines.end() ? nullptr : (f.enabled ? it->second.first : it->second.second);
            if (define) f.why += std::string(f.enabled ? " (compiled in: " : " (compiled out: ") + define + ")";
        }
        return p;
    }

    FrameOutput run(const FrameInput& input) override {
        const scene::Scene& scene = *input.scene;
        const Settings& s = input.settings;
        FrameOutput out;
        out.plan = plan(scene, s);
        out.timing.clock = gl::StageClock::method();
        const int stop = input.stopAfterStage < 0 ? kComposeIndex : input.stopAfterStage;
        const scene::Light* area = areaLightOf(scene);
        const bool naive = s.at("mode") != 0.0;
        const int count = area ? int(s.at("vpls")) : 0;
        const int cells = int(s.at("voxels"));
        const int tile = int(s.at("shadow_map"));
        const int shown = std::max(0, std::min(int(s.at("pick_vpl")), count - 1));
        gl::StageClock clock;
        mSurfaceRan = mNaiveBuilt = false;
        mMark.reset();

        // ---- VPLs and their epipolar spaces ----
        clock.begin();
        mVpls.clear();
        if (area) {
            mVpls = vsv::sampleVpls(scene, *area, count);
            mVplArea = 4.0 * glm::length(glm::cross(area->halfU, area->halfV)) / count;
            for (vsv::Vpl& v : mVpls) v.position += kVplOffset * v.normal;
        }
        layOut(std::max(count, 1), cells, tile);
        uploadVpls(scene, input.width, input.height, cells, tile);
        out.timing.stages.push_back({kStageVpls, clock.endMilliseconds()});
        if (area)
            out.intermediates.push_back(vsv::cpuIntermediate(
                kVplImage, "VPLs on the emitter", "emitter uv square (u right, v down): each VPL's L_e as a dot",
                ViewKind::Color, vplImage()));
        if (area) out.intermediates.back().picture = true;
        out.lastStageRun = kVplsIndex;
        if (stop == kVplsIndex) return out;

        // ---- shadow maps ----
        clock.begin();
        if (area && naive) {
            scene::Scene points = scene;
            points.lights.clear();
            for (int i = 0; i < count; ++i) {
                scene::Light l;
                l.name = "vpl" + std::to_string(i);
                l.type = scene::LightType::Point;
                l.position = mVpls[std::size_t(i)].position;
                points.lights.push_back(l);
            }
            mNaiveView.buildShadows(points, tile, 1, out.intermediates, "ivsv.naive");
            mNaiveBuilt = true;
        } else if (area) {
            buildIsm(scene, *area, int(s.at("points")), count, tile, int(s.at("fill_levels")));
        }
        out.timing.stages.push_back({kStageShadows, clock.endMilliseconds()});
        if (area && !naive) {
            out.intermediates.push_back(render::textureIntermediate(
                kIsmRaw, "ISM atlas (splatted)", "one paraboloid tile per VPL: distance of the nearest point, 0 = hole",
                "scene units", ViewKind::Depth, 0.0f, 8.0f, mIsmRaw));
            out.intermediates.back().sentinels = {{0.0f, "hole: no point splatted"}};
            out.intermediates.push_back(render::textureIntermediate(
                kIsm, "ISM atlas (after push-pull)", "holes filled from coarser levels (mean of valid samples)",
                "scene units", ViewKind::Depth, 0.0f, 8.0f, mIsm));
            out.intermediates.push_back(vsv::cpuIntermediate(
                kPointCloud, "Point cloud of VPL " + std::to_string(shown),
                "the subset of the scene's points splatted into its tile, seen from the camera (nearest distance)",
                ViewKind::Depth, pointCloudImage(scene, input.width, input.height, shown, count), 0.0f, 8.0f));
        }
        out.lastStageRun = kShadowsIndex;
        if (stop == kShadowsIndex) return out;

        // ---- camera view (the shared surface term) ----
        clock.begin();
        mView.buildShadows(scene, s, out.intermediates, "ivsv");
        mView.renderSurface(scene, input.width, input.height, out.intermediates, "ivsv");
        mSurfaceRan = true;
        out.timing.stages.push_back({kStageSurface, clock.endMilliseconds()});
        out.lastStageRun = kSurfaceIndex;
        if (stop == kSurfaceIndex) return out;

        const int pickX = s.at("pick_x") < 0 ? input.width / 2 : std::min(int(s.at("pick_x")), input.width - 1);
        const int pickY = s.at("pick_y") < 0 ? input.height / 2 : std::min(int(s.at("pick_y")), input.height - 1);
        const glm::dvec3 pickRay = scene::pixelRay(scene.camera, input.width, input.height, pickX, pickY);
        int pickTheta = 0;
        if (area) {
            const vsv::EpipolarFrame f = vsv::makeFrame(mVpls[std::size_t(shown)].position - scene.camera.position);
            const vsv::EpipolarGrid& g = mGrids[std::size_t(shown)];
            pickTheta = std::clamp(int(std::floor(vsv::thetaCoord(g, vsv::thetaOf(f, pickRay)))), 0, cells - 1);
        }
        if (s.at("pick_theta") >= 0) pickTheta = std::min(int(s.at("pick_theta")), cells - 1);
        const glm::ivec2 shownTile = tileOrigin(shown, cells);
        if (area) mMark = MarkState{shown, pickTheta, tile, naive, scene.camera.position};

        // ---- rectify ----
        clock.begin();
        if (area) rectify(s, count, cells, tile, naive);
        out.timing.stages.push_back({kStageVoxelize, clock.endMilliseconds()});
        if (area)
            out.intermediates.push_back(vsv::cpuIntermediate(
            kVoxelSlice, "Voxels of VPL " + std::to_string(shown) + " (before scan)",
            "alpha (x) x phi (y, eye at the top) at theta cell " + std::to_string(pickTheta) + ": white = occluder",
            ViewKind::BitField, vsv::sliceImage(mGrid, shownTile.x, cells, shownTile.y + pickTheta, kPhiBits)));
        out.lastStageRun = kVoxelizeIndex;
        if (stop == kVoxelizeIndex) return out;

        // The picked pixel's column as voxelized, for the gather's column view (the scan overwrites the
        // grid); read only when the gather will run.
        if (area && stop != kScanIndex) {
            const glm::ivec2 cell = pickedCell(scene, input, shown, cells, pickX, pickY);
            mPreScanColumn = vsv::readGridRow(mGrid, shownTile.x + cell.x, 1, shownTile.y + cell.y).front();
        }

        // ---- segmented scan ----
        clock.begin();
        const int passSetting = int(substepLimit(input, kScanIndex));
        const int passLimit = passSetting < 0 ? kMaxScanPasses : passSetting;
        if (area) scan(count, cells, passLimit, naive);
        out.timing.stages.push_back({kStageScan, clock.endMilliseconds()});
        if (area)
            out.intermediates.push_back(vsv::cpuIntermediate(
            kScanSlice,
            "Voxels of VPL " + std::to_string(shown) + " after " +
                std::to_string(std::min(passLimit, scanPassCount(cells))) + " scan passes",
            "alpha x phi at theta cell " + std::to_string(pickTheta) + ": white = shadowed", ViewKind::BitField,
            vsv::sliceImage(*mResult, shownTile.x, cells, shownTile.y + pickTheta, kPhiBits)));
        out.lastStageRun = kScanIndex;
        if (stop == kScanIndex) return out;

        // ---- gather ----
        clock.begin();
        const int gatherMode = int(s.at("gather"));
        const int vplStep = int(substepLimit(input, kGatherIndex));
        const int gathered = vplStep < 0 ? count : std::min(count, vplStep + 1);
        allocateOutputs(input.width, input.height);
        mPick.clearZero();
        if (area && out.plan.stages[kGatherIndex].runs) {
            gather(scene, input, gatherMode, gathered, cells, naive, {pickX, input.height - 1 - pickY});
        } else {
            mAirlight.clear(glm::vec4(0.0f));
            mVisibility.clear(glm::vec4(1.0f));
        }
        // Point, spot and directional lights: vsv, added to the VPLs' airlight.
        if (otherLightsOn(out.plan) && out.plan.stages[kGatherIndex].runs) addOtherLights(input);
        out.timing.stages.push_back({kStageGather, clock.endMilliseconds()});
        if (area) {
            out.intermediates.push_back(vsv::cpuIntermediate(
                kColumn, "Voxel column of pixel (" + std::to_string(pickX) + ", " + std::to_string(pickY) + "), VPL " +
                             std::to_string(shown),
                "its 128 phi bits; top row as voxelized (1 occluder), bottom row after the scan (1 shadowed, 0 lit); "
                "0.5 beyond the fragment (not read)", ViewKind::BitField,
                columnImage(scene, input, shown, cells, pickX, pickY)));
            out.intermediates.back().rayView = true;
            const std::shared_ptr<Image> perVpl = perVplImage(count);
            out.intermediates.push_back(vsv::cpuIntermediate(
                kPerVpl, "Per-VPL airlight of pixel (" + std::to_string(pickX) + ", " + std::to_string(pickY) + ")",
                "x = VPL index: its unscaled contribution to L_air (only VPLs this pixel gathered)", ViewKind::Color,
                perVpl, 0.0f, 0.0f));
            out.intermediates.back().plots = {perVplPlot(*perVpl)};
            out.intermediates.back().rayView = true;
            out.intermediates.push_back(vsv::cpuIntermediate(
                kInterleave, "Interleaving pattern", "which ninth of the VPLs each pixel gathers (0..8 / 8)",
                ViewKind::Scalar, interleaveImage(input.width, input.height, gatherMode)));
        }
        out.intermediates.push_back(render::textureIntermediate(
            kAirlight, "L_air", "single-scattered light reaching the eye", "radiance", ViewKind::Color, 0.0f, 1.0f,
            mAirlight));
        out.intermediates.push_back(render::textureIntermediate(
            kVisibility, "Visibility", "mean over the gathered VPLs of the phi-uniform lit fraction of the ray", "",
            ViewKind::Scalar, 0.0f, 1.0f, mVisibility));
        out.airlight = render::readRgb(mAirlight);
        out.lastStageRun = kGatherIndex;
        if (stop == kGatherIndex) return out;

        // ---- compose ----
        clock.begin();
        out.final = mView.compose(scene, mAirlight, out.intermediates, "ivsv");
        out.timing.stages.push_back({mStages[kComposeIndex].id, clock.endMilliseconds()});
        out.lastStageRun = kComposeIndex;
        return out;
    }

    // Linked cursors (once the camera view ran: the eye ray ends at the pixel's surface): in the shadow
    // maps, the eye ray and its lit/shadow changes by the map's own test (render/shadow_map_markers.h).
    std::vector<ViewMarker> markersFor(glm::ivec2 pixel, const std::string& id) const override {
        if (!mSurfaceRan) return {};
        if (render::shadowMapIndexOf(id, "ivsv") >= 0) return mView.shadowMapMarkers(pixel, id, "ivsv");
        const int naive = render::shadowMapIndexOf(id, "ivsv.naive");
        if (naive >= 0) {
            // mode=naive: VPL i as point light i; the same eye, so the same eye-relative space.
            const auto& lights = mNaiveView.lights().lights();
            glm::dvec3 w;
            double tEnd = 0.0;
            if (!mNaiveBuilt || naive >= int(lights.size()) || lights[std::size_t(naive)].info.z < 0 ||
                !mView.pixelRay(pixel, w, tEnd))
                return {};
            return render::shadowMapMarkers(mNaiveView.shadows(), lights[std::size_t(naive)], w, tEnd);
        }
        if (!mMark) return {};
        const MarkState& m = *mMark;
        glm::dvec3 w;
        double d = 0.0;
        if (!mView.pixelRay(pixel, w, d)) return {};
        const vsv::Vpl& vpl = mVpls[std::size_t(m.shown)];
        if (id == kVoxelSlice || id == kScanSlice) {
            // As vsv: the slices show theta cell pickTheta of the shown VPL's grid (alpha x, phi y); the eye
            // ray is the column at its alpha when its theta cell is that one.
            const vsv::EpipolarFrame f = vsv::makeFrame(vpl.position - m.eye);
            const vsv::EpipolarGrid& g = mGrids[std::size_t(m.shown)];
            const int theta = int(std::floor(vsv::thetaCoord(g, vsv::thetaOf(f, w))));
            if (theta != m.pickTheta) return {};
            const double alpha = vsv::alphaCoord(g, vsv::alphaOf(f, w));
            if (alpha < 0.0 || alpha >= double(g.nAlpha)) return {};
            const float u = float(alpha) / float(g.nAlpha);
            return {{{u, 0.0f}, {u, 1.0f}, "eye ray, alpha cell " + std::to_string(int(alpha))}};
        }
        if ((id == kIsm || id == kIsmRaw) && !m.naive) return ismMarkers(m, vpl, w, d);
        return {};
    }

private:
    // What markersFor needs of the last run (set once the VPLs' grids exist).
    struct MarkState {
        int shown = 0, pickTheta = 0, tile = 0;
        bool naive = false;
        glm::dvec3 eye{0.0};  // world position of the camera: the VPLs are in world space
    };
    std::optional<MarkState> mMark;

    // The eye ray t w, t in [0, d], in the shown VPL's paraboloid tile of the ISM atlas: a curve, drawn as
    // a polyline of the parts in its hemisphere (shaders/vsv/ism.glsl: uv = (x, y) / (1 + z) in the VPL's
    // frame, texel = tile origin + (uv / 2 + 1 / 2) tile size; data uv = texel / atlas size, GL rows).
    std::vector<ViewMarker> ismMarkers(const MarkState& m, const vsv::Vpl& vpl, const glm::dvec3& w, double d) const {
        glm::dvec3 tx, ty;
        vsv::hemisphereFrame(vpl.normal, tx, ty);
        const glm::dvec3 from = vpl.position - m.eye;  // eye-relative
        const glm::dvec2 origin(tileOrigin(m.shown, m.tile));
        const glm::dvec2 atlas(double(mTilesX * m.tile), double(mTilesY * m.tile));
        const auto project = [&](double t, glm::vec2& uv) {
            const glm::dvec3 v = t * w - from;
            const double len = glm::length(v);
            if (len <= 0.0) return false;
            const glm::dvec3 local(glm::dot(v, tx) / len, glm::dot(v, ty) / len, glm::dot(v, vpl.normal) / len);
            if (local.z <= 0.0) return false;
            const glm::dvec2 texel = origin + (vsv::paraboloid(local) * 0.5 + 0.5) * double(m.tile);
            uv = glm::vec2(texel / atlas);
            return true;
        };
        constexpr int kPieces = 48;
        std::vector<ViewMarker> marks;
        glm::vec2 previous(0.0f);
        bool previousIn = project(0.0, previous);
        for (int k = 1; k <= kPieces; ++k) {
            glm::vec2 uv(0.0f);
            const bool in = project(d * double(k) / kPieces, uv);
            if (in && previousIn) {
                char text[96];
                text[0] = 0;
                if (marks.empty()) std::snprintf(text, sizeof text, "eye ray t=0..%.2f, VPL %d", d, m.shown);
                marks.push_back({previous, uv, text});
            }
            previous = uv;
            previousIn = in;
        }
        return marks;
    }

    static void checkTileSize(const Settings& s) {
        const int t = int(s.at("shadow_map"));
        if (t > 512 || (t & (t - 1)) != 0)
            throw InputError("ivsv: shadow_map (" + std::to_string(t) + ") must be a power of two <= 512");
    }

    glm::ivec2 tileOrigin(int i, int size) const { return {(i % mTilesX) * size, (i / mTilesX) * size}; }

    void layOut(int count, int cells, int tile) {
        mTilesX = int(std::ceil(std::sqrt(double(count))));
        mTilesY = (count + mTilesX - 1) / mTilesX;
        const glm::ivec3 gridSize(mTilesX * cells, mTilesY * cells, 1);
        if (!mGrid || mGrid.size() != gridSize) {
            mGrid = gl::Texture::create({.target = GL_TEXTURE_2D_ARRAY, .format = GL_RGBA32UI, .size = gridSize,
                                         .levels = 1, .label = "ivsv.grid"});
            mPong = gl::Texture::create({.target = GL_TEXTURE_2D_ARRAY, .format = GL_RGBA32UI, .size = gridSize,
                                         .levels = 1, .label = "ivsv.grid_pong"});
            mWords = gl::Texture::create({.target = GL_TEXTURE_2D_ARRAY, .format = GL_R32UI,
                                          .size = {gridSize.x, gridSize.y, 4}, .levels = 1, .label = "ivsv.words"});
        }
        const glm::ivec3 ismSize(mTilesX * tile, mTilesY * tile, 1);
        if (!mIsm || mIsm.size() != ismSize) {
            const int levels = scanPassCount(tile) + 1;
            mIsmBits = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_R32UI, .size = ismSize, .levels = 1,
                                            .label = "ivsv.ism_bits"});
            mIsmRaw = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_R32F, .size = ismSize, .levels = 1,
                                           .label = kIsmRaw});
            mIsm = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_R32F, .size = ismSize, .levels = levels,
                                        .label = kIsm});
        }
        if (!mVplBuffer) {
            mVplBuffer = gl::Buffer::create({.bytes = kMaxVpls * sizeof(GpuVpl), .label = "ivsv.vpls"});
            mPick = gl::Buffer::create({.bytes = kMaxVpls * sizeof(glm::vec4), .label = "ivsv.pick"});
        }
        if (!mSplat) {
            mSplat = gl::Program::compile({.stages = {"vsv/ism_splat.comp"}, .label = "ivsv.ism_splat"});
            mPushPull = gl::Program::compile({.stages = {"vsv/ism_pushpull.comp"}, .label = "ivsv.ism_pushpull"});
            mRectifyIsm = gl::Program::compile({.stages = {"vsv/ivsv_voxelize.comp"}, .label = "ivsv.rectify"});
            mRectifyCube = gl::Program::compile(
                {.stages = {"vsv/ivsv_voxelize.comp"}, .defines = {{"CUBE", "1"}}, .label = "ivsv.rectify_cube"});
            mPack = gl::Program::compile({.stages = {"vsv/pack.comp"}, .label = "ivsv.pack"});
            mScan = gl::Program::compile({.stages = {"vsv/scan.comp"}, .label = "ivsv.scan"});
            mBilateral = gl::Program::compile({.stages = {"vsv/bilateral.comp"}, .label = "ivsv.bilateral"});
        }
    }

    // Each VPL's epipolar grid covers what the camera sees of its hemisphere (a cone of half angle pi/2
    // around its normal narrows phi, as a spot's cone does for vsv).
    void uploadVpls(const scene::Scene& scene, int width, int height, int cells, int tile) {
        mGrids.clear();
        std::vector<GpuVpl> gpu;
        const vsv::CameraRays cam = vsv::cameraRays(scene.camera, width, height);
        for (int i = 0; i < int(mVpls.size()); ++i) {
            const vsv::Vpl& v = mVpls[std::size_t(i)];
            const glm::dvec3 rel = v.position - scene.camera.position;
            const vsv::EpipolarFrame f = vsv::makeFrame(rel);
            vsv::SpotCone cone;
            cone.present = true;
            cone.axis = v.normal;
            cone.outer = 0.5 * std::numbers::pi;
            const vsv::EpipolarGrid g = vsv::selectRanges(f, cam, scene.camera.zfar, cone, cells, cells, kPhiBits);
            mGrids.push_back(g);
            glm::dvec3 tx, ty;
            vsv::hemisphereFrame(v.normal, tx, ty);
            GpuVpl o{};
            o.position = glm::vec4(glm::vec3(rel), 0.0f);
            o.normal = glm::vec4(glm::vec3(v.normal), 0.0f);
            o.tangent = glm::vec4(glm::vec3(tx), 0.0f);
            o.bitangent = glm::vec4(glm::vec3(ty), 0.0f);
            o.weight = glm::vec4(glm::vec3(v.weight), float(mVplArea / std::numbers::pi));
            o.epiB = glm::vec4(glm::vec3(f.b), float(f.D));
            o.epiU = glm::vec4(glm::vec3(f.u), 0.0f);
            o.epiV = glm::vec4(glm::vec3(f.v), 0.0f);
            o.epiAlpha = glm::vec4(float(g.alpha0), float(g.dAlpha()), 0.0f, 0.0f);
            o.epiTheta = glm::vec4(float(g.thetaCentre), float(g.thetaHalf), float(g.dTheta()), g.thetaFull ? 1.0f : 0.0f);
            o.epiPhi = glm::vec4(float(g.phi0), float(g.dPhi()), 0.0f, 0.0f);
            o.tile = glm::ivec4(tileOrigin(i, cells), tileOrigin(i, tile));
            o.extra = glm::ivec4(i, 0, 0, 0);  // mode=naive: VPL i is point light i, cube i
            gpu.push_back(o);
        }
        if (!gpu.empty()) mVplBuffer.upload(0, gpu.size() * sizeof(GpuVpl), gpu.data());
    }

    // The point cloud is sampled once per scene and size; each splat pass uses all of it.
    void buildIsm(const scene::Scene& scene, const scene::Light& light, int points, int count, int tile, int fillLevels) {
        const std::size_t key = render::geometryFingerprint(scene) ^ (std::size_t(points) * 2654435761u);
        if (key != mPointsKey || &scene != mPointsScene) {
            mCloudWorld = vsv::samplePointCloud(scene, points, light.mesh);
            mPointsKey = key;
            mPointsScene = &scene;
            mCloud.clear();
        }
        // Uploaded eye-relative, like every position the shaders see; again when the camera moved.
        if (mCloud.empty() || mCloudEye != scene.camera.position) {
            mCloud.clear();
            for (const glm::dvec3& p : mCloudWorld) mCloud.emplace_back(glm::vec3(p - scene.camera.position), 1.0f);
            if (mCloud.empty()) mCloud.emplace_back(0.0f);
            mPoints = gl::Buffer::create(
                {.bytes = mCloud.size() * sizeof(glm::vec4), .data = mCloud.data(), .label = kPointCloud});
            mCloudEye = scene.camera.position;
        }
        const GLuint empty = 0xffffffffu;
        mIsmBits.clear(GL_RED_INTEGER, GL_UNSIGNED_INT, &empty);
        mSplat.use();
        mSplat.set("uPointCount", int(mCloudWorld.size()));
        mSplat.set("uVplCount", count);
        mSplat.set("uTileSize", tile);
        mVplBuffer.bindBase(GL_SHADER_STORAGE_BUFFER, 4);
        mPoints.bindBase(GL_SHADER_STORAGE_BUFFER, 5);
        mIsmBits.bindImage(0, GL_READ_WRITE);
        glDispatchCompute(GLuint((mCloud.size() + 63) / 64), 1, 1);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);

        // Push-pull only over the rows of tiles holding VPLs.
        const glm::ivec2 used(mTilesX * tile, mTilesY * tile);
        mPushPull.use();
        auto dispatch = [&](glm::ivec2 size) {
            mPushPull.set("uSize", size);
            const glm::ivec3 groups = gl::groupCount({size.x, size.y, 1}, mPushPull.workGroupSize());
            glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
            glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
        };
        mPushPull.set("uMode", 0);
        mIsmBits.bindImage(0, GL_READ_ONLY);
        mIsm.bindImage(1, GL_READ_WRITE, 0);
        mIsm.bindImage(2, GL_READ_WRITE, 0);
        mIsmRaw.bindImage(3, GL_WRITE_ONLY);
        dispatch(used);
        const int levels = mIsm.levels();
        mPushPull.set("uMode", 1);
        for (int l = 0; l + 1 < levels; ++l) {
            mIsm.bindImage(1, GL_READ_WRITE, l);
            mIsm.bindImage(2, GL_READ_WRITE, l + 1);
            dispatch(used >> (l + 1));
        }
        mPushPull.set("uMode", 2);
        mPushPull.set("uFillLevels", fillLevels);
        for (int l = levels - 2; l >= 0; --l) {
            mPushPull.set("uLevel", l);
            mIsm.bindImage(1, GL_READ_WRITE, l);
            mIsm.bindImage(2, GL_READ_WRITE, l + 1);
            dispatch(used >> l);
        }
    }

    void setRectifyCommon(const gl::Program& p, const Settings& s, int cells, int tile) const {
        p.use();
        p.set("uCells", glm::ivec3(cells, cells, kPhiBits));
        p.set("uTileSize", tile);
        p.set("uAlphaBias", float(s.at("alpha_bias")));
        p.set("uPhiBias", float(s.at("phi_bias")));
    }

    void rectify(const Settings& s, int count, int cells, int tile, bool naive) {
        const GLuint zero = 0;
        mWords.clear(GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
        mVplBuffer.bindBase(GL_SHADER_STORAGE_BUFFER, 4);
        mWords.bindImage(0, GL_READ_WRITE);
        const glm::ivec3 groups = gl::groupCount({kPhiBits, cells, 1}, glm::ivec3(8, 8, 1));
        if (naive) {
            mNaiveView.shadows().bind();
            setRectifyCommon(mRectifyCube, s, cells, tile);
            for (int i = 0; i < count; ++i) {
                mRectifyCube.set("uFirstVpl", i);
                glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
                glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
                pack(tileOrigin(i, cells), {cells, cells, 1});
                mRectifyCube.use();
                mWords.bindImage(0, GL_READ_WRITE);
            }
        } else {
            mIsm.bindUnit(render::hd::kFirstFreeTextureUnit + 1);
            setRectifyCommon(mRectifyIsm, s, cells, tile);
            mRectifyIsm.set("uFirstVpl", 0);
            glDispatchCompute(GLuint(groups.x), GLuint(groups.y), GLuint(count));
            glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
            pack({0, 0}, {mTilesX * cells, mTilesY * cells, 1});
        }
    }

    void pack(glm::ivec2 origin, glm::ivec3 size) {
        mPack.use();
        mPack.set("uSize", size);
        mPack.set("uOrigin", origin);
        mWords.bindImage(0, GL_READ_ONLY);
        mGrid.bindImage(1, GL_WRITE_ONLY);
        const glm::ivec3 groups = gl::groupCount(size, mPack.workGroupSize());
        glDispatchCompute(GLuint(groups.x), GLuint(groups.y), GLuint(groups.z));
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    }

    // Segmented Hillis-Steele scan: segments of `cells` texels (one tile each) along x. Imperfect: all
    // tiles per pass; naive: each tile on its own, pass after pass.
    void scan(int count, int cells, int passLimit, bool naive) {
        const int passes = std::min(passLimit, scanPassCount(cells));
        mScan.use();
        mScan.set("uSegment", cells);
        auto run = [&](glm::ivec2 origin, glm::ivec3 size, gl::Texture* a, gl::Texture* b) {
            mScan.set("uOrigin", origin);
            mScan.set("uSize", size);
            const glm::ivec3 groups = gl::groupCount(size, mScan.workGroupSize());
            gl::Texture* src = a;
            gl::Texture* dst = b;
            for (int p = 0; p < passes; ++p) {
                mScan.set("uOffset", 1 << p);
                src->bindImage(0, GL_READ_ONLY);
                dst->bindImage(1, GL_WRITE_ONLY);
                glDispatchCompute(GLuint(groups.x), GLuint(groups.y), GLuint(groups.z));
                glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
                std::swap(src, dst);
            }
            return src;
        };
        if (naive) {
            for (int i = 0; i < count; ++i) mResult = run(tileOrigin(i, cells), {cells, cells, 1}, &mGrid, &mPong);
        } else {
            mResult = run({0, 0}, {mTilesX * cells, mTilesY * cells, 1}, &mGrid, &mPong);
        }
    }

    void allocateOutputs(int width, int height) {
        if (mAirlight && mAirlight.size().x == width && mAirlight.size().y == height) return;
        auto rgba = [](int w, int h, const char* label) {
            return gl::Texture::create(
                {.target = GL_TEXTURE_2D, .format = GL_RGBA32F, .size = {w, h, 1}, .levels = 1, .label = label});
        };
        mAirlight = rgba(width, height, kAirlight);
        mRaw = rgba(width, height, "ivsv.gather_raw");
        mLow = rgba((width + 1) / 2, (height + 1) / 2, "ivsv.gather_quarter");
        mVisibility = gl::Texture::create(
            {.target = GL_TEXTURE_2D, .format = GL_R32F, .size = {width, height, 1}, .levels = 1, .label = kVisibility});
    }

    const gl::Program& gatherProgram(bool exact, bool interp) {
        const std::string key = std::string(exact ? "E" : "F") + (interp ? "I" : "N");
        if (key != mGatherKey || !mGather) {
            gl::ShaderDefines defines;
            if (exact) defines.push_back({"COMBINE_EXACT", "1"});
            if (interp) defines.push_back({"INTERP", "1"});
            mGather = gl::Program::compile({.stages = {"vsv/ivsv_gather.comp"}, .defines = defines, .label = "ivsv.gather"});
            mGatherKey = key;
        }
        return mGather;
    }

    void gather(const scene::Scene& scene, const FrameInput& input, int mode, int gathered, int cells, bool naive,
                glm::ivec2 pickGl) {
        const Settings& s = input.settings;
        const scene::Camera& cam = scene.camera;
        const gl::Program& program = gatherProgram(s.at("combine") != 0.0, s.at("interp") != 0.0);
        const int w = input.width, h = input.height;
        gl::Texture& target = mode == kGatherFull ? mAirlight : (mode == kGatherInterleaved ? mRaw : mLow);
        const glm::ivec2 outSize = mode == kGatherQuarter ? glm::ivec2((w + 1) / 2, (h + 1) / 2) : glm::ivec2(w, h);
        program.use();
        program.set("uOutSize", outSize);
        program.set("uSize", glm::ivec2(w, h));
        program.set("uScale", mode == kGatherQuarter ? 2 : 1);
        program.set("uForward", glm::vec3(cam.forward));
        program.set("uRight", glm::vec3(scene::cameraRight(cam)));
        program.set("uUp", glm::vec3(cam.up));
        program.set("uTanHalf", float(std::tan(cam.yfov * 0.5)));
        program.set("uAspect", float(scene::aspectOf(cam, w, h)));
        program.set("uCells", glm::ivec3(cells, cells, kPhiBits));
        program.set("uVplStride", mode == kGatherInterleaved ? 9 : 1);
        program.set("uSigmaS", float(scene.medium.sigma_s));
        program.set("uSigmaT", float(scene.medium.sigma_t()));
        program.set("uG", float(scene.medium.g));
        program.set("uChunkBits", int(s.at("chunk_bits")));
        program.set("uDiscScale", float(s.at("vpl_disc")));
        program.set("uPick", pickGl);
        mVplBuffer.bindBase(GL_SHADER_STORAGE_BUFFER, 4);
        mPick.bindBase(GL_SHADER_STORAGE_BUFFER, 6);
        mView.surface().distance().bindUnit(render::hd::kFirstFreeTextureUnit);
        mResult->bindImage(0, GL_READ_ONLY);
        target.bindImage(1, GL_READ_WRITE);
        mVisibility.bindImage(2, GL_READ_WRITE);
        const glm::ivec3 groups = gl::groupCount({outSize.x, outSize.y, 1}, program.workGroupSize());
        // Naive: one gather pass per VPL, accumulating; imperfect: one pass over all of them.
        const int passes = naive ? gathered : 1;
        for (int i = 0; i < passes; ++i) {
            program.set("uFirstVpl", naive ? i : 0);
            program.set("uVplCount", naive ? 1 : gathered);
            program.set("uAccumulate", i > 0 ? 1 : 0);
            glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
            glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                            GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
        }
        if (mode == kGatherFull) return;
        mBilateral.use();
        mBilateral.set("uSize", glm::ivec2(w, h));
        mBilateral.set("uSourceSize", outSize);
        mBilateral.set("uMode", mode == kGatherInterleaved ? 0 : 1);
        mBilateral.set("uSigma", float(s.at("bilateral_sigma")));
        target.bindImage(0, GL_READ_ONLY);
        mAirlight.bindImage(1, GL_WRITE_ONLY);
        const glm::ivec3 g2 = gl::groupCount({w, h, 1}, mBilateral.workGroupSize());
        glDispatchCompute(GLuint(g2.x), GLuint(g2.y), 1);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                        GL_TEXTURE_UPDATE_BARRIER_BIT);
    }

    static bool otherLightsOn(const Plan& plan) { return featureEnabled(plan, "OTHER_LIGHTS_BY_VSV"); }

    // The scene's other lights through an inner vsv (its defaults, this run's `voxels`), its L_air added
    // to mAirlight on the CPU (an upload per frame; the combination is not where the time goes).
    void addOtherLights(const FrameInput& input) {
        const scene::Scene others = withoutAreaLights(*input.scene);
        if (!mVsv) mVsv = makeVsvTechnique();
        FrameInput in;
        in.scene = &others;
        in.width = input.width;
        in.height = input.height;
        in.settings = completeSettings(*mVsv, {{"voxels", input.settings.at("voxels")}});
        in.stopAfterStage = 4;  // vsv.gather: L_air exists, no compose needed
        const FrameOutput extra = mVsv->run(in);
        vsv::addAirlight(mAirlight, extra.airlight);
    }

    // ---- CPU images for the debugger ----
    std::shared_ptr<Image> vplImage() const {
        constexpr int kSize = 64;
        auto image = std::make_shared<Image>(kSize, kSize, 3);
        double peak = 0.0;
        for (const vsv::Vpl& v : mVpls) peak = std::max(peak, std::max(v.weight.x, std::max(v.weight.y, v.weight.z)));
        for (const vsv::Vpl& v : mVpls) {
            const int x = std::clamp(int(v.uv.x * kSize), 0, kSize - 1);
            const int y = std::clamp(int(v.uv.y * kSize), 0, kSize - 1);
            for (int c = 0; c < 3; ++c) image->at(x, y, c) = float(peak > 0.0 ? v.weight[c] / peak : 1.0);
        }
        return image;
    }

    // The points splatted into VPL `vpl`'s tile (every count-th point of the cloud), seen from the camera
    // with a depth test: the value is the nearest point's distance, 0 where none fell.
    std::shared_ptr<Image> pointCloudImage(const scene::Scene& scene, int width, int height, int vpl, int count) const {
        auto image = std::make_shared<Image>(width, height, 1);
        const scene::Camera& cam = scene.camera;
        const glm::dvec3 right = scene::cameraRight(cam);
        const double tanY = std::tan(cam.yfov * 0.5), tanX = tanY * scene::aspectOf(cam, width, height);
        for (std::size_t i = std::size_t(vpl); i < mCloudWorld.size(); i += std::size_t(count)) {
            const glm::dvec3 p = mCloudWorld[i] - cam.position;
            const double z = glm::dot(p, cam.forward);
            if (z <= cam.znear) continue;
            const double nx = glm::dot(p, right) / (z * tanX), ny = glm::dot(p, cam.up) / (z * tanY);
            const int x = int(std::floor((nx + 1.0) * 0.5 * width)), y = int(std::floor((1.0 - ny) * 0.5 * height));
            if (x < 0 || x >= width || y < 0 || y >= height) continue;
            const float t = float(glm::length(p));
            if (image->at(x, y) == 0.0f || t < image->at(x, y)) image->at(x, y) = t;
        }
        return image;
    }

    // The alpha cell (x) and theta cell (y) of pixel (x, y)'s eye ray in VPL `vpl`'s grid.
    glm::ivec2 pickedCell(const scene::Scene& scene, const FrameInput& input, int vpl, int cells, int x, int y) const {
        const vsv::EpipolarFrame f = vsv::makeFrame(mVpls[std::size_t(vpl)].position - scene.camera.position);
        const vsv::EpipolarGrid& g = mGrids[std::size_t(vpl)];
        const glm::dvec3 ray = scene::pixelRay(scene.camera, input.width, input.height, x, y);
        return {std::clamp(int(std::floor(vsv::alphaCoord(g, vsv::alphaOf(f, ray)))), 0, cells - 1),
                std::clamp(int(std::floor(vsv::thetaCoord(g, vsv::thetaOf(f, ray)))), 0, cells - 1)};
    }

    // Two rows of phi bits along pixel (x, y)'s column: row 0 as voxelized (mPreScanColumn), row 1 after
    // the scan; 0.5 beyond the pixel's fragment (the gather does not read them).
    std::shared_ptr<Image> columnImage(const scene::Scene& scene, const FrameInput& input, int vpl, int cells, int x,
                                       int y) const {
        const vsv::EpipolarFrame f = vsv::makeFrame(mVpls[std::size_t(vpl)].position - scene.camera.position);
        const vsv::EpipolarGrid& g = mGrids[std::size_t(vpl)];
        const double alpha = vsv::alphaOf(f, scene::pixelRay(scene.camera, input.width, input.height, x, y));
        const glm::ivec2 cell = pickedCell(scene, input, vpl, cells, x, y);
        float d = 0.0f;
        glGetTextureSubImage(mView.surface().distance().id(), 0, x, input.height - 1 - y, 0, 1, 1, 1, GL_RED,
                             GL_FLOAT, sizeof(float), &d);
        const double kEnd = vsv::phiCoord(g, vsv::phiOnEyeRay(f, alpha, double(d)));
        const glm::ivec2 origin = tileOrigin(vpl, cells);
        const vsv::Bits128 after = vsv::readGridRow(*mResult, origin.x + cell.x, 1, origin.y + cell.y).front();
        auto image = std::make_shared<Image>(kPhiBits, 2, 1);
        for (int row = 0; row < 2; ++row)
            for (int k = 0; k < kPhiBits; ++k)
                image->at(k, row) = double(k) >= kEnd ? 0.5f
                                                      : (vsv::testBitPlain(row == 0 ? mPreScanColumn : after, k) ? 1.0f : 0.0f);
        return image;
    }

    std::shared_ptr<Image> perVplImage(int count) const {
        const std::vector<glm::vec4> values = mPick.download<glm::vec4>();
        auto image = std::make_shared<Image>(count, 1, 3);
        for (int i = 0; i < count; ++i)
            for (int c = 0; c < 3; ++c) image->at(i, 0, c) = values[std::size_t(i)][c];
        return image;
    }

    // The same terms plotted: each VPL's contribution (luminance of its RGB) against its index, the
    // ones the pixel did not gather (zero) left out.
    static PlotData perVplPlot(const Image& perVpl) {
        PlotData p;
        p.title = "per-VPL airlight (luminance, unscaled)";
        p.xLabel = "VPL index";
        p.yLabel = "contribution";
        PlotCurve gathered{"gathered VPLs", {}, false, true, 0};
        for (int i = 0; i < perVpl.width; ++i) {
            const double y = 0.2126 * perVpl.at(i, 0, 0) + 0.7152 * perVpl.at(i, 0, 1) + 0.0722 * perVpl.at(i, 0, 2);
            if (y != 0.0 && std::isfinite(y)) gathered.points.push_back({double(i), y});
        }
        p.curves = {gathered};
        return p;
    }

    static std::shared_ptr<Image> interleaveImage(int width, int height, int mode) {
        auto image = std::make_shared<Image>(width, height, 1);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const int glY = height - 1 - y;  // the gather works in GL rows
                image->at(x, y) = mode == kGatherInterleaved ? float((x % 3) + 3 * (glY % 3)) / 8.0f : 0.0f;
            }
        return image;
    }

    std::vector<ParamInfo> mParams;
    std::vector<StageInfo> mStages;
    render::SceneViewPasses mView;       // surface term and compose
    render::SceneViewPasses mNaiveView;  // mode=naive: one point light (cube map) per VPL
    bool mSurfaceRan = false, mNaiveBuilt = false;  // in the last run (markersFor)
    std::unique_ptr<Technique> mVsv;     // the scene's other lights
    std::vector<vsv::Vpl> mVpls;
    std::vector<vsv::EpipolarGrid> mGrids;
    double mVplArea = 0.0;  // dA of one VPL
    int mTilesX = 1, mTilesY = 1;
    gl::Program mSplat, mPushPull, mRectifyIsm, mRectifyCube, mPack, mScan, mBilateral, mGather;
    std::string mGatherKey;
    gl::Buffer mVplBuffer, mPoints, mPick;
    std::vector<glm::dvec3> mCloudWorld;  // sampled once per scene geometry and point count
    std::vector<glm::vec4> mCloud;        // eye-relative copy that was uploaded
    glm::dvec3 mCloudEye{0.0};
    std::size_t mPointsKey = 0;
    const scene::Scene* mPointsScene = nullptr;
    gl::Texture mIsmBits, mIsmRaw, mIsm;
    gl::Texture mGrid, mPong, mWords;
    const gl::Texture* mResult = nullptr;
    vsv::Bits128 mPreScanColumn{};  // the picked pixel's column of the shown VPL before the scan
    gl::Texture mAirlight, mRaw, mLow, mVisibility;
};

}  // namespace

std::unique_ptr<Technique> makeIvsvTechnique() { return std::make_unique<IvsvTechnique>(); }

}  // namespace viz
