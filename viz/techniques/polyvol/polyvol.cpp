#include "techniques/polyvol/polyvol.h"

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <map>
#include <memory>
#include <string>

#include "core/error.h"
#include "gl/buffer.h"
#include "gl/framebuffer.h"
#include "debug/permutations.h"
#include "gl/program.h"
#include "gl/readback.h"
#include "gl/stage_clock.h"
#include "gl/texture.h"
#include "gl/vertex_array.h"
#include "render/eye_space.h"
#include "render/host_device.h"
#include "render/intermediates.h"
#include "render/light_culling.h"
#include "render/scene_view.h"
#include "render/shadow_map_markers.h"
#include "scene/camera.h"
#include "render/mesh_view.h"
#include "techniques/polyvol/adaptive_tessellation.h"
#include "techniques/polyvol/airlight_lut.h"
#include "techniques/polyvol/crack_check.h"
#include "techniques/polyvol/light_volume_mesh.h"
#include "techniques/polyvol/volume_crossings.h"
#include "techniques/polyvol/volume_grid.h"

namespace viz {
namespace {

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

enum StageIndex { kShadowMapsIndex = 0, kSurfaceIndex = 1, kVolumeIndex = 2, kComposeIndex = 3 };

using polyvol::kModeCube;
using polyvol::kModeDirectional;
using polyvol::kModeSpot;

// Shader permutations: feature -> {define when enabled, define when disabled}. Others are run-time.
const PermutationTable kDefines = {
    {"SPOT", {nullptr, "LIGHTS_NO_SPOT"}},
    {"COOKIE", {nullptr, "LIGHTS_NO_COOKIE"}},
    {"SHADOW_MAPS_CUBE", {nullptr, "SHADOW_NO_CUBE"}},
    {"SHADOW_MAPS_2D", {nullptr, "SHADOW_NO_2D"}},
    {"AIRLIGHT_LUT", {"AIRLIGHT_LUT", nullptr}},
};

// The smallest shadow map at which adaptive tessellation paid off on every built-in scene measured
// (README, benchmark: forest broke even between 256^2 and 512^2).
constexpr int kAdaptivePaysFrom = 512;

// Whether the settings ask for adaptive tessellation at a size where the plan keeps it (or force it);
// the plan also needs a 2D map in the scene.
bool adaptiveBySettings(const Settings& s) {
    return s.at("tessellation") != 0.0 &&
           (int(s.at("shadow_map")) >= kAdaptivePaysFrom || s.at("force_features") != 0.0);
}

class PolyvolTechnique final : public Technique {
public:
    PolyvolTechnique() {
        mParams = {
            {"tessellation", "static: one vertex per shadow-map texel; adaptive: refined where the Laplacian is large",
             0, 0, 1, true, {"static", "adaptive"}},
            {"airlight", "analytic: the stable segment integral (common/airlight.glsl: Gauss-Legendre panels for "
                        "point and spot lights, closed form for suns); lut: 2D lookup table (supplement)",
             0, 0, 1, true, {"analytic", "lut"}},
            {"threshold", "adaptive: Laplacian of the vertex distances, relative to the map's depth range, above which a "
             "vertex needs the finest level", 1e-4, 0, 1e3, false},
            {"spot_pieces", "spot and VPL lights: equal-angle pieces per penumbra (or lobe) part of a segment", 8, 1, 256,
             true},
            {"crack_check", "1: constant integrand; the signed crossing count per pixel reveals holes", 0, 0, 1, true},
            {"draw_triangles", "stepping: draw only the first N triangles of each light volume (0: all)", 0, 0, 1e12,
             true},
            {"origin", "eye: each crossing adds +-L(0, x); surface: -+L(x, d), plus c L(0, d) once per pixel "
             "(crossings clamped to d add exactly 0)", 0, 0, 1, true, {"eye", "surface"}},
            {"wireframe", "also draw the volume mesh as a wireframe (polyvol.mesh): camera (from the camera), light "
             "(from the first 2D light), orbit (from an orbit camera of its own: mesh_yaw, mesh_pitch, mesh_zoom; with "
             "the scene, the camera frustum and the lights)", 0, 0, 3, true, {"off", "camera", "light", "orbit"}},
            {"mesh_yaw", "wireframe=orbit: orbit camera's angle about the vertical (degrees)", 35, -360, 360, false},
            {"mesh_pitch", "wireframe=orbit: orbit camera's angle above the horizon (degrees)", 25, -89, 89, false},
            {"mesh_zoom", "wireframe=orbit: orbit camera's zoom (1 fits the scene and the camera)", 1, 0.05, 50, false},
            {"stop_level", "adaptive stepping: quads of this level are not refined further (-1: refine fully)", -1, -1,
             13, true},
            {"cookie_mask", "cookie texels darker than this (brightest channel, linear) close the volume", 1.0 / 512.0,
             0, 1, false},
        };
        for (ParamInfo& p : render::SceneViewPasses::params()) mParams.push_back(std::move(p));
        mParams.push_back(forceFeaturesParam());
        mStages = {
            render::SceneViewPasses::shadowStage("polyvol"),
            render::SceneViewPasses::surfaceStage("polyvol"),
            {kStageVolume, "Light volume",
             "closed mesh from the shadow map, drawn with signed additive airlight terms at each crossing",
             {"tessellation", "airlight", "threshold", "spot_pieces", "crack_check", "draw_triangles", "origin",
              "wireframe", "mesh_yaw", "mesh_pitch", "mesh_zoom", "stop_level", "cookie_mask", "force_features"},
             {kEdgeMap, kTessLevels, kMesh, kCrossings, kPositive, kNegative, kTotal, kCracks, kLut, kLutError},
             1, "stop_level", "", {kMesh}},
            render::SceneViewPasses::composeStage("polyvol"),
        };
    }

    // Stepping the adaptive refinement coarse to fine: stop_level = the coarse grid's level (16^2 quads),
    // then one level finer per step, then -1 (refined fully). No sub-steps with static tessellation or
    // when the plan leaves adaptive out below its break-even size.
    std::vector<double> substepValues(int stage, const Settings& s) const override {
        if (stage != kVolumeIndex) return Technique::substepValues(stage, s);
        const int n = int(s.at("shadow_map"));
        if (!adaptiveBySettings(s) || n < 16 || !std::has_single_bit(unsigned(n))) return {};
        const int coarse = std::countr_zero(unsigned(n)) - polyvol::AdaptiveTessellation::kCoarseSteps;
        std::vector<double> values;
        for (int level = coarse; level >= 1; --level) values.push_back(double(level));
        values.push_back(-1.0);
        return values;
    }

    std::string id() const override { return "polyvol"; }
    std::string description() const override {
        return "polygonal light volumes from the shadow map, signed airlight per crossing (Billeter 2010)";
    }
    const std::vector<StageInfo>& stages() const override { return mStages; }
    const std::vector<ParamInfo>& params() const override { return mParams; }
    bool needsGl() const override { return true; }

    // Issue 9's knobs: the shadow-map size (the volume's resolution, one vertex per texel) with static
    // tessellation, then adaptive at the sizes where it was measured to pay off (README, benchmark).
    // The quick sweep also takes area lights as one VPL (area_samples=1, label "1vpl"): tv-room's 16 VPL
    // cube volumes cost ~6 s per run in Release on llvmpipe (every crossing integrates the cosine lobe
    // in 8 pieces), which alone would exceed the quick report's budget; other scenes have no area light.
    std::vector<QualitySetting> qualitySweep(bool quick) const override {
        std::vector<QualitySetting> sweep;
        if (quick) {
            // One point: polyvol's volume stage follows cookies texel by texel, which costs seconds per
            // frame on stained-glass, and the quick report has a 5-minute budget for everything.
            sweep.push_back({"map=128 1vpl", {{"shadow_map", 128.0}, {"area_samples", 1.0}}});
            return sweep;
        }
        for (int n : {256, 512, 1024, 2048})
            sweep.push_back({"map=" + std::to_string(n) + " static", {{"shadow_map", double(n)}}});
        for (int n : {512, 1024, 2048})
            sweep.push_back({"map=" + std::to_string(n) + " adaptive", {{"shadow_map", double(n)}, {"tessellation", 1.0}}});
        return sweep;
    }

    // The accurate end: 1024^2 (at 512^2 a ray passing the light within a texel of the plate's shadow
    // boundary in occluder-touching-light is misclassified next to the 1/r^2 singularity: 0.25), adaptive
    // (the same image, half the time), origin=surface (crossings behind d add exactly 0, so a camera
    // inside a closed occluder gets exactly 0 instead of a 4e-9 blend-order residue).
    // Billeter et al. 2010 and its supplement: the airlight lookup table, adaptive tessellation, 1024^2
    // shadow maps (Table 1's smallest size).
    Settings paperSettings() const override {
        return {{"airlight", 1.0}, {"tessellation", 1.0}, {"shadow_map", 1024.0}};
    }
    Settings stiffSettings() const override {
        return {{"shadow_map", 1024.0}, {"tessellation", 1.0}, {"origin", 1.0}};
    }

    // Measured by `airlight report --suite stiff` at 33x25 (figures in README.md), bounds about twice that.
    std::optional<StiffBound> stiffBound(const std::string& caseClass) const override {
        static const std::map<std::string, StiffBound> kBounds = {
            {"medium", {0.005, "closed-form segments are exact in sigma; what is left is the shadow map's (0.0022)"}},
            {"intensity", {0.004, "linear in the intensity; float holds 1e-3 to 1e7 (0.0017)"}},
            {"scale", {0.004, "eye-relative vertices, distance-valued maps, cone roots solved in units of |light| "
                              "(0.0017; 0.96 at 1e4 before the roots were scaled)"}},
            {"singular-ray", {0.003, "the ray's chord through a ball around the light is integrated once per pixel, "
                                     "the cone cuts are solved relative to the light (ray-through-light 0.0011)"}},
            {"near-light", {1e-4, "the chord through the ball around the light is integrated in closed form "
                                   "with the ray's own distance from the light (8.4e-7)"}},
            {"epipole", {0.045, "no epipolar structure; grazing sun is the worst: shadow-map edges (0.021)"}},
            {"camera-placement", {0.008, "depth clamp keeps faces before the near plane; origin=surface makes "
                                         "crossings behind d add exactly 0 (0.0039)"}},
            {"geometry", {0.05, "shadow-map rasterisation drops slivers the reference still hits (0.024)"}},
            {"leak", {0.002, "the volume's triangles are linear between texel centres: a grazing plane is exact (0.0007)"}},
            {"depth-range", {0.02, "distance-valued R32F maps; the volume is as coarse as the 1e6-wide map (0.0099)"}},
            {"phase", {0.016, "the HG lobe is inside the closed form of each segment; g = 0.99 is the worst (0.0079)"}},
        };
        const auto it = kBounds.find(caseClass);
        return it == kBounds.end() ? std::nullopt : std::optional<StiffBound>(it->second);
    }

    Plan plan(const scene::Scene& scene, const Settings& settings) const override {
        Plan p;
        for (const StageInfo& s : mStages) p.stages.push_back({s.id, true, ""});
        const bool constant = settings.at("crack_check") != 0.0;
        if (scene.medium.sigma_s == 0.0 && !constant) {
            p.stages[kVolumeIndex].runs = false;
            p.stages[kVolumeIndex].why = "sigma_s = 0: the medium scatters nothing, L_air = 0";
        } else {
            const int n = int(settings.at("shadow_map"));
            std::int64_t triangles = 0;
            // VPL cubes are capped at 256^2 per face (render::SceneViewPasses).
            const int vpl = std::min(n, 256);
            const int areaSamples = int(settings.at("area_samples"));
            auto cube = [](int m) { return gridTriangleCountFor(m, 6) + 12 * 2 * std::int64_t(m - 1) + 8; };
            for (const scene::Light& l : scene.lights) {
                if (!render::lightReachesView(l, scene.camera)) continue;  // culled: no map, no volume
                if (l.type == scene::LightType::Point) {
                    triangles += cube(n);
                } else if (l.type == scene::LightType::Area) {
                    triangles += std::int64_t(areaSamples) * areaSamples * cube(vpl);
                } else {
                    triangles += gridTriangleCountFor(n, 1) + 3 * 4 * std::int64_t(n - 1);
                }
            }
            const bool adaptive = settings.at("tessellation") != 0.0;
            p.stages[kVolumeIndex].why =
                adaptive ? "adaptive tessellation: at most " + std::to_string(triangles) +
                               " triangles (the static count; the run's count is in polyvol.mesh), " +
                               std::to_string(n) + "^2 texels per map"
                         : std::to_string(triangles) + " triangles (static tessellation, " + std::to_string(n) +
                               "^2 texels per map)";
        }
        const bool hasSpot = render::hasLightOfType(scene, scene::LightType::Spot);
        const bool hasCookie = std::any_of(scene.lights.begin(), scene.lights.end(), [](const scene::Light& l) {
            return l.type == scene::LightType::Spot && l.cookie >= 0;
        });
        const bool hasPoint = render::hasLightOfType(scene, scene::LightType::Point);
        const bool maps2D = hasSpot || render::hasLightOfType(scene, scene::LightType::Directional);
        const bool lut = settings.at("airlight") != 0.0;
        p.features.push_back({"SPOT", hasSpot,
                              hasSpot ? "spot cone: volume follows the cone; segments clipped to the cones, " +
                                            std::to_string(int(settings.at("spot_pieces"))) +
                                            " equal-angle pieces per penumbra part"
                                      : "no spot light in the scene"});
        p.features.push_back({"COOKIE", hasCookie,
                              hasCookie ? "cookie: dark texels close the volume; colour per angular piece, about one "
                                          "piece per cookie texel (at most 64)"
                                        : "no spot light has a cookie"});
        const bool hasArea = render::hasLightOfType(scene, scene::LightType::Area);
        p.features.push_back({"SHADOW_MAPS_CUBE", hasPoint || hasArea,
                              hasPoint || hasArea
                                  ? "point lights / area-light VPLs: six grids from the cube map, stitched at the seams"
                                  : "no point or area light: no cube-map grids or seams"});
        p.features.push_back({"SHADOW_MAPS_2D", maps2D,
                              maps2D ? "spot / directional lights: one grid each" : "no spot or directional light"});
        p.features.push_back({"AIRLIGHT_LUT", lut,
                              lut ? "airlight=lut: 2D table of the unit point-light integral (supplement)"
                                  : "airlight=analytic: segment integral of common/airlight.glsl, no table"});
        const int areaSamples = int(settings.at("area_samples"));
        p.features.push_back({"AREA_VPLS", hasArea,
                              hasArea ? "each area light -> " + std::to_string(areaSamples * areaSamples) +
                                            " virtual point lights, each a cube light volume (cosine lobe over "
                                            "equal-angle pieces)"
                                      : "no area light in the scene"});
        // Adaptive tessellation is left out below the shadow-map size where it stops paying off
        // (measured, README "Benchmark: static vs adaptive": from 256^2 on colonnade but only from 512^2
        // on forest, where the edge map and refinement passes cost more than the triangles they save).
        // force_features=1 keeps it on at any size, so its steps can be shown on small maps.
        const bool adaptiveAsked = settings.at("tessellation") != 0.0;
        const bool forced = settings.at("force_features") != 0.0;
        const int mapSize = int(settings.at("shadow_map"));
        const bool pays = mapSize >= kAdaptivePaysFrom;
        const bool adaptive = maps2D && adaptiveBySettings(settings);
        std::string why;
        if (!adaptiveAsked)
            why = "tessellation=static: one vertex per texel" +
                  std::string(maps2D && pays ? " (adaptive measured faster from 512^2)" : "");
        else if (!maps2D)
            why = "tessellation=adaptive but no 2D map: cubes stay static";
        else if (!pays && !forced)
            why = "tessellation=adaptive left out: static tessellation at " + std::to_string(mapSize) + "^2 (below " +
                  std::to_string(kAdaptivePaysFrom) +
                  "^2 adaptive did not pay off: forest 256^2 took 1 061 ms adaptive vs 814 ms static); "
                  "force_features=1 keeps it";
        else
            why = "tessellation=adaptive: edge map, flag hierarchy, refinement from 16^2 coarse quads, 16 patterns, "
                  "indirect draw (2D maps; cubes stay static)" +
                  std::string(pays ? "; measured to pay off at this size" : "; forced on below its break-even size");
        p.features.push_back({"ADAPTIVE", adaptive, why});
        render::planCulledLights(scene, p);
        forcePlan(p, settings.at("force_features") != 0.0, {"SPOT", "COOKIE", "SHADOW_MAPS_CUBE", "SHADOW_MAPS_2D"});
        annotatePermutations(p, kDefines);
        return p;
    }

    FrameOutput run(const FrameInput& input) override {
        const scene::Scene& scene = *input.scene;
        const Settings& s = input.settings;
        FrameOutput out;
        out.plan = plan(scene, s);
        out.timing.clock = gl::StageClock::method();
        const int stop = input.stopAfterStage < 0 ? kComposeIndex : input.stopAfterStage;
        // The light volume mesh view: as `wireframe` says, or (wireframe=off) from the orbit camera when
        // the caller shows polyvol.mesh, so that the view always has a picture.
        mWireMode = int(s.at("wireframe"));
        if (mWireMode == 0 && std::find(input.views.begin(), input.views.end(), kMesh) != input.views.end()) mWireMode = 3;
        gl::StageClock clock;

        mMarkZfar = scene.camera.zfar;
        mMarkCookieMask = float(s.at("cookie_mask"));
        mAdaptiveUsed = false;
        mAdaptiveLights.clear();
        mMarkKeysRead = false;

        // ---- shadow maps and camera view ----
        mReuse.begin(input, out);
        if (!mView.runSharedStages(input, stop, mStages, "polyvol", out, mReuse)) return out;

        clock.begin();
        allocateTargets(input.width, input.height);
        const glm::vec4 zero(0.0f);
        mTotal.clear(zero);
        mPositive.clear(zero);
        mNegative.clear(zero);
        mCrossings.clear(zero);
        std::int64_t triangles = 0;
        const bool lut = s.at("airlight") != 0.0;
        if (lut) ensureLut(scene.medium.g);
        if (out.plan.stages[kVolumeIndex].runs) triangles = drawVolumes(scene, input, out.plan);
        clampAirlight();
        out.timing.stages.push_back({kStageVolume, clock.endMilliseconds()});
        publishVolume(out, s, triangles);
        if (lut) {
            out.intermediates.push_back(render::textureIntermediate(
                kLut, "Airlight lookup table",
                "R: A = tau_h int_{-200}^{-|u|} f, G: B = tau_h e^{|u|+rho} int_{|u|}^inf f; x: asinh(|u| / s), "
                "s = tau_h / (1 + tau_h) (left edge: the foot point), y: log tau_h (1e-9 .. 200; below: closed "
                "form), g = " + std::to_string(scene.medium.g) + ", built in " + std::to_string(mLutMs) + " ms",
                "", ViewKind::Color, 0.0f, 2.0f, mLut));
            out.intermediates.back().channels = {{"A (near side)", "", ViewKind::Scalar, 0.0f, 2.0f},
                                                 {"B (far side)", "", ViewKind::Scalar, 0.0f, 2.0f}};
            const float worst = lutError(input);
            out.intermediates.push_back(render::textureIntermediate(
                kLutError, "Lookup table error",
                "|lut - analytic| / analytic of the unshadowed [0, d] per pixel (worst light); max " +
                    std::to_string(worst),
                "", ViewKind::Scalar, 0.0f, 0.01f, mLutError));
        }
        out.lastStageRun = kVolumeIndex;
        if (stop == kVolumeIndex) return out;

        clock.begin();
        out.final = mView.compose(scene, mAirlight, out.intermediates, "polyvol");
        out.timing.stages.push_back({mStages[kComposeIndex].id, clock.endMilliseconds()});
        out.lastStageRun = kComposeIndex;
        return out;
    }

    // Linked cursors. In each light's shadow map, and in the edge map and tessellation levels (the last
    // adaptive 2D light's): the pixel's eye ray projected into the map (cubes: per face) and every crossing
    // of the ray with that light's volume mesh (volume_crossings.h), signed as the volume pass adds it
    // (+1 leaving the lit volume, -1 entering), also those beyond d, so that they add up to the pixel's
    // polyvol.crossings (r: count, g: signed sum) in a one-light scene. Cube marks carry their face.
    std::vector<ViewMarker> markersFor(glm::ivec2 pixel, const std::string& id) const override {
        int index = render::shadowMapIndexOf(id, "polyvol");
        if (index < 0 && (id == kEdgeMap || id == kTessLevels) && mAdaptiveUsed) index = mEdgeLight;
        if (index < 0 || index >= mView.lights().count()) return {};
        const render::GpuLightCpu& L = mView.lights().lights()[std::size_t(index)];
        const bool flat = L.info.x == render::hd::kLightSpot || L.info.x == render::hd::kLightDirectional;
        if (L.info.z < 0 || (!flat && (id == kEdgeMap || id == kTessLevels))) return {};
        glm::dvec3 w;
        double d = 0.0;
        if (!mView.pixelRay(pixel, w, d)) return {};
        const int n = mView.shadows().size();
        polyvol::VolumeGrid grid = describe(L, index, n, mMarkZfar, mMarkCookieMask);
        // An adaptive volume: its triangles as emitted, read back; only the last adaptive light's are
        // still in the buffer, the others are marked with their static mesh (the adaptive one agrees with
        // it up to `threshold`).
        const bool adaptive = std::find(mAdaptiveLights.begin(), mAdaptiveLights.end(), index) != mAdaptiveLights.end();
        const std::vector<std::uint32_t>* keys = nullptr;
        if (adaptive && index == mEdgeLight) {
            grid.keyStride = n + 1;
            keys = &adaptiveKeys();
        }
        std::vector<polyvol::VolumeCrossing> crossings;
        if (flat) {
            crossings = polyvol::volumeCrossings(grid, L, mView.shadows().texels(L, 0), w, keys);
        } else {
            std::array<const std::vector<float>*, 6> faces{};
            for (int f = 0; f < 6; ++f) faces[std::size_t(f)] = &mView.shadows().texels(L, f);
            crossings = polyvol::cubeVolumeCrossings(grid, L, faces, w);
        }
        int sum = 0;
        for (const polyvol::VolumeCrossing& c : crossings) sum += c.sign;
        std::vector<ViewMarker> marks;
        char text[160];
        // Cube maps: marks on the face (layer) the point's direction from the light selects.
        const auto faceOf = [&](const glm::dvec3& p) {
            if (flat) return 0;
            const glm::dvec3 v = p - glm::dvec3(L.position), a = glm::abs(v);
            const int axis = (a.x >= a.y && a.x >= a.z) ? 0 : (a.y >= a.z ? 1 : 2);
            return 2 * axis + (v[axis] < 0.0 ? 1 : 0);
        };
        for (const render::MapStretch& s : render::walkShadowMap(mView.shadows(), L, w, d).stretches) {
            std::snprintf(text, sizeof text, "eye ray t=%.2f..%.2f: %d crossings, signed %+d%s", s.t0, s.t1,
                          int(crossings.size()), sum, adaptive && !keys ? " (static mesh)" : "");
            marks.push_back({render::shadowMapUv(L, s.face, s.t0 * w), render::shadowMapUv(L, s.face, s.t1 * w), text,
                             flat ? -1 : s.face});
        }
        for (const polyvol::VolumeCrossing& c : crossings) {
            const int face = faceOf(c.t * w);
            const glm::vec2 uv = render::shadowMapUv(L, face, c.t * w);
            // Crossings on a directional volume's skirt lie outside the map: not drawable there.
            if (!(uv.x >= -1e-3f && uv.y >= -1e-3f && uv.x <= 1.001f && uv.y <= 1.001f)) continue;
            std::snprintf(text, sizeof text, c.sign > 0 ? "+1 leaves lit t=%.2f%s" : "-1 enters lit t=%.2f%s", c.t,
                          c.t > d ? " (beyond d)" : "");
            marks.push_back({uv, uv, text, flat ? -1 : face});
        }
        return marks;
    }

private:
    // The keys of the last adaptive light's triangles (3 per triangle), read back once per run.
    const std::vector<std::uint32_t>& adaptiveKeys() const {
        if (!mMarkKeysRead) {
            const std::size_t count = std::size_t(std::max<std::int64_t>(0, mTess.triangles())) * 3;
            mMarkKeys.assign(std::min(count, mTess.keys().bytes() / sizeof(std::uint32_t)), 0u);
            if (!mMarkKeys.empty()) mTess.keys().download(0, mMarkKeys.size() * sizeof(std::uint32_t), mMarkKeys.data());
            mMarkKeysRead = true;
        }
        return mMarkKeys;
    }

    static std::int64_t gridTriangleCountFor(int n, int faces) { return polyvol::gridTriangleCount(n, faces); }

    void allocateTargets(int width, int height) {
        if (mTotal && mTotal.size().x == width && mTotal.size().y == height) return;
        auto make = [&](GLenum format, const char* label) {
            return gl::Texture::create(
                {.target = GL_TEXTURE_2D, .format = format, .size = {width, height, 1}, .levels = 1, .label = label});
        };
        mTotal = make(GL_RGBA32F, kTotal);
        mPositive = make(GL_RGBA32F, kPositive);
        mNegative = make(GL_RGBA32F, kNegative);
        mCrossings = make(GL_RGBA32F, kCrossings);
        mAirlight = make(GL_RGBA32F, "polyvol.airlight");
        mFramebuffer = gl::Framebuffer::create("polyvol.volume_fbo");
        mFramebuffer.attachColor(0, mTotal);
        mFramebuffer.attachColor(1, mPositive);
        mFramebuffer.attachColor(2, mNegative);
        mFramebuffer.attachColor(3, mCrossings);
        mFramebuffer.checkComplete();
    }

    // The table for the medium's g, built from the double closed form when g changes.
    void ensureLut(double g) {
        if (mLut && mLutG == g) return;
        // Built once per process and g (the table depends on nothing else), then uploaded per technique.
        static std::map<double, std::pair<polyvol::AirlightLut, double>> cache;
        auto it = cache.find(g);
        if (it == cache.end()) {
            const auto start = std::chrono::steady_clock::now();
            polyvol::AirlightLut built = polyvol::buildAirlightLut(g, kLutWidth, kLutHeight);
            const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            it = cache.emplace(g, std::make_pair(std::move(built), ms)).first;
        }
        const polyvol::AirlightLut& table = it->second.first;
        mLutMs = it->second.second;
        mLut = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_RG32F, .size = {kLutWidth, kLutHeight, 1},
                                    .levels = 1, .label = kLut});
        mLut.upload(GL_RG, GL_FLOAT, table.rg.data());
        mLut.setFilter(GL_NEAREST, GL_NEAREST);  // read with texelFetch, interpolated in the shader
        mLut.setWrap(GL_CLAMP_TO_EDGE);
        mLutG = g;
    }

    const gl::Program& volumeProgram(const Plan& plan) {
        std::string key;
        const gl::ShaderDefines defines = permutationDefines(plan, kDefines, &key);
        mDefines = defines;
        if (key != mProgramKey || !mProgram) {
            mProgram = gl::Program::compile({.stages = {"polyvol/volume.vert", "polyvol/volume.frag"},
                                             .defines = defines,
                                             .label = "polyvol.volume"});
            mWireProgram = gl::Program::compile({.stages = {"polyvol/volume.vert", "polyvol/wire.frag"},
                                                 .defines = defines,
                                                 .label = "polyvol.wire"});
            mProgramKey = key;
        }
        return mProgram;
    }

    // Extra key lists, uploaded once per kind and size: the closure of a 2D grid of `stride` texels per row
    // (N static, N + 1 adaptive) or the seams of a cube.
    enum class ExtraKind { Closure, Seams };
    const gl::Buffer& extraKeys(ExtraKind kind, int stride, std::int64_t& triangles) {
        Extra& e = mExtras[{int(kind), stride}];
        if (!e.buffer) {
            const bool cube = kind == ExtraKind::Seams;
            const std::vector<std::uint32_t> keys = cube ? polyvol::cubeSeams(stride) : polyvol::gridClosure(stride);
            e.buffer = gl::Buffer::create({.bytes = keys.size() * sizeof(std::uint32_t),
                                           .data = keys.data(),
                                           .flags = 0,
                                           .label = cube ? "polyvol.cube_seams" : "polyvol.grid_closure"});
            e.triangles = std::int64_t(keys.size() / 3);
        }
        triangles = e.triangles;
        return e.buffer;
    }

    // Per light: the draw's geometry. Spot: the unit-depth view plane of the shadow matrix; directional:
    // its near plane, the far depth of empty texels and the cap behind the scene; all from the inverse
    // shadow matrix in double, so the mesh samples exactly the directions the map was rendered with.
    polyvol::VolumeGrid describe(const render::GpuLightCpu& L, int index, int n, double zfar, float cookieMask) const {
        polyvol::VolumeGrid v;
        v.lightIndex = index;
        v.layer = L.info.z;
        v.mapSize = n;
        v.keyStride = n;
        v.cookieMask = cookieMask;
        v.range = L.shadow.y - L.shadow.x;
        const glm::dvec3 pos(L.position);
        if (L.info.x == render::hd::kLightPoint || L.info.x == render::hd::kLightVpl) {
            v.mode = kModeCube;
            v.faces = 6;
            v.vplCube = L.info.x == render::hd::kLightVpl;
            if (v.vplCube) v.mapSize = v.keyStride = mView.shadows().vplSize();
            v.noHit = float((glm::length(pos) + zfar) * 1.01);
            return v;
        }
        const glm::dmat4 inv = glm::inverse(glm::dmat4(L.shadowMatrix));
        auto unproject = [&](double x, double y, double z) {
            const glm::dvec4 q = inv * glm::dvec4(x, y, z, 1.0);
            return glm::dvec3(q) / q.w;
        };
        if (L.info.x == render::hd::kLightSpot) {
            v.mode = kModeSpot;
            const glm::dvec3 axis(L.direction);
            auto plane = [&](double x, double y) {
                const glm::dvec3 d = unproject(x, y, 0.0) - pos;
                return d / glm::dot(d, axis);
            };
            const glm::dvec3 o = plane(0, 0);
            v.planeOrigin = glm::vec3(o);
            v.planeX = glm::vec3(plane(1, 0) - o);
            v.planeY = glm::vec3(plane(0, 1) - o);
            v.noHit = float((glm::length(pos) + zfar) * 1.01);
            return v;
        }
        v.mode = kModeDirectional;
        const glm::dvec3 o = unproject(0, 0, -1);
        const glm::dvec3 x = unproject(1, 0, -1) - o, y = unproject(0, 1, -1) - o;
        v.planeOrigin = glm::vec3(o), v.planeX = glm::vec3(x), v.planeY = glm::vec3(y);
        // Every point the camera can see is within zfar of the eye (the origin): the border ring is
        // pushed out far enough to cover them, empty texels reach past them, the cap lies behind them.
        const double half = std::min(glm::length(x), glm::length(y));
        const double reach = glm::length(o) + zfar;
        v.skirt = float(1.0 + (reach + half) / half);
        const double margin = 0.01 * (reach + half);
        v.noHit = float(std::max(double(L.shadow.y), zfar) + margin);
        v.capDepth = float(std::min(double(L.shadow.x), -zfar) - margin);
        return v;
    }

    std::int64_t drawVolumes(const scene::Scene& scene, const FrameInput& input, const Plan& plan) {
        const Settings& s = input.settings;
        const scene::Camera& cam = scene.camera;
        const gl::Program& program = volumeProgram(plan);
        const int n = mView.shadows().size();
        // wireframe=3: the mesh from an orbit camera of its own, over the scene, the camera frustum and
        // the lights (render::MeshView); set up before the volume pass's state.
        if (mWireMode == 3)
            mMeshView.begin(scene, mView.gpuScene(),
                            {s.at("mesh_yaw"), s.at("mesh_pitch"), s.at("mesh_zoom")}, input.width, input.height);
        // Each light's ball radius, before the volume pass's state: nearRadius runs a compute pass.
        mNearRadii.clear();
        for (const render::GpuLightCpu& L : mView.lights().lights())
            mNearRadii.push_back(L.info.z < 0 || s.at("crack_check") != 0.0 ? 0.0f : nearRadius(L, cam, input.height));
        program.use();
        program.set("uViewProj", render::eyeRelativeViewProjection(cam, input.width, input.height));
        program.set("uSize", glm::ivec2(input.width, input.height));
        program.set("uForward", glm::vec3(cam.forward));
        program.set("uNear", float(cam.znear));
        program.set("uRight", glm::vec3(scene::cameraRight(cam)));
        program.set("uUp", glm::vec3(cam.up));
        program.set("uTanHalf", float(std::tan(cam.yfov * 0.5)));
        program.set("uAspect", float(scene::aspectOf(cam, input.width, input.height)));
        program.set("uSigmaS", float(scene.medium.sigma_s));
        program.set("uSigmaT", float(scene.medium.sigma_t()));
        program.set("uG", float(scene.medium.g));
        program.set("uSpotPieces", int(s.at("spot_pieces")));
        program.set("uConstant", int(s.at("crack_check")));
        const bool atSurface = s.at("origin") != 0.0;
        program.set("uOriginAtSurface", atSurface ? 1 : 0);
        mView.lights().bind();
        mView.shadows().bind();
        mView.surface().distance().bindUnit(render::hd::kFirstFreeTextureUnit);
        if (mLut) mLut.bindUnit(render::hd::kFirstFreeTextureUnit + 1);
        if (mVao.id() == 0) mVao = gl::VertexArray::create("polyvol.vao");
        mVao.bind();
        mFramebuffer.bind();
        glViewport(0, 0, input.width, input.height);
        glDisable(GL_DEPTH_TEST);
        glDepthMask(GL_FALSE);
        glDisable(GL_CULL_FACE);
        // Faces between the eye and the near plane must still count (ours: Billeter Sec. 5 disables the depth
        // test and clamps each fragment to the depth buffer, which volume.frag does, but is silent on the
        // near plane).
        glEnable(GL_DEPTH_CLAMP);
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(GL_ONE, GL_ONE);
        const std::int64_t limit = std::int64_t(s.at("draw_triangles"));
        const bool adaptiveWanted = featureEnabled(plan, "ADAPTIVE");
        const int wire = mWireMode;
        mWireDrawn = false;
        if (wire) {
            if (!mWire || mWire.size().x != input.width || mWire.size().y != input.height) {
                mWire = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_RGBA8,
                                             .size = {input.width, input.height, 1}, .levels = 1,
                                             .label = kMesh});
                mWireFramebuffer = gl::Framebuffer::create("polyvol.wire_fbo");
                mWireFramebuffer.attachColor(0, mWire);
                mWireFramebuffer.checkComplete();
            }
            mWire.clear(glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
        }
        std::int64_t drawn = 0;
        mAdaptiveUsed = false;
        mAdaptiveOverflow = false;
        const auto& lights = mView.lights().lights();
        for (int i = 0; i < int(lights.size()); ++i) {
            const render::GpuLightCpu& L = lights[std::size_t(i)];
            const int type = L.info.x;
            if (L.info.z < 0) continue;
            (void)type;
            polyvol::VolumeGrid grid = describe(L, i, n, cam.zfar, float(s.at("cookie_mask")));
            const bool adaptive = adaptiveWanted && grid.mode != kModeCube;
            // The crack detector counts crossings of the whole mesh: no ball there.
            const float radius = mNearRadii[std::size_t(i)];
            program.set("uNearRadius", radius);
            std::int64_t extraTriangles = 0;
            if (adaptive) {
                // Compute passes in between: the draw state is set again afterwards.
                grid.keyStride = n + 1;
                mTess.build(grid, s.at("threshold"), int(substepLimit(input, kVolumeIndex)), mDefines, mProgramKey);
                mAdaptiveUsed = true;
                mEdgeLight = i;
                mAdaptiveLights.push_back(i);
                mAdaptiveOverflow = mAdaptiveOverflow || mTess.overflowed();
                mView.lights().bind();
                mView.shadows().bind();
                mFramebuffer.bind();
                mVao.bind();
                program.use();
                setGridUniforms(program, grid);
                program.set("uGridVertices", 0);
                mTess.keys().bindBase(GL_SHADER_STORAGE_BUFFER, render::hd::kFirstFreeSsboBinding);
                mTess.counters().bind(GL_DRAW_INDIRECT_BUFFER);
                glDrawArraysIndirect(GL_TRIANGLES, reinterpret_cast<const void*>(polyvol::AdaptiveTessellation::drawOffset()));
                drawn += mTess.triangles();
                const gl::Buffer& closure = extraKeys(ExtraKind::Closure, n + 1, extraTriangles);
                closure.bindBase(GL_SHADER_STORAGE_BUFFER, render::hd::kFirstFreeSsboBinding);
                glDrawArrays(GL_TRIANGLES, 0, GLsizei(3 * extraTriangles));
                drawn += extraTriangles;
                if (wire) drawWire(input, L, grid, 0, extraTriangles, true);
                if (atSurface || radius > 0.0f) resolve(input, i, radius);
                continue;
            }
            const std::int64_t gridTriangles = polyvol::gridTriangleCount(grid.mapSize, grid.faces);
            const gl::Buffer& keys = extraKeys(grid.mode == kModeCube ? ExtraKind::Seams : ExtraKind::Closure,
                                               grid.mapSize, extraTriangles);
            keys.bindBase(GL_SHADER_STORAGE_BUFFER, render::hd::kFirstFreeSsboBinding);
            setGridUniforms(program, grid);
            program.set("uGridVertices", int(3 * gridTriangles));
            std::int64_t count = gridTriangles + extraTriangles;
            if (limit > 0) count = std::min(count, limit);
            glDrawArrays(GL_TRIANGLES, 0, GLsizei(3 * count));
            drawn += count;
            if (wire) drawWire(input, L, grid, gridTriangles, std::min(count, gridTriangles + extraTriangles) - gridTriangles, false);
            if (atSurface || radius > 0.0f) resolve(input, i, radius);
        }
        glDisable(GL_DEPTH_CLAMP);
        glDisable(GL_BLEND);
        glDepthMask(GL_TRUE);
        gl::Framebuffer::bindDefault();
        return drawn;
    }

    // The wireframe of one light's volume into polyvol.mesh, from the camera (wireframe=1) or from the
    // first 2D light (wireframe=2, through its shadow matrix). Restores the volume pass's state.
    void drawWire(const FrameInput& input, const render::GpuLightCpu& L, const polyvol::VolumeGrid& grid,
                  std::int64_t gridTriangles, std::int64_t extraTriangles, bool adaptive) {
        const int wire = mWireMode;
        glm::mat4 viewProj = render::eyeRelativeViewProjection(input.scene->camera, input.width, input.height);
        if (wire == 2) {
            if (grid.mode == polyvol::kModeCube || mWireDrawn) return;
            viewProj = L.shadowMatrix;
        }
        if (wire == 3) viewProj = mMeshView.viewProj();
        mWireDrawn = true;
        mWireProgram.use();
        setGridUniforms(mWireProgram, grid);
        mWireProgram.set("uViewProj", viewProj);
        if (wire == 3) mMeshView.bindTarget();
        else mWireFramebuffer.bind();
        glDisable(GL_BLEND);
        glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
        if (adaptive) {
            mWireProgram.set("uGridVertices", 0);
            mTess.keys().bindBase(GL_SHADER_STORAGE_BUFFER, render::hd::kFirstFreeSsboBinding);
            mTess.counters().bind(GL_DRAW_INDIRECT_BUFFER);
            glDrawArraysIndirect(GL_TRIANGLES, reinterpret_cast<const void*>(polyvol::AdaptiveTessellation::drawOffset()));
            std::int64_t closure = 0;
            extraKeys(ExtraKind::Closure, grid.keyStride, closure).bindBase(GL_SHADER_STORAGE_BUFFER,
                                                                              render::hd::kFirstFreeSsboBinding);
            glDrawArrays(GL_TRIANGLES, 0, GLsizei(3 * closure));
        } else {
            mWireProgram.set("uGridVertices", int(3 * gridTriangles));
            glDrawArrays(GL_TRIANGLES, 0, GLsizei(3 * (gridTriangles + extraTriangles)));
        }
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        glEnable(GL_BLEND);
        mFramebuffer.bind();
        mProgram.use();
    }

    // The radius of the ball around a light whose part of each ray is integrated once per pixel by the
    // resolve instead of between rasterised crossings (README, "Rays next to the light"): at most half the
    // nearest distance the light's shadow map stores (nothing occludes within it; an empty map: half its
    // far plane), and at most kBallPixels pixel footprints at the light's distance (the crossings' rounding,
    // ~1/256 pixel, matters only that close to the light; a larger ball costs two segment integrals per
    // crossing term on more pixels for nothing: +22 % volume time on grate with half the nearest
    // distance alone). 0 for directional lights.
    static constexpr double kBallPixels = 16.0;
    float nearRadius(const render::GpuLightCpu& L, const scene::Camera& cam, int height) const {
        const int type = L.info.x;
        if (type == render::hd::kLightDirectional || L.info.z < 0) return 0.0f;
        const float nearest = mView.shadows().nearest(L, L.shadow.y);
        const double footprint = glm::length(glm::dvec3(L.position)) * 2.0 * std::tan(cam.yfov * 0.5) / double(height);
        return float(std::min(0.5 * double(std::max(nearest, 0.0f)), kBallPixels * footprint));
    }

    // Per light, after its volume: origin=surface adds c L(0, d) (without the ball's chord) and zeroes the
    // light's signed count; every origin adds the airlight of the ray's chord through the ball of radius
    // `radius` around the light. The volume program and blend state are restored for the next light.
    void resolve(const FrameInput& input, int light, float radius) {
        const Settings& s = input.settings;
        const scene::Scene& scene = *input.scene;
        const scene::Camera& cam = scene.camera;
        if (!mResolve || mResolveKey != mProgramKey) {
            mResolve = gl::Program::compile(
                {.stages = {"polyvol/resolve.comp"}, .defines = mDefines, .label = "polyvol.resolve"});
            mResolveKey = mProgramKey;
        }
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
        mResolve.use();
        mResolve.set("uSize", glm::ivec2(input.width, input.height));
        mResolve.set("uForward", glm::vec3(cam.forward));
        mResolve.set("uRight", glm::vec3(scene::cameraRight(cam)));
        mResolve.set("uUp", glm::vec3(cam.up));
        mResolve.set("uTanHalf", float(std::tan(cam.yfov * 0.5)));
        mResolve.set("uAspect", float(scene::aspectOf(cam, input.width, input.height)));
        mResolve.set("uSigmaS", float(scene.medium.sigma_s));
        mResolve.set("uSigmaT", float(scene.medium.sigma_t()));
        mResolve.set("uG", float(scene.medium.g));
        mResolve.set("uSpotPieces", int(s.at("spot_pieces")));
        mResolve.set("uLightIndex", light);
        mResolve.set("uConstant", int(s.at("crack_check")));
        mResolve.set("uOriginAtSurface", s.at("origin") != 0.0 ? 1 : 0);
        mResolve.set("uNearRadius", radius);
        mTotal.bindImage(0, GL_READ_WRITE);
        mPositive.bindImage(1, GL_READ_WRITE);
        mNegative.bindImage(2, GL_READ_WRITE);
        const glm::ivec3 groups = gl::groupCount({input.width, input.height, 1}, mResolve.workGroupSize());
        glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
        glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        mProgram.use();
    }

    // The table against the closed form per pixel (lut_error.comp); returns the image's maximum.
    float lutError(const FrameInput& input) {
        const scene::Scene& scene = *input.scene;
        const scene::Camera& cam = scene.camera;
        if (!mLutErrorProgram) {
            mLutErrorProgram = gl::Program::compile({.stages = {"polyvol/lut_error.comp"},
                                                     .defines = {{"AIRLIGHT_LUT", "1"}},
                                                     .label = "polyvol.lut_error"});
        }
        if (!mLutError || mLutError.size().x != input.width || mLutError.size().y != input.height) {
            mLutError = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_R32F,
                                             .size = {input.width, input.height, 1}, .levels = 1, .label = kLutError});
        }
        const gl::Program& p = mLutErrorProgram;
        p.use();
        p.set("uSize", glm::ivec2(input.width, input.height));
        p.set("uForward", glm::vec3(cam.forward));
        p.set("uRight", glm::vec3(scene::cameraRight(cam)));
        p.set("uUp", glm::vec3(cam.up));
        p.set("uTanHalf", float(std::tan(cam.yfov * 0.5)));
        p.set("uAspect", float(scene::aspectOf(cam, input.width, input.height)));
        p.set("uSigmaS", float(scene.medium.sigma_s));
        p.set("uSigmaT", float(scene.medium.sigma_t()));
        p.set("uG", float(scene.medium.g));
        p.set("uLightCount", mView.lights().count());
        mView.lights().bind();
        mView.surface().distance().bindUnit(render::hd::kFirstFreeTextureUnit);
        mLut.bindUnit(render::hd::kFirstFreeTextureUnit + 1);
        mLutError.bindImage(0, GL_WRITE_ONLY);
        const glm::ivec3 groups = gl::groupCount({input.width, input.height, 1}, p.workGroupSize());
        glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
        const Image e = gl::readTexture(mLutError);
        float worst = 0.0f;
        for (float v : e.pixels) worst = std::max(worst, v);
        return worst;
    }

    // L_air = max(0, total) (clamp.comp).
    void clampAirlight() {
        if (!mClamp) mClamp = gl::Program::compile({.stages = {"polyvol/clamp.comp"}, .label = "polyvol.clamp"});
        mClamp.use();
        mClamp.set("uSize", glm::ivec2(mTotal.size().x, mTotal.size().y));
        mTotal.bindImage(0, GL_READ_ONLY);
        mAirlight.bindImage(1, GL_WRITE_ONLY);
        const glm::ivec3 groups = gl::groupCount({mTotal.size().x, mTotal.size().y, 1}, mClamp.workGroupSize());
        glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }

    void publishVolume(FrameOutput& out, const Settings& s, std::int64_t triangles) {
        const bool constant = s.at("crack_check") != 0.0;
        const std::string count = std::to_string(triangles) + " triangles drawn" +
                                  (mAdaptiveOverflow ? " (adaptive buffers overflowed: mesh cut short)" : "");
        mTriangles = triangles;
        if (mAdaptiveUsed) {
            out.intermediates.push_back(render::textureIntermediate(
                kEdgeMap, "Edge map", "|Laplacian| of the vertex distances / the map's depth range (last 2D light)",
                "", ViewKind::Scalar, 0.0f, float(std::max(1e-6, 10.0 * s.at("threshold"))), mTess.edgeMap()));
            out.intermediates.push_back(render::textureIntermediate(
                kTessLevels, "Tessellation level", "leaf level k of each texel's quad (2^k texels wide), stored k/16; " +
                count, "", ViewKind::Scalar, 0.0f, float(mTess.levels()) / 16.0f, mTess.levelMap()));
        }
        Intermediate mesh;
        if (mWireMode == 3) {
            mesh = render::textureIntermediate(kMesh, "Light volume mesh", "", "", ViewKind::Color, 0.0f, 1.0f,
                                               mMeshView.texture());
        } else if (mWireMode != 0 && mWire) {
            mesh = render::textureIntermediate(kMesh, "Light volume mesh", "", "", ViewKind::Color, 0.0f, 1.0f, mWire);
        }
        mesh.id = kMesh;
        mesh.label = "Light volume mesh";
        mesh.note = count + " (grid: one vertex per shadow-map texel; closure to the light / cap; cube seams)" +
                    (mWireMode != 0 ? "; wireframe: green = rays leave (+L), red = rays enter (-L)" +
                                                    std::string(mWireMode == 3
                                                                    ? "; blue: camera frustum, yellow: lights"
                                                                    : "")
                                              : "; wireframe=camera|light|orbit draws it (orbit: a view of its own)") +
                    (mWireMode == 3 && s.at("wireframe") == 0.0 ? "; drawn because this view is shown (its time counts in the volume stage)" : "");
        mesh.kind = mWireMode != 0 ? ViewKind::Color : ViewKind::Mesh;
        mesh.orbit = mWireMode == 3;
        mesh.picture = mWireMode != 0;
        out.intermediates.push_back(mesh);
        out.intermediates.push_back(render::textureIntermediate(
            kCrossings, "Crossings",
            "r: volume faces crossed by each pixel's ray (overdraw), g: signed count, b: crossings in front of the "
            "near plane (kept by the depth clamp), a: crossings beyond the surface (clamped to d); " + count, "",
            ViewKind::Scalar, 0.0f, 16.0f, mCrossings));
        out.intermediates.back().channels = {{"faces crossed (overdraw)", "faces", ViewKind::Scalar, 0.0f, 16.0f},
                                             {"signed count", "faces", ViewKind::Signed, -4.0f, 4.0f},
                                             {"crossings before the near plane", "faces", ViewKind::Scalar, 0.0f, 4.0f},
                                             {"crossings beyond the surface", "faces", ViewKind::Scalar, 0.0f, 4.0f}};
        const std::string units = constant ? "scene units (lit length)" : "radiance";
        out.intermediates.push_back(render::textureIntermediate(
            kPositive, "Positive terms", "sum of +L(0, x) where rays leave the lit volume, plus the chord through the ball around the light", units, ViewKind::Color,
            0.0f, 1.0f, mPositive));
        out.intermediates.push_back(render::textureIntermediate(
            kNegative, "Negative terms", "sum of L(0, x) where rays enter the lit volume (subtracted)", units,
            ViewKind::Color, 0.0f, 1.0f, mNegative));
        std::string balls;
        for (float r : mNearRadii) {
            char text[32];
            std::snprintf(text, sizeof text, "%s%.3g", balls.empty() ? "" : ", ", double(r));
            balls += text;
        }
        out.intermediates.push_back(render::textureIntermediate(
            kTotal, "Signed total",
            "positive - negative (unclamped; L_air = max(0, total)); each ray's chord through a ball around each "
            "light, radius half its map's nearest distance (" + (balls.empty() ? std::string("none") : balls) +
                "; 0: none), is added once per pixel, not by crossings",
            units, ViewKind::Signed, -1.0f, 1.0f, mTotal));
        const Image total = gl::readTexture(mCrossings);
        const polyvol::CrackReport report = polyvol::countCrackPixels(total, 1);
        auto mask = std::make_shared<Image>(total.width, total.height, 1);
        for (int y = 0; y < total.height; ++y)
            for (int x = 0; x < total.width; ++x)
                mask->at(x, y) = std::fabs(total.at(x, y, 1) - float(report.expected)) < 1e-3f ? 0.0f : 1.0f;
        Intermediate cracks;
        cracks.id = kCracks;
        cracks.label = "Crack pixels";
        cracks.note = std::to_string(report.badPixels) + " bad pixels (signed crossing count != " +
                      std::to_string(report.expected) + ", the volumes containing the eye)";
        cracks.kind = ViewKind::Mask;
        cracks.image = mask;
        cracks.extent = {total.width, total.height, 1};
        out.intermediates.push_back(cracks);
        out.airlight = render::readRgb(mAirlight);
    }

    struct Extra {
        std::int64_t triangles = 0;
        gl::Buffer buffer;
    };

    std::vector<ParamInfo> mParams;
    std::vector<StageInfo> mStages;
    render::SceneViewPasses mView;
    StageReuse mReuse;  // stages carried over from the last run (FrameInput::resumeAtStage)
    gl::Program mProgram;
    std::string mProgramKey;
    gl::Texture mTotal, mPositive, mNegative, mCrossings;
    gl::Framebuffer mFramebuffer;
    gl::VertexArray mVao;
    std::map<std::pair<int, int>, Extra> mExtras;
    polyvol::AdaptiveTessellation mTess;
    bool mAdaptiveUsed = false, mAdaptiveOverflow = false, mWireDrawn = false;
    int mWireMode = 0;  // this run's wireframe: the setting, or orbit for a caller showing polyvol.mesh
    // markersFor: the light whose edge map and levels are shown (the last adaptive 2D light), the camera's
    // zfar and cookie_mask of the last run (they place the volume's vertices).
    int mEdgeLight = -1;
    std::vector<int> mAdaptiveLights;  // lights drawn with adaptive tessellation in the last run
    mutable std::vector<std::uint32_t> mMarkKeys;
    mutable bool mMarkKeysRead = false;
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

}  // namespace

std::unique_ptr<Technique> makePolyvolTechnique() { return std::make_unique<PolyvolTechnique>(); }

}  // namespace viz
