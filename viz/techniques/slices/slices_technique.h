// The slices technique (Mitchell 2004) as one class, declared here for its files: slices.cpp (parameters,
// stages, plan, run), slices_passes.cpp (the GL passes: sampling planes, accumulation, resolve),
// slices_views.cpp (what it shows: the planes' polygons, fragment counts, markers) and slices_pick.cpp (the
// picked pixel's ray replayed against the planes). Only those files include it; the rest of the program
// knows slices through slices.h.
#pragma once

#include <cstdint>

#include "gl/buffer.h"
#include "gl/framebuffer.h"
#include "gl/readback.h"
#include "gl/samples_query.h"
#include "gl/vertex_array.h"
#include "render/compose.h"
#include "render/eye_space.h"
#include "render/gl_technique.h"
#include "render/gpu_lights.h"
#include "render/gpu_scene.h"
#include "render/mesh_view.h"
#include "render/shadow_maps.h"
#include "render/surface_pass.h"
#include "techniques/slices/ray_planes.h"
#include "techniques/slices/slice_geometry.h"
#include "techniques/slices/slices.h"

namespace viz::slices_detail {

// ---- ids (stable: lessons and tests use them) ----
constexpr const char* kStagePlanes = "slices.planes";
constexpr const char* kStageResolve = "slices.resolve";
constexpr const char* kNoise = "slices.noise";
constexpr const char* kCookies = "slices.cookie";
constexpr const char* kAccum = "slices.accumulation";
constexpr const char* kPlane = "slices.plane";
constexpr const char* kFragments = "slices.fragments";
constexpr const char* kPlaneMesh = "slices.plane_mesh";
constexpr const char* kPlaneView = "slices.plane_view";
constexpr const char* kAirlight = "slices.airlight";
constexpr const char* kRayPlanes = "slices.ray_planes";
constexpr const char* kRayPlanesChart = "slices.ray_planes_chart";
// The pick replay target's width: each record's quad covers the rest of its row (work: count x width / 2
// fragments); each further row is seeded with the accumulation at the end of the one before.
constexpr int kReplayColumns = 64;

// The picked pixel's record of one plane, as shaders/slices/pick_record.glsl lays it out (std430).
struct PickRecord {
    glm::vec4 where;  // plane i, view depth s_i, t along the ray, dt
    glm::vec4 test;   // status (PickStatus), V (-1: not tested), channel (-1: all), surface distance d
    glm::vec4 value;  // the fragment's output (stored units), before the blend quantises it
};
static_assert(sizeof(PickRecord) == 48);

constexpr std::array<std::string_view, 5> kStageOrder = {"slices.shadow_maps", "slices.surface", kStagePlanes,
                                                         kStageResolve, "slices.compose"};
constexpr int kPlanesIndex = stageIndexOf(kStageOrder, kStagePlanes);
constexpr int kResolveIndex = stageIndexOf(kStageOrder, kStageResolve);
constexpr int kComposeIndex = stageIndexOf(kStageOrder, "slices.compose");

// The paper's example draws at most 100 planes; its per-plane scale is 9 / (N / 100).
constexpr double kPaperMaxPlanes = 100.0;
constexpr double kPaperAmbient = 0.35;
constexpr int kNoiseSize = 64;
// distance_scale never goes below this many planes.
constexpr int kMinScaledPlanes = 8;

struct Terms {
    bool physical = true;
    bool equiangular = false;  // the slab integral (integration=equiangular, or auto's choice; physical weighting only)
    bool spot = false, cookie = false, shadow = false, pcf = false, noise = false;
    bool mask = false, blur = false, clip = true, userClip = false, count = false, cubes = false;
    bool spots = false;  // a spot light in the scene (else LIGHTS_NO_SPOT)
    bool pick = false;  // record the picked pixel's planes (slices.ray_planes)
    bool lastPlane = false;  // draw the last plane alone too (slices.plane, on demand)
    bool depthTest = false;  // depth_test=1: fragments wholly behind the first surface are rejected unshaded
    bool farTail = false;    // a far camera: the resolve adds each ray past the planes' end (resolve.frag)
    double planesEnd = 0.0;  // where the planes end along the view: zfar, or the scene's far side under a
                             // far camera (scene::depthOfInterest)
};

// One draw set as the pick replay needs it again.
struct PickSet {
    int light = -1;  // index into Scene::lights, -1: the unbounded lights together
    int base = 0;    // first record
    int drawn = 0;
    bool clipLight = false;
    float depthFar = 0.0f, spacing = 0.0f, drawNear = 0.0f;
    int nearestPlane = 0;
    float nearestWeight = 1.0f;
    glm::vec2 boxMin{0.0f}, boxMax{0.0f};
    glm::mat4 volume{1.0f};
};

// The settings a run reads, each declared once with its parameter (slicesParams(), debug/param_table.h).
struct SlicesSettings {
    int planes = 0;
    bool physical = false;  // weighting=physical
    SlicesIntegration integration = SlicesIntegration::Auto;
    double slabAngle = 0.0;    // radians between two nodes of a slab at most
    SlicesAccum accum = SlicesAccum::Rgba32f;
    double accumRange = 0.0;
    int shadow = 0;  // off, nearest, pcf
    bool spotFalloff = false, cookie = false, noise = false;
    double noiseTiles = 0.0;
    bool falloff = false, ambient = false;
    double artisticUnits = 0.0;
    bool blur = false, clip = false, userClip = false;
    double clipYMin = 0.0, clipYMax = 0.0;
    bool directionalBox = false;
    bool worldGrid = false;  // plane_grid=world
    double distanceScale = 0.0;
    bool countFragments = false, meshView = false;
    bool rayPlanes = false, forceFeatures = false;
    bool depthTest = false;  // the surface's depth buffer rejects plane fragments behind it before shading
};
const ParamTable<SlicesSettings>& slicesParams();

class SlicesTechnique final : public render::GlTechnique<SlicesSettings> {
public:
    SlicesTechnique();

    // Plane count in float accumulation, then the precision lab's targets at one plane count.
    std::vector<QualitySetting> qualitySweep(bool quick) const override;
    // Area lights: more VPLs, each count also at 256 planes (SceneViewPasses::areaSampleSweep): on 8^2
    // VPLs the default 128 planes bound the error at 6.1 % on tv-room.
    std::vector<QualitySetting> areaLightSweep(bool quick) const override {
        return render::SceneViewPasses::areaSampleSweep(quick, 16, "planes", 256);
    }
    // The report and bench time the technique, not the inspector's recording of one pixel.
    Settings measurementSettings() const override { return {{"ray_planes", 0.0}}; }
    std::vector<StabilisingOption> stabilisingOptions(const scene::Scene& scene) const override;

    Settings stiffSettings() const override { return {{"planes", 512.0}, {"ray_planes", 0.0}}; }
    // Mitchell 2004: the artistic formula and constants, the RGBA8 target with the channel mask, 100
    // planes (the example application's count, Figure 8.1.11c).
    Settings paperSettings() const override { return {{"weighting", 0.0}, {"accum", 1.0}, {"planes", 100.0}}; }

    // Measured by `airlight report --suite stiff` at 33x25 (figures in README.md), bounds about twice that.
    std::optional<StiffBound> stiffBound(const std::string& caseClass) const override;

    // Linked cursors: in every light's shadow map the pixel's eye ray and where it enters or leaves
    // shadow by the map's own test (render/shadow_map_markers.h). They follow the camera-view stage.
    std::vector<ViewMarker> markersFor(glm::ivec2 pixel, const std::string& id) const override;

    Plan plan(const scene::Scene& scene, const Settings& s) const override;

    FrameOutput run(const FrameInput& input) override;

private:
    static Terms terms(const scene::Scene& scene, const SlicesSettings& s);

    // The defines of the plane shader, in a fixed order: also the cache key and what plan() reports.
    // pick: the picked pixel's recording draw (PICK_RAY, no fragment counting); the frame's draw is without.
    static gl::ShaderDefines planeDefines(const Terms& t, bool pick = false);
    static std::string permutationKey(const Terms& t, bool pick = false);

    void allocateTargets(int width, int height, SlicesAccum accum);

    double storeScale(const Terms& t, const SlicesSettings& s) const;

    const gl::Program& planeProgram(const Terms& t, bool pick);

    // The camera's view volume up to zfar as a clip matrix (eye-relative world -> clip), for planeRange.
    static glm::dmat4 cameraVolume(const scene::Camera& cam, int width, int height);

    void drawPlanes(const scene::Scene& scene, const FrameInput& input, const Terms& t);

    // The picked pixel's blend replayed (pick_replay.*): every record in drawing order (draw sets in turn)
    // over a target in the accumulation's format, so texel k holds the pixel's accumulation after records
    // 0..k as this blend quantises it. Then the records and the replay are read back into mRayPlanes.
    // Runs with the plane pass's blend state (dst + src).
    void replayPick(const FrameInput& input, const CameraBasis& basis, const Terms& t);

    // slices.ray_planes as a table: one row per record, RayPlaneColumn columns of four channels.
    std::shared_ptr<Image> rayPlaneTable(const std::vector<PickRecord>& records, const Image& replay,
                                         const Terms& t) const;

    // The drawn planes as polygons (rows: planes back to front, light after light; columns: vertices;
    // rgb = eye-relative world xyz; NaN pads unused vertices), for viewing the slab stack from outside.
    Intermediate polygonIntermediate() const;

    // Occlusion queries over the same planes with colour writes off: all fragments, then only those the
    // shader finds outside the light frustum (it discards the rest). Adds to mQueryCounts.
    void countFragments(const gl::Program& program, int drawn);

    void resolve(const Terms& t, const scene::Scene& scene, const FrameInput& input);

    std::unique_ptr<render::FullscreenTriangle> mTriangle;
    std::map<std::string, gl::Program> mPlanePrograms, mResolvePrograms;
    gl::VertexArray mVao;
    gl::Framebuffer mFramebuffer;
    gl::Buffer mCounters;
    gl::Texture mNoise, mAccum, mPlane, mAirlight;
    // depth_test=1: the first surface's depth from its distance (slices/depth.frag), what the planes are
    // tested against; its program and framebuffer.
    gl::Texture mDepth;
    gl::Program mDepthProgram;
    gl::Framebuffer mDepthFramebuffer;
    void writeSurfaceDepth(const FrameInput& input, const CameraBasis& basis);
    // The uniforms of slices/pixel_ray.glsl (the camera basis, the image size, the field of view).
    static void setPixelRay(const gl::Program& program, const CameraBasis& basis, const FrameInput& input);
    double mLastStoreScale = 1.0;
    std::vector<int> mPlanesUsed;                         // per drawn light, after distance scaling
    render::MeshView mMeshView;
    std::vector<std::vector<glm::dvec3>> mPolygons;       // drawn planes, clipped (eye-relative world)
    double mQueryCounts[2] = {0.0, 0.0};  // occlusion queries: outside the frustum, all
    gl::SamplesPassedQuery mCountQuery;
    // The fragments of the last plane drawn alone (slices.plane), one query per drawn light, read when
    // the plane's note is written (after the stage's draws, so the count waits for nothing else).
    std::vector<gl::SamplesPassedQuery> mPlaneQueries;
    int mPlaneQueriesUsed = 0;
    // "N fragments: " to start slices.plane's note, and why a plane with none is black.
    std::string planeFragmentsNote();
    // slices.plane: plane `drawn` alone when it was drawn (Terms::lastPlane), else its entry saying why not.
    Intermediate planeIntermediate(int drawn, bool wasDrawn);
    glm::vec3 mMaskColour{1.0f};
    // The picked pixel's planes (slices.ray_planes).
    gl::Buffer mPickRecords;
    gl::Texture mReplay;
    gl::Program mReplayProgram;
    std::vector<PickSet> mPickSets;
    glm::ivec2 mPickPixel{0};
    std::shared_ptr<Image> mRayPlanes;
};

}  // namespace viz::slices_detail
