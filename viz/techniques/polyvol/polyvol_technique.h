// The polyvol technique (Billeter, Sintorn, Assarsson 2010 and its supplement) as one class, declared here for
// its three files: polyvol.cpp (parameters, stages, plan, run), polyvol_passes.cpp (the GL passes: the light
// volumes' meshes, their rasterisation, the resolve) and polyvol_views.cpp (what it shows: intermediates,
// the lookup table's error, markers). Only those files include it; the rest of the program knows polyvol
// through polyvol.h.
#pragma once

#include <array>
#include <bit>
#include <chrono>
#include <cstdio>
#include <map>

#include "gl/buffer.h"
#include "gl/framebuffer.h"
#include "gl/readback.h"
#include "gl/vertex_array.h"
#include "render/camera_ray.h"
#include "render/eye_space.h"
#include "render/gl_technique.h"
#include "render/host_device.h"
#include "render/mesh_view.h"
#include "render/shadow_map_markers.h"
#include "techniques/polyvol/adaptive_tessellation.h"
#include "techniques/polyvol/airlight_lut.h"
#include "techniques/polyvol/crack_check.h"
#include "techniques/polyvol/light_volume_mesh.h"
#include "techniques/polyvol/volume_crossings.h"
#include "techniques/polyvol/volume_grid.h"

namespace viz::polyvol_detail {

// ---- ids (stable: lessons and tests use them) ----
constexpr const char* kStageVolume = "polyvol.volume";
constexpr const char* kMesh = "polyvol.mesh";
constexpr const char* kCrossings = "polyvol.crossings";
constexpr const char* kPositive = "polyvol.positive";
constexpr const char* kNegative = "polyvol.negative";
constexpr const char* kTotal = "polyvol.total";
constexpr const char* kCracks = "polyvol.cracks";
constexpr const char* kLut = "polyvol.lut";
constexpr const char* kLutError = "polyvol.lut_error";
constexpr const char* kEdgeMap = "polyvol.edge_map";
constexpr const char* kTessLevels = "polyvol.tess_levels";

// Lookup table size (asinh(|u| / s) x log tau_h samples), built from the double closed form at first use.
constexpr int kLutWidth = polyvol::AirlightLut::kWidth, kLutHeight = polyvol::AirlightLut::kHeight;

constexpr std::array<std::string_view, 4> kStageOrder = {"polyvol.shadow_maps", "polyvol.surface", kStageVolume,
                                                         "polyvol.compose"};
constexpr int kVolumeIndex = stageIndexOf(kStageOrder, kStageVolume);
constexpr int kComposeIndex = stageIndexOf(kStageOrder, "polyvol.compose");

using polyvol::kModeCube;
using polyvol::kModeDirectional;
using polyvol::kModeSpot;

// Shader permutations: feature -> {define when enabled, define when disabled}. Others are run-time.
inline const PermutationTable kDefines = {
    {"SPOT", {nullptr, "LIGHTS_NO_SPOT"}},
    {"COOKIE", {nullptr, "LIGHTS_NO_COOKIE"}},
    {"SHADOW_MAPS_CUBE", {nullptr, "SHADOW_NO_CUBE"}},
    {"SHADOW_MAPS_2D", {nullptr, "SHADOW_NO_2D"}},
    {"AIRLIGHT_LUT", {"AIRLIGHT_LUT", nullptr}},
};

// The smallest shadow map at which adaptive tessellation paid off on every built-in scene measured
// (README, benchmark: forest broke even between 256^2 and 512^2).
constexpr int kAdaptivePaysFrom = 512;
// The same for cube faces (point lights and area-light VPLs; README, benchmark: tv-room's VPL cubes broke
// even between 64^2 and 128^2 faces at 160x120).
constexpr int kAdaptiveCubesPayFrom = 128;

// The settings a run reads, each declared once with its parameter (polyvolParams(), debug/param_table.h).
struct PolyvolSettings {
    bool adaptive = false;  // tessellation=adaptive
    polyvol::EdgeMeasure edgeMeasure = polyvol::EdgeMeasure::Laplacian;
    bool lut = false;  // airlight=lut
    double threshold = 0.0;
    int spotPieces = 0;
    bool crackCheck = false;
    std::int64_t drawTriangles = 0;
    bool originAtSurface = false;  // origin=surface
    int wireframe = 0;             // off, camera, light, orbit
    int stopLevel = 0;
    double cookieMask = 0.0;
    int shadowMap = 0, areaSamples = 0;
    bool forceFeatures = false;

    // Whether they ask for adaptive tessellation at a size where the plan keeps it (or force it); the plan
    // also needs a 2D map in the scene.
    // draw_triangles cuts the static mesh, so it leaves adaptive tessellation out; so does a map size the
    // refinement cannot halve down to texels (a power of two, at least 16).
    bool adaptiveKept() const {
        return adaptive && drawTriangles == 0 && tessellable(shadowMap) &&
               (shadowMap >= kAdaptivePaysFrom || forceFeatures);
    }
    static bool tessellable(int n) { return n >= 16 && std::has_single_bit(unsigned(n)); }
};
const ParamTable<PolyvolSettings>& polyvolParams();

class PolyvolTechnique final : public render::GlTechnique<PolyvolSettings> {
public:
    PolyvolTechnique();

    // Stepping the adaptive refinement coarse to fine: stop_level = 0 (each grid's coarse 16^2 quads),
    // then one level finer per step, then -1 (refined fully). No sub-steps with static tessellation or
    // when the plan leaves adaptive out below its break-even size.
    std::vector<double> substepValues(int stage, const Settings& s) const override;

    // Issue 9's knobs: the shadow-map size (the volume's resolution, one vertex per texel) with static
    // tessellation, then adaptive at the sizes where it was measured to pay off (README, benchmark).
    // The quick sweep's cheap end also takes area lights as one VPL (area_samples=1, label "1vpl").
    std::vector<QualitySetting> qualitySweep(bool quick) const override;
    // Area lights: 8^2 and 12^2 VPLs in the full sweep (SceneViewPasses::areaSampleSweep), none in the
    // quick one. Each VPL is a cube volume, so the count costs its square: tv-room on llvmpipe 3.3 s a run
    // at the default 4^2 and 13 s at 8^2 (160x120; 18 and 71 s at 640x480), which alone would double the
    // quick report's time on tv-room, for 8.4 % -> 3.9 %.
    std::vector<QualitySetting> areaLightSweep(bool quick) const override {
        return quick ? std::vector<QualitySetting>{} : render::SceneViewPasses::areaSampleSweep(false, 12);
    }

    // The accurate end: 1024^2 (at 512^2 a ray passing the light within a texel of the plate's shadow
    // boundary in occluder-touching-light is misclassified next to the 1/r^2 singularity: 0.25), adaptive
    // (the same image, half the time), origin=surface (crossings behind d add exactly 0, so a camera
    // inside a closed occluder gets exactly 0 instead of a 4e-9 blend-order residue).
    // Billeter et al. 2010 and its supplement: the airlight lookup table, adaptive tessellation, 1024^2
    // shadow maps (Table 1's smallest size), refined where the Laplacian is large (section 4.1).
    Settings paperSettings() const override {
        return {{"airlight", 1.0}, {"tessellation", 1.0}, {"shadow_map", 1024.0}, {"edge_measure", 0.0}};
    }
    Settings stiffSettings() const override {
        return {{"shadow_map", 1024.0}, {"tessellation", 1.0}, {"origin", 1.0}};
    }

    // Measured by `airlight report --suite stiff` at 33x25 (figures in README.md), bounds about twice that.
    std::optional<StiffBound> stiffBound(const std::string& caseClass) const override;

    Plan plan(const scene::Scene& scene, const Settings& settings) const override;

    FrameOutput run(const FrameInput& input) override;

    // Linked cursors. In each light's shadow map, and in the edge map and tessellation levels (the last
    // adaptive light's, marked when it is a 2D light): the pixel's eye ray projected into the map (cubes: per face) and every crossing
    // of the ray with that light's volume mesh (volume_crossings.h), signed as the volume pass adds it
    // (+1 leaving the lit volume, -1 entering), also those beyond d, so that they add up to the pixel's
    // polyvol.crossings (r: count, g: signed sum), summed over the lights. Cube marks carry their face.
    std::vector<ViewMarker> markersFor(glm::ivec2 pixel, const std::string& id) const override;

private:
    // The keys of the last adaptive 2D light's (cube: cube light's) triangles (3 per triangle), read back
    // once per run.
    const std::vector<std::uint32_t>& adaptiveKeys(bool cube) const;
    // The keys a tessellation emitted in its last build (3 per triangle), read back.
    static std::vector<std::uint32_t> downloadKeys(const polyvol::AdaptiveTessellation& tess);
    // An earlier adaptive light's keys (its build overwritten by a later light's), built again.
    const std::vector<std::uint32_t>& rebuiltKeys(int index, const polyvol::VolumeGrid& grid) const;

    static std::int64_t gridTriangleCountFor(int n, int faces) { return polyvol::gridTriangleCount(n, faces); }

    void allocateTargets(int width, int height);

    // The table for the medium's g, built from the double closed form when g changes.
    void ensureLut(double g);

    const gl::Program& volumeProgram(const Plan& plan);

    // Extra key lists, uploaded once per kind, size and key stride (N static, N + 1 adaptive): the closure
    // of a 2D grid or the seams of a cube's six grids of `size` texels per side.
    enum class ExtraKind { Closure, Seams };
    const gl::Buffer& extraKeys(ExtraKind kind, int size, int stride, std::int64_t& triangles);

    // The static mesh of one light: the first `count` of its grid's triangles (one instance per row of
    // quads, indexed through the element buffer of rowIndices, so a texel's position is shared by the
    // triangles around it) and then of its extra keys' triangles, in the one order the volume, the wire
    // and `draw_triangles` use. Binds mVao and `keys`; sets uGridRows and uRowOffset on `program`.
    void drawMesh(const gl::Program& program, const polyvol::VolumeGrid& grid, const gl::Buffer& keys,
                  std::int64_t gridTriangles, std::int64_t extraTriangles, std::int64_t count);

    // Per light: the draw's geometry. Spot: the unit-depth view plane of the shadow matrix; directional:
    // its near plane, the far depth of empty texels and the cap behind the scene; all from the inverse
    // shadow matrix in double, so the mesh samples exactly the directions the map was rendered with.
    polyvol::VolumeGrid describe(const render::GpuLightCpu& L, int index, int n, double zfar, float cookieMask) const;

    std::int64_t drawVolumes(const scene::Scene& scene, const FrameInput& input, const Plan& plan);

    // The wireframe of one light's volume into polyvol.mesh, from the camera (wireframe=1) or from the
    // first 2D light (wireframe=2, through its shadow matrix). Restores the volume pass's state.
    // The orbit view's clip box (the scene's meshes and its lights' positions, 2 % larger) set on the wire
    // program; false (no clip) for a scene without triangles.
    bool setOrbitClipBox(const scene::Scene& scene);
    void drawWire(const FrameInput& input, const render::GpuLightCpu& L, const polyvol::VolumeGrid& grid,
                  const gl::Buffer& keys, std::int64_t gridTriangles, std::int64_t extraTriangles, std::int64_t count,
                  const polyvol::AdaptiveTessellation* adaptive);

    // The radius of the ball around a light whose part of each ray is integrated once per pixel by the
    // resolve instead of between rasterised crossings (README, "Rays next to the light"): at most half the
    // nearest distance the light's shadow map stores (nothing occludes within it; an empty map: half its
    // far plane), and at most kBallPixels pixel footprints at the light's distance (the crossings' rounding,
    // ~1/256 pixel, matters only that close to the light; a larger ball costs two segment integrals per
    // crossing term on more pixels for nothing: +22 % volume time on grate with half the nearest
    // distance alone). 0 for directional lights.
    static constexpr double kBallPixels = 16.0;
    float nearRadius(const render::GpuLightCpu& L, const scene::Camera& cam, int height) const;

    // Per light, after its volume: origin=surface adds c L(0, d) (without the ball's chord) and zeroes the
    // light's signed count; every origin adds the airlight of the ray's chord through the ball of radius
    // `radius` around the light. The volume program and blend state are restored for the next light.
    void resolve(const FrameInput& input, int light, float radius);

    // The table against the closed form per pixel (lut_error.comp); returns the image's maximum.
    float lutError(const FrameInput& input);

    // L_air = max(0, total) (clamp.comp).
    void clampAirlight();

    void publishVolume(FrameOutput& out, const FrameInput& input, std::int64_t triangles);
    // The airlight lookup table of phase parameter g and its error against the closed form.
    void publishLut(FrameOutput& out, const FrameInput& input, double g);

    struct Extra {
        std::int64_t triangles = 0;
        gl::Buffer buffer;
    };

    gl::Program mProgram;
    std::string mProgramKey;
    gl::Texture mTotal, mPositive, mNegative, mCrossings;
    gl::Framebuffer mFramebuffer;
    gl::VertexArray mVao;
    std::map<int, gl::Buffer> mRowIndices;  // per grid size N: one row of N - 1 quads (drawMesh)
    std::map<std::array<int, 3>, Extra> mExtras;  // kind, size, stride
    polyvol::AdaptiveTessellation mTess, mTessCube;  // 2D grids; cube faces
    const polyvol::AdaptiveTessellation* mShownTess = nullptr;  // the last adaptive light's; null: none
    bool mAdaptiveOverflow = false, mWireDrawn = false;
    int mWireMode = 0;  // this run's wireframe: the setting, or orbit for a caller showing polyvol.mesh
    // markersFor: the camera's zfar and cookie_mask of the last run (they place the volume's vertices);
    // the edge and level maps shown are those of mAdaptiveLights.back() (mShownTess).
    int mFlatAdaptiveLight = -1;  // the last adaptive 2D light: its keys are still in mTess
    int mCubeAdaptiveLight = -1;  // the last adaptive cube light: its keys are still in mTessCube
    std::vector<int> mAdaptiveLights;  // lights drawn with adaptive tessellation in the last run
    mutable std::array<std::vector<std::uint32_t>, 2> mMarkKeys;  // 2D, cube
    // The other adaptive lights' keys, built again when they are marked (once per light and run) in a
    // tessellation of their own: the run itself pays nothing for them. The run's settings for the build:
    mutable polyvol::AdaptiveTessellation mMarkTess;
    mutable std::map<int, std::vector<std::uint32_t>> mRebuiltKeys;
    polyvol::EdgeMeasure mMarkMeasure = polyvol::EdgeMeasure::Laplacian;
    double mMarkThreshold = 0.0;
    int mMarkStopLevel = -1;
    mutable std::array<bool, 2> mMarkKeysRead{};
    double mMarkZfar = 0.0;
    float mMarkCookieMask = 0.0f;
    std::int64_t mTriangles = 0;
    std::vector<float> mNearRadii;  // per drawn light: the ball radius left to the resolve (README)
    gl::ShaderDefines mDefines;
    gl::Program mResolve, mWireProgram, mClamp;
    gl::Texture mAirlight;
    gl::Texture mWire;
    gl::Framebuffer mWireFramebuffer;
    render::MeshView mMeshView;
    std::string mResolveKey;
    gl::Texture mLut, mLutError;
    gl::Program mLutErrorProgram;
    double mLutG = 0.0, mLutMs = 0.0;
};

}  // namespace viz::polyvol_detail
