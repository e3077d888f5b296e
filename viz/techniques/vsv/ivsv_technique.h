// The ivsv technique (Wyman and Dai 2013, imperfect voxelized shadow volumes for area lights) as one class,
// declared here for its files: ivsv.cpp (parameters, stages, plan, run), ivsv_ism.cpp (VPLs, their tile
// layout and the imperfect shadow maps), ivsv_passes.cpp (rectification, voxel scan, gather) and
// ivsv_views.cpp (what it shows: VPL and point-cloud images, the picked column, per-VPL plots, markers).
// Only those files include it; the rest of the program knows ivsv through ivsv.h.
#pragma once

#include <bit>
#include <cstdio>
#include <numbers>
#include <optional>

#include "gl/buffer.h"
#include "render/camera_ray.h"
#include "render/gl_technique.h"
#include "render/host_device.h"
#include "render/shadow_map_markers.h"
#include "techniques/vsv/add_airlight.h"
#include "techniques/vsv/bits128.h"
#include "techniques/vsv/epipolar_setup.h"
#include "techniques/vsv/grid_passes.h"
#include "techniques/vsv/grid_readback.h"
#include "techniques/vsv/stiff_bounds.h"
#include "techniques/vsv/vpl_sampling.h"
#include "techniques/vsv/vsv.h"

namespace viz::ivsv_detail {

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

constexpr std::array<std::string_view, 7> kStageOrder = {kStageVpls,     kStageShadows, kStageSurface, kStageVoxelize,
                                                         kStageScan,     kStageGather,  "ivsv.compose"};
constexpr int kVplsIndex = stageIndexOf(kStageOrder, kStageVpls);
constexpr int kShadowsIndex = stageIndexOf(kStageOrder, kStageShadows);
constexpr int kSurfaceIndex = stageIndexOf(kStageOrder, kStageSurface);
constexpr int kVoxelizeIndex = stageIndexOf(kStageOrder, kStageVoxelize);
constexpr int kScanIndex = stageIndexOf(kStageOrder, kStageScan);
constexpr int kGatherIndex = stageIndexOf(kStageOrder, kStageGather);
constexpr int kComposeIndex = stageIndexOf(kStageOrder, "ivsv.compose");

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
    glm::vec4 cellCorner, cellU, cellV;
};
static_assert(sizeof(GpuVpl) == 16 * 16);

inline const PermutationTable kDefines = {
    {"COMBINE_EXACT", {"COMBINE_EXACT", nullptr}},
    {"INTERP", {"INTERP", nullptr}},
    {"EPIPOLE", {"EPIPOLE", nullptr}},
    {"DEINTERLEAVE", {"DEINTERLEAVE", nullptr}},
};

using vsv::scanPassCount;

// The scene's area light (ivsv shades one), or nullptr; every other light goes to an inner vsv.
inline const scene::Light* areaLightOf(const scene::Scene& scene) {
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
inline scene::Scene withoutAreaLights(const scene::Scene& scene) {
    scene::Scene out = scene;
    out.lights.clear();
    for (const scene::Light& l : scene.lights)
        if (l.type != scene::LightType::Area) out.lights.push_back(l);
    return out;
}

// The settings a run reads, each declared once with its parameter (ivsvParams(), debug/param_table.h).
struct IvsvSettings {
    int vpls = 0, voxels = 0;
    bool gridLayout = false;    // vpl_layout=grid
    bool exactCombine = false;  // combine=exact
    int gather = kGatherFull;
    bool subsetsPerFrame = false;  // subsets=per-frame
    bool deinterleave = false;     // deinterleave=on
    bool naive = false;            // mode=naive
    int points = 0, fillLevels = 0;
    double alphaBias = 0.0, phiBias = 0.0;
    bool interp = false;
    bool epipole = false;  // epipole=paper
    int chunkBits = 0;
    double vplKernel = 0.0, bilateralSigma = 0.0;
    int pickVpl = 0, pickTheta = -1;
    int tile = 0;  // shadow_map: the ISM tile or naive cube face
    bool forceFeatures = false;
};
const ParamTable<IvsvSettings>& ivsvParams();

// The interleaved gather's shift of its 3x3 subset pattern on this frame (subsets=per-frame: the frame
// index mod 9), 0 otherwise.
inline int phaseShift(const IvsvSettings& s, const FrameInput& input) {
    return s.gather == kGatherInterleaved && s.subsetsPerFrame ? std::max(0, input.frame) % 9 : 0;
}

class IvsvTechnique final : public render::GlTechnique<IvsvSettings> {
public:
    IvsvTechnique();

    // Stepping: the segmented scan pass by pass (scan_passes = 0 before any pass, 1, ..., then -1 = all),
    // and the gather VPL by VPL (vpl_step = 0 gathers VPL 0 only, 1 adds VPL 1, ..., then -1 = all).
    std::vector<double> substepValues(int stage, const Settings& s) const override;

    // VPL count (the area light's sampling) and voxel resolution (each VPL grid's), issue 9's knobs:
    // cheapest first. On a scene without an area light only `voxels` matters (the inner vsv).
    std::vector<QualitySetting> qualitySweep(bool quick) const override;
    std::vector<StabilisingOption> stabilisingOptions(const scene::Scene& scene) const override;
    // Area lights: the quick sweep adds 256 VPLs (the full sweep has them already; without an area light
    // ivsv hands every light to vsv and the VPL count changes nothing). tv-room at 160x120: 0.026 against
    // the reference, where the quick sweep's 64 stop at 0.042.
    std::vector<QualitySetting> areaLightSweep(bool quick) const override {
        if (!quick) return {};
        return {{"vpls=256 voxels=128", {{"vpls", 256.0}, {"voxels", 128.0}}}};
    }
    bool readsFrame(const Settings& settings) const override {
        return settingOr(settings, "gather", 0.0) == double(kGatherInterleaved) && settingOr(settings, "subsets", 0.0) != 0.0;
    }

    // The stiff cases have no area light: ivsv hands every light to its inner vsv at this resolution.
    Settings stiffSettings() const override { return {{"voxels", 512.0}, {"vpls", 256.0}}; }
    // Wyman and Dai 2013: 256 VPLs at Halton points (Sec. 3.1.1) with imperfect shadow maps, the lit
    // fraction, the 3x3 interleaved
    // gather with its bilateral filter (ours offers it or the quarter-size gather, not both at once), the
    // fragment-against-light test at each VPL's epipole.
    Settings paperSettings() const override {
        return {{"vpls", 256.0}, {"vpl_layout", 0.0}, {"mode", 0.0}, {"combine", 0.0}, {"gather", 1.0}, {"epipole", 1.0}};
    }
    std::optional<StiffBound> stiffBound(const std::string& caseClass) const override {
        return vsv::stiffBound(caseClass);
    }

    Plan plan(const scene::Scene& scene, const Settings& settings) const override;

    FrameOutput run(const FrameInput& input) override;

    // Linked cursors (once the camera view ran: the eye ray ends at the pixel's surface): in the shadow
    // maps, the eye ray and its lit/shadow changes by the map's own test (render/shadow_map_markers.h).
    std::vector<ViewMarker> markersFor(glm::ivec2 pixel, const std::string& id) const override;

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
    std::vector<ViewMarker> ismMarkers(const MarkState& m, const vsv::Vpl& vpl, const glm::dvec3& w, double d) const;

    // The ISM tile (and naive cube face) in texels: `shadow_map` rounded up to a power of two (the
    // push-pull halves tiles level by level; 201 -> 256, the plan says so), so every value the range
    // (16 to 512) allows runs.
    static int tileSize(const IvsvSettings& s) { return int(std::bit_ceil(unsigned(std::max(s.tile, 1)))); }

    glm::ivec2 tileOrigin(int i, int size) const { return {(i % mTilesX) * size, (i / mTilesX) * size}; }

    void layOut(int count, int cells, int tile);

    // Each VPL's epipolar grid covers what the camera sees of its hemisphere (a cone of half angle pi/2
    // around its normal narrows phi, as a spot's cone does for vsv).
    void uploadVpls(const scene::Scene& scene, int width, int height, int cells, int tile);

    // The point cloud is sampled once per scene and size; each splat pass uses all of it.
    void buildIsm(const scene::Scene& scene, const scene::Light& light, int points, int count, int tile, int fillLevels);

    void setRectifyCommon(const gl::Program& p, const IvsvSettings& s, int cells, int tile) const;

    void rectify(const IvsvSettings& s, int count, int cells, int tile, bool naive);

    // Segmented Hillis-Steele scan: segments of `cells` texels (one tile each) along x. Imperfect: all
    // tiles per pass; naive: each tile on its own, pass after pass.
    void scan(int count, int cells, int passLimit, bool naive);

    void allocateOutputs(int width, int height);

    const gl::Program& gatherProgram(bool exact, bool interp, bool epipole, bool naive, bool deinterleave);

    void gather(const scene::Scene& scene, const FrameInput& input, int mode, int gathered, int cells, bool naive,
                glm::ivec2 pickGl);

    static bool otherLightsOn(const Plan& plan) { return featureEnabled(plan, "OTHER_LIGHTS_BY_VSV"); }

    // The scene's other lights through an inner vsv (its defaults, this run's `voxels`), its L_air added
    // to mAirlight on the CPU (an upload per frame; the combination is not where the time goes).
    void addOtherLights(const FrameInput& input);

    // ---- CPU images for the debugger ----
    std::shared_ptr<Image> vplImage() const;

    // The points splatted into VPL `vpl`'s tile (every count-th point of the cloud), seen from the camera
    // with a depth test: the value is the nearest point's distance, 0 where none fell.
    std::shared_ptr<Image> pointCloudImage(const scene::Scene& scene, int width, int height, int vpl, int count) const;

    // The alpha cell (x) and theta cell (y) of pixel (x, y)'s eye ray in VPL `vpl`'s grid.
    glm::ivec2 pickedCell(const scene::Scene& scene, const FrameInput& input, int vpl, int cells, int x, int y) const;

    // Two rows of phi bits along pixel (x, y)'s column: row 0 as voxelized (mPreScanColumn), row 1 after
    // the scan; 0.5 beyond the pixel's fragment (the gather does not read them).
    std::shared_ptr<Image> columnImage(const scene::Scene& scene, const FrameInput& input, int vpl, int cells, int x,
                                       int y) const;

    std::shared_ptr<Image> perVplImage(int count) const;

    // The same terms plotted: each VPL's contribution (luminance of its RGB) against its index, the
    // ones the pixel did not gather (zero) left out.
    static PlotData perVplPlot(const Image& perVpl);

    static std::shared_ptr<Image> interleaveImage(int width, int height, int mode, int phaseShift);
    // ivsv.interleave: the 3x3 subset pattern the gather used (its per-frame shift included), or black with a
    // note saying that every pixel gathers every VPL.
    static Intermediate interleaveIntermediate(int width, int height, int mode, int phaseShift);

    // mView (GlTechnique) draws the surface term and composes; no ivsv stage keeps its outputs yet, so
    // every run starts at stage 0 (mReuse carries nothing).
    render::SceneViewPasses mNaiveView;  // mode=naive: one point light (cube map) per VPL
    bool mSurfaceRan = false, mNaiveBuilt = false;  // in the last run (markersFor)
    std::unique_ptr<Technique> mVsv;     // the scene's other lights
    // The scene vsv renders: a member, so that its address (with its geometry) stays the same from frame
    // to frame and vsv uploads the geometry once, not every frame.
    scene::Scene mOtherLightsScene;
    vsv::AirlightAdder mAdder;
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

}  // namespace viz::ivsv_detail
