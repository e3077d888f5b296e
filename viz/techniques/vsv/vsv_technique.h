// The vsv technique (Wyman 2011, voxelized shadow volumes) as one class, declared here for its three files:
// vsv.cpp (parameters, stages, plan, run), vsv_passes.cpp (the GL passes: voxelization, scan, gather) and
// vsv_views.cpp (what it shows: the picked pixel's voxel column, markers). Only those files include it; the
// rest of the program knows vsv through vsv.h.
#pragma once

#include <algorithm>
#include <optional>

#include "render/camera_ray.h"
#include "render/gl_technique.h"
#include "render/host_device.h"
#include "render/shadow_map_markers.h"
#include "techniques/vsv/add_airlight.h"
#include "techniques/vsv/bits128.h"
#include "techniques/vsv/epipolar_setup.h"
#include "techniques/vsv/grid_passes.h"
#include "techniques/vsv/grid_readback.h"
#include "techniques/vsv/ivsv.h"
#include "techniques/vsv/stiff_bounds.h"

namespace viz::vsv_detail {

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

constexpr std::array<std::string_view, 6> kStageOrder = {"vsv.shadow_maps", "vsv.surface", kStageVoxelize,
                                                         kStageScan,          kStageGather,  "vsv.compose"};
constexpr int kVoxelizeIndex = stageIndexOf(kStageOrder, kStageVoxelize);
constexpr int kScanIndex = stageIndexOf(kStageOrder, kStageScan);
constexpr int kGatherIndex = stageIndexOf(kStageOrder, kStageGather);
constexpr int kComposeIndex = stageIndexOf(kStageOrder, "vsv.compose");

constexpr int kMaxScanPasses = 10;  // 2^10 = 1024 alpha cells, the largest `voxels`

// Shader permutations: feature -> {define when enabled, define when disabled}.
inline const PermutationTable kDefines = {
    {"COMBINE_EXACT", {"COMBINE_EXACT", nullptr}},
    {"INTERP", {"INTERP", nullptr}},
    {"EPIPOLE", {"EPIPOLE", nullptr}},
    {"SPOT", {nullptr, "LIGHTS_NO_SPOT"}},
    {"COOKIE", {nullptr, "LIGHTS_NO_COOKIE"}},
    {"SHADOW_MAPS_CUBE", {nullptr, "SHADOW_NO_CUBE"}},
    {"SHADOW_MAPS_2D", {nullptr, "SHADOW_NO_2D"}},
    {"FAR_TAIL", {"FAR_TAIL", nullptr}},
};

struct GridSize {
    int alpha = 128, theta = 128, phi = 128;
};

// The settings a run reads, each declared once with its parameter (vsvParams(), debug/param_table.h).
struct VsvSettings {
    int voxels = 0, voxelsAlpha = 0, voxelsTheta = 0, voxelsPhi = 0;
    bool exactCombine = false;  // combine=exact
    double alphaBias = 0.0, phiBias = 0.0;
    bool interp = false, dynamicRange = false;
    int epipole = 0;  // off, march, paper
    double directBins = 0.0;
    int directSegments = 0, runBins = 0;
    int pickTheta = -1, light = 0;
    bool forceFeatures = false;
};
const ParamTable<VsvSettings>& vsvParams();

// The grid `voxels` (and the per-axis parameters) ask for. phi bits are packed in 32-bit words, so phi,
// from `voxels` or `voxels_phi`, is rounded up to whole words (48 -> 64; the plan says so): every value
// the ranges allow runs, and the window's sliders never land on one that fails.
inline int wholeWords(int bits) { return std::max(32, (bits + 31) / 32 * 32); }
inline int phiAsked(const VsvSettings& s) { return s.voxelsPhi > 0 ? s.voxelsPhi : s.voxels; }
inline GridSize gridSize(const VsvSettings& s) {
    const int n = s.voxels;
    GridSize g{n, n, wholeWords(phiAsked(s))};
    if (s.voxelsAlpha > 0) g.alpha = s.voxelsAlpha;
    if (s.voxelsTheta > 0) g.theta = s.voxelsTheta;
    return g;
}

// The scene lights vsv shades itself: point, spot, directional, except those culled because their lit
// volume misses the view (render/light_culling.h: they have no GPU light and add nothing). Area lights
// go to an inner ivsv.
inline std::vector<int> shadedLights(const scene::Scene& scene) {
    std::vector<int> out;
    for (int i = 0; i < int(scene.lights.size()); ++i) {
        const scene::Light& l = scene.lights[std::size_t(i)];
        if (l.type != scene::LightType::Area && render::lightReachesView(l, scene.camera)) out.push_back(i);
    }
    return out;
}

inline scene::Scene onlyAreaLights(const scene::Scene& scene) {
    scene::Scene out = scene;
    out.lights.clear();
    for (const scene::Light& l : scene.lights)
        if (l.type == scene::LightType::Area) out.lights.push_back(l);
    return out;
}

using vsv::scanPassCount;

class VsvTechnique final : public render::GlTechnique<VsvSettings> {
public:
    VsvTechnique();

    // Stepping the scan pass by pass: scan_passes = 0 (the voxelized grid before any pass), 1, ...,
    // then -1 (all log2(alpha cells) passes).
    std::vector<double> substepValues(int stage, const Settings& s) const override;

    // Voxel resolution per axis, the one quality knob (issue 9): the grid's alpha, theta and phi cells
    // bound how finely shadow edges and the light's falloff along each ray are resolved.
    std::vector<QualitySetting> qualitySweep(bool quick) const override;

    Settings stiffSettings() const override { return {{"voxels", 512.0}, {"combine", 1.0}}; }
    // Wyman 2011: the lit fraction times the unshadowed airlight, alpha and phi biases of -2.25 and -1
    // cells, and at an epipole the fragment compared with the light (Wyman and Dai 2013 Sec. 5).
    Settings paperSettings() const override {
        return {{"combine", 0.0}, {"alpha_bias", -2.25}, {"phi_bias", -1.0}, {"epipole", 2.0}};
    }

    std::optional<StiffBound> stiffBound(const std::string& caseClass) const override {
        return vsv::stiffBound(caseClass);
    }

    Plan plan(const scene::Scene& scene, const Settings& settings) const override;

    FrameOutput run(const FrameInput& input) override;

    // A screen pixel in the grid of the shown light: its eye ray's theta cell as a row of the occluder
    // map (x = phi bit, y = theta cell), and in the alpha x phi voxel slices, when the slice shown is
    // the pixel's (theta cell = pick_theta's), its eye ray as the column at its alpha.
    // In every light's shadow map: the eye ray and its lit/shadow changes (render/shadow_map_markers.h).
    std::vector<ViewMarker> markersFor(glm::ivec2 pixel, const std::string& id) const override;

private:
    struct MarkState {
        vsv::EpipolarFrame frame;
        vsv::EpipolarGrid grid;
        scene::Camera camera;
        glm::ivec2 size{0};
        int pickTheta = 0;
    };
    std::optional<MarkState> mMark;  // the shown light's grid in the last run, for markersFor

    Plan planFor(const scene::Scene& scene, const Settings& settings, int width, int height) const;
    Plan planForRun(const FrameInput& input) const override {
        return planFor(*input.scene, input.settings, input.width, input.height);
    }

    void allocate(const GridSize& size, int width, int height, int lightCount);

    // Area lights through ivsv (its defaults, this run's `voxels` for alpha and theta), added to L_air.
    void addAreaLights(const FrameInput& input);

    int gpuLightIndex(int sceneLight) const;

    static void setEpipolar(const gl::Program& program, const vsv::EpipolarFrame& f, const vsv::EpipolarGrid& g);

    void voxelize(const scene::Scene& scene, const VsvSettings& s, int sceneLight, const vsv::EpipolarGrid& g, int slot);

    // Hillis-Steele passes with offsets 1, 2, 4, ...: ping-pong between the grid and its partner; the
    // result pointer follows the last pass written.
    void scan(int slot, const GridSize& size, int passLimit);

    const gl::Program& gatherProgram(const Plan& plan);

    void gather(const gl::Program& program, const scene::Scene& scene, const FrameInput& input, int sceneLight,
                const vsv::EpipolarGrid& g, int slot);

    // The phi bits the picked pixel's eye ray reads (nearest theta cell), marked 0.5 beyond its fragment.
    // The alpha cell (x) and theta cell (y) of pixel (x, y)'s eye ray in light `sceneLight`'s grid.
    static glm::ivec2 pickedCell(const scene::Scene& scene, const FrameInput& input, int sceneLight,
                                 const vsv::EpipolarGrid& g, int x, int y);

    // Two rows of phi bits along pixel (x, y)'s column: row 0 as voxelized (mPreScanColumn), row 1 after the
    // scan; 0.5 beyond the pixel's fragment (the gather does not read them).
    std::shared_ptr<Image> columnImage(const scene::Scene& scene, const FrameInput& input, int sceneLight,
                                       const vsv::EpipolarGrid& g, int slot, int x, int y) const;

    gl::Program mVoxelize, mPack, mScan, mGather;
    std::string mGatherKey;
    glm::ivec3 mGridSize{0};
    std::vector<gl::Texture> mGrid, mPong, mOccluder;  // per light
    std::vector<const gl::Texture*> mResult;           // per light: where the scan left the grid
    std::vector<vsv::Bits128> mPreScanColumn;           // the picked pixel's texels before the scan
    gl::Texture mWords;                                // voxelization scratch, one light at a time
    gl::Texture mAirlight, mVisibility;
    std::unique_ptr<Technique> mIvsv;  // the scene's area lights
    // The scene ivsv renders: a member, so that its address (with its geometry) stays the same from
    // frame to frame and ivsv uploads the geometry once, not every frame.
    scene::Scene mAreaLightsScene;
    vsv::AirlightAdder mAdder;
};

}  // namespace viz::vsv_detail
