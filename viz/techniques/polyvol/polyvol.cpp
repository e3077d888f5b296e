// polyvol: parameters, stages, plan and the run (polyvol_technique.h).
#include "techniques/polyvol/polyvol.h"

#include <algorithm>

#include "techniques/polyvol/polyvol_technique.h"

namespace viz::polyvol_detail {

const ParamTable<PolyvolSettings>& polyvolParams() {
    using S = PolyvolSettings;
    static const ParamTable<S> table =
        ParamTable<S>()
            .add(&S::adaptive, {"tessellation", "static: one vertex per shadow-map texel; adaptive (default): refined "
                                "where the edge measure is large, at the map sizes where that was measured to pay off "
                                "(the plan says which)", 1, 0, 1, true, {"static", "adaptive"}})
            .add(&S::edgeMeasure,
                 {"edge_measure", "adaptive: laplacian (the paper: misses saddles, z = xy) or curvature (the absolute "
                  "second differences along x, y and both diagonals: zero only on a plane)",
                  1, 0, 1, true, {"laplacian", "curvature"}})
            .add(&S::lut, {"airlight", "analytic: the stable segment integral (common/airlight.glsl: Gauss-Legendre "
                           "panels for point and spot lights, closed form for suns); lut: 2D lookup table (supplement)",
                           0, 0, 1, true, {"analytic", "lut"}})
            .add(&S::threshold, {"threshold", "adaptive: edge measure of the vertex depths (directional) or reciprocal "
                                 "depths (spot, cube faces; scaled to a depth), relative to the map's depth range, above "
                                 "which a vertex needs the finest level", 1e-4, 0, 1e3, false})
            .add(&S::spotPieces, {"spot_pieces", "equal-angle pieces per penumbra part of a spot segment with airlight=lut, "
                                  "and the least under a cookie (VPLs' lobes too with airlight=lut); the segment "
                                  "integral takes a penumbra without a cookie, and VPLs' lobes, exactly",
                                  8, 1, 256, true})
            .add(&S::crackCheck, {"crack_check", "1: constant integrand; the signed crossing count per pixel reveals "
                                  "holes", 0, 0, 1, true})
            .add(&S::drawTriangles, {"draw_triangles", "stepping: draw only the first N triangles of each light "
                                     "volume's static mesh (0: all; N > 0 leaves adaptive tessellation out)", 0, 0, 1e12,
                                     true})
            .add(&S::originAtSurface,
                 {"origin", "eye: each crossing adds +-L(0, x); surface: -+L(x, d), plus c L(0, d) once per pixel "
                  "(crossings clamped to d add exactly 0)", 0, 0, 1, true, {"eye", "surface"}})
            .add(&S::wireframe,
                 {"wireframe", "also draw the volume mesh as a wireframe (polyvol.mesh): camera (from the camera), "
                  "light (from the first 2D light), orbit (from an orbit camera of its own: mesh_yaw, mesh_pitch, "
                  "mesh_zoom; with the scene, the camera frustum and the lights)",
                  0, 0, 3, true, {"off", "camera", "light", "orbit"}})
            .declare(orbitParams("wireframe=orbit"))
            .add(&S::stopLevel, {"stop_level", "adaptive stepping: refine this many levels below each grid's coarse "
                                 "16 x 16 quads, then stop (0: the coarse quads alone; -1: refine fully)", -1, -1, 13,
                                 true})
            .add(&S::cookieMask, {"cookie_mask", "cookie texels darker than this (brightest channel, linear) close the "
                                  "volume", 1.0 / 512.0, 0, 1, false})
            .add(&S::shadowMap, render::SceneViewPasses::params(), "shadow_map")
            .add(&S::areaSamples, render::SceneViewPasses::params(), "area_samples")
            .declare(render::SceneViewPasses::params(), "vpl_kernel")
            .add(&S::forceFeatures, forceFeaturesParam());
    VIZ_CHECK(table.missing().empty(), "polyvol declares a shared parameter the shared passes lack");
    return table;
}

PolyvolTechnique::PolyvolTechnique()
    : GlTechnique({.id = "polyvol",
                   .description = "polygonal light volumes from the shadow map, signed airlight per crossing (Billeter 2010)",
                   .controls = {.orbitCamera = true}},
                  polyvolParams()) {
    mStages = {
        render::SceneViewPasses::shadowStage("polyvol"),
        render::SceneViewPasses::surfaceStage("polyvol"),
        {kStageVolume, "Light volume",
         "closed mesh from the shadow map, drawn with signed additive airlight terms at each crossing",
         {"tessellation", "airlight", "edge_measure", "threshold", "spot_pieces", "crack_check", "draw_triangles", "origin",
          "wireframe", "mesh_yaw", "mesh_pitch", "mesh_zoom", "stop_level", "cookie_mask", "force_features"},
         {kEdgeMap, kTessLevels, kMesh, kCrossings, kPositive, kNegative, kTotal, kCracks, kLut, kLutError},
         1, "stop_level", "", {kMesh}, false, /*substepsPerRun=*/true},
        render::SceneViewPasses::composeStage("polyvol"),
    };
    checkStageOrder(mStages, kStageOrder);
}

std::vector<double> PolyvolTechnique::substepValues(int stage, const Settings& settings) const {
    if (stage != kVolumeIndex) return Technique::substepValues(stage, settings);
    const PolyvolSettings s = polyvolParams().read(settings);
    const int n = s.shadowMap;
    if (!s.adaptiveKept() || n < 16 || !std::has_single_bit(unsigned(n))) return {};
    // The 2D map's levels: the most any grid has (VPL cubes are at most as large). A run counts the
    // levels of the grids it refines (FrameOutput::substepCounts): fewer on a scene lit by VPLs alone.
    std::vector<double> values;
    for (int k = 0; k < polyvol::AdaptiveTessellation::refinementLevels(n); ++k) values.push_back(double(k));
    values.push_back(-1.0);
    return values;
}

std::vector<QualitySetting> PolyvolTechnique::qualitySweep(bool quick) const {
    std::vector<QualitySetting> sweep;
    if (quick) {
        // Two points: polyvol's volume stage follows cookies texel by texel, which costs seconds per
        // frame on stained-glass (3.7 s at the default at 160x120, tv-room's 16 VPLs 2.3 s), so the
        // cheap end and the defaults, which the report must measure as a user runs them.
        sweep.push_back({"map=128 1vpl", {{"shadow_map", 128.0}, {"area_samples", 1.0}}});
        sweep.push_back({"map=1024 adaptive", {{"shadow_map", 1024.0}, {"tessellation", 1.0}}});
        return sweep;
    }
    for (int n : {256, 512, 1024, 2048})
        sweep.push_back({"map=" + std::to_string(n) + " static", {{"shadow_map", double(n)}, {"tessellation", 0.0}}});
    for (int n : {512, 1024, 2048})
        sweep.push_back({"map=" + std::to_string(n) + " adaptive", {{"shadow_map", double(n)}, {"tessellation", 1.0}}});
    return sweep;
}

std::optional<StiffBound> PolyvolTechnique::stiffBound(const std::string& caseClass) const {
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
    return boundOf(kBounds, caseClass);
}

namespace {

// Adaptive tessellation of cube faces: each face refined on its own, its border ring at texel resolution so
// that the seams (which join border texels) close the volume without T-junctions.
FeaturePlan adaptiveCubesFeature(const PolyvolSettings& s, bool hasPoint, bool hasArea) {
    if (!hasPoint && !hasArea) return {"ADAPTIVE_CUBES", false, "no point or area light: no cube grids"};
    if (!s.adaptive) return {"ADAPTIVE_CUBES", false, "tessellation=static: one vertex per texel of every cube face"};
    if (s.drawTriangles > 0)
        return {"ADAPTIVE_CUBES", false, "draw_triangles counts the static mesh: one vertex per texel of every cube face"};
    const int point = s.shadowMap, vpl = std::min(s.shadowMap, render::kMaxVplShadowSize);
    const int smallest = hasPoint && hasArea ? std::min(point, vpl) : hasPoint ? point : vpl;
    const std::string faces = hasPoint && hasArea ? std::to_string(point) + "^2 (point) and " + std::to_string(vpl) +
                                                        "^2 (VPL) faces"
                                                  : std::to_string(smallest) + "^2 faces";
    if ((hasPoint && !PolyvolSettings::tessellable(point)) || (hasArea && !PolyvolSettings::tessellable(vpl)))
        return {"ADAPTIVE_CUBES", false,
                "tessellation=adaptive left out on cube grids: " + faces +
                    ", not a power of two of at least 16 (the refinement halves quads down to texels)"};
    if (smallest < kAdaptiveCubesPayFrom && !s.forceFeatures)
        return {"ADAPTIVE_CUBES", false,
                "tessellation=adaptive left out on cube grids: " + faces + "; below " +
                    std::to_string(kAdaptiveCubesPayFrom) +
                    "^2 it did not pay off (tv-room 64^2 faces: 1 518 ms adaptive vs 1 327 ms static); "
                    "force_features=1 keeps it"};
    return {"ADAPTIVE_CUBES", true,
            "tessellation=adaptive on cube grids: each of the six faces refined on its own (" + faces +
                "), border texels kept for the seams"};
}

}  // namespace

Plan PolyvolTechnique::plan(const scene::Scene& scene, const Settings& settings) const {
    const PolyvolSettings s = polyvolParams().read(settings);
    Plan p = planEveryStage(mStages);
    const bool hasPoint = render::hasLightOfType(scene, scene::LightType::Point);
    const bool hasArea = render::hasLightOfType(scene, scene::LightType::Area);
    const bool maps2D = render::hasLightOfType(scene, scene::LightType::Spot) ||
                        render::hasLightOfType(scene, scene::LightType::Directional);
    const FeaturePlan cubes = adaptiveCubesFeature(s, hasPoint, hasArea);
    const bool adaptive2D = maps2D && s.adaptiveKept();
    const bool constant = s.crackCheck;
    if (scene.medium.sigma_s == 0.0 && !constant) {
        p.stages[kVolumeIndex].runs = false;
        p.stages[kVolumeIndex].why = "sigma_s = 0: the medium scatters nothing, L_air = 0";
    } else {
        const int n = s.shadowMap;
        std::int64_t triangles = 0;
        const int vpl = std::min(n, render::kMaxVplShadowSize);
        const int areaSamples = s.areaSamples;
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
        const bool adaptive = adaptive2D || cubes.enabled;
        const std::string texels = std::to_string(n) + "^2 texels per map" +
                                   (hasArea && vpl != n ? ", " + std::to_string(vpl) + "^2 per VPL cube face" : "");
        p.stages[kVolumeIndex].why =
            adaptive ? std::to_string(triangles) +
                           " triangles at most (the static count; adaptive tessellation draws fewer, the run's count "
                           "is in polyvol.mesh), " + texels
                     : std::to_string(triangles) + " triangles (static tessellation, " + texels + ")";
    }
    const bool hasSpot = render::hasLightOfType(scene, scene::LightType::Spot);
    const bool hasCookie = std::any_of(scene.lights.begin(), scene.lights.end(), [](const scene::Light& l) {
        return l.type == scene::LightType::Spot && l.cookie >= 0;
    });
    const bool lut = s.lut;
    p.features.push_back({"SPOT", hasSpot,
                          hasSpot ? "spot cone: volume follows the cone; segments clipped to the cones, " +
                                        (lut ? std::to_string(s.spotPieces) +
                                                   " equal-angle pieces per penumbra part (the table has no lobe)"
                                             : std::string("each penumbra part one segment integral with A_spot "
                                                           "as the square of a lobe"))
                                  : "no spot light in the scene"});
    p.features.push_back({"COOKIE", hasCookie,
                          hasCookie ? "cookie: dark texels close the volume; colour per angular piece, about one "
                                      "piece per cookie texel (at most 64), neighbouring pieces of one colour "
                                      "one segment integral"
                                    : "no spot light has a cookie"});
    p.features.push_back({"SHADOW_MAPS_CUBE", hasPoint || hasArea,
                          hasPoint || hasArea
                              ? "point lights / area-light VPLs: six grids from the cube map, stitched at the seams"
                              : "no point or area light: no cube-map grids or seams"});
    p.features.push_back({"SHADOW_MAPS_2D", maps2D,
                          maps2D ? "spot / directional lights: one grid each" : "no spot or directional light"});
    p.features.push_back({"AIRLIGHT_LUT", lut,
                          lut ? "airlight=lut: 2D table of the unit point-light integral (supplement)"
                              : "airlight=analytic: segment integral of common/airlight.glsl, no table"});
    const int areaSamples = s.areaSamples;
    const bool cells = render::SceneViewPasses::vplKernel(settings) == render::VplKernel::Cell;
    const std::string factor = cells ? "its cell's solid angle" : "the cosine lobe";
    p.features.push_back({"AREA_VPLS", hasArea,
                          hasArea ? "each area light -> " + std::to_string(areaSamples * areaSamples) +
                                        " virtual point lights, " + render::SceneViewPasses::vplKernelText(settings) +
                                        ", each a cube light volume (" +
                                        (lut ? std::to_string(s.spotPieces) + " equal-angle pieces of " + factor +
                                                   " per crossing: the table has none)"
                                             : factor + " integrated exactly in each crossing's segment)")
                                  : "no area light in the scene"});
    // Adaptive tessellation is left out below the shadow-map size where it stops paying off
    // (measured, README "Benchmark: static vs adaptive": from 256^2 on colonnade but only from 512^2
    // on forest, where the edge map and refinement passes cost more than the triangles they save).
    // force_features=1 keeps it on at any size, so its steps can be shown on small maps.
    const bool adaptiveAsked = s.adaptive;
    const bool forced = s.forceFeatures;
    const int mapSize = s.shadowMap;
    const bool pays = mapSize >= kAdaptivePaysFrom;
    std::string why;
    if (!adaptiveAsked)
        why = "tessellation=static: one vertex per texel" +
              std::string(maps2D && pays ? " (adaptive measured faster from 512^2)" : "");
    else if (!maps2D)
        why = "tessellation=adaptive but no 2D map (cube grids: ADAPTIVE_CUBES)";
    else if (s.drawTriangles > 0)
        why = "draw_triangles counts the static mesh: one vertex per texel";
    else if (!PolyvolSettings::tessellable(mapSize))
        why = "tessellation=adaptive left out: " + std::to_string(mapSize) +
              "^2 is not a power of two of at least 16 (the refinement halves quads down to texels)";
    else if (!pays && !forced)
        why = "tessellation=adaptive left out: static tessellation at " + std::to_string(mapSize) + "^2 (below " +
              std::to_string(kAdaptivePaysFrom) +
              "^2 adaptive did not pay off: forest 256^2 took 1 061 ms adaptive vs 814 ms static); "
              "force_features=1 keeps it";
    else
        why = "tessellation=adaptive: edge map, flag hierarchy, refinement from 16^2 coarse quads, 16 patterns, "
              "indirect draw (2D maps; cube grids: ADAPTIVE_CUBES)" +
              std::string(pays ? "; measured to pay off at this size" : "; forced on below its break-even size");
    p.features.push_back({"ADAPTIVE", adaptive2D, why});
    p.features.push_back(cubes);
    render::planCulledLights(scene, p);
    forcePlan(p, s.forceFeatures, {"SPOT", "COOKIE", "SHADOW_MAPS_CUBE", "SHADOW_MAPS_2D"});
    annotatePermutations(p, kDefines);
    return p;
}

FrameOutput PolyvolTechnique::run(const FrameInput& input) {
    const scene::Scene& scene = *input.scene;
    FrameOutput out;
    const PolyvolSettings& s = startRun(input, out);
    // The light volume mesh view: as `wireframe` says, or (wireframe=off) from the orbit camera when
    // the caller shows polyvol.mesh, so that the view always has a picture.
    mWireMode = s.wireframe;
    if (mWireMode == 0 && input.shows(kMesh)) mWireMode = 3;

    mMarkZfar = scene.camera.zfar;
    mMarkCookieMask = float(s.cookieMask);
    mAdaptiveLights.clear();
    mShownTess = nullptr;
    mFlatAdaptiveLight = mCubeAdaptiveLight = -1;
    mMarkKeysRead = {false, false};
    mRebuiltKeys.clear();

    gl::StageClock clock;
    StageRunner stages(mStages, input, out, mReuse, clock);
    if (!mView.runSharedStages(stages, input, "polyvol", out)) return out;

    std::int64_t triangles = 0;
    const bool lut = s.lut;
    const bool more = stages.run(
        kVolumeIndex,
        [&] {
            allocateTargets(input.width, input.height);
            const glm::vec4 zero(0.0f);
            mTotal.clear(zero);
            mPositive.clear(zero);
            mNegative.clear(zero);
            mCrossings.clear(zero);
            if (lut) ensureLut(scene.medium.g);
            if (out.plan.stages[kVolumeIndex].runs) {
                triangles = drawVolumes(scene, input, out.plan);
                // Stepping: one sub-step per level the largest adaptive grid refines, and the whole stage.
                int levels = 0;
                for (int i : mAdaptiveLights)
                    levels = std::max(levels, polyvol::AdaptiveTessellation::refinementLevels(
                                                  mView.shadows().sizeOf(mView.lights().lights()[std::size_t(i)])));
                out.substepCounts[kVolumeIndex] = 1 + levels;
            }
            clampAirlight();
        },
        [&] {
            publishVolume(out, input, triangles);
            if (lut) publishLut(out, input, scene.medium.g);
        });
    if (!more) return out;

    mView.runCompose(stages, kComposeIndex, input, mAirlight, out, "polyvol");
    return out;
}

void PolyvolTechnique::publishLut(FrameOutput& out, const FrameInput& input, double g) {
    out.intermediates.push_back(render::textureIntermediate(
        kLut, "Airlight lookup table",
        "R: A = tau_h int_{-200}^{-|u|} f, G: B = tau_h e^{|u|+rho} int_{|u|}^inf f, B: C = tau_h e^{rho-|u|} int_{-|u|}^0 f; "
        "x: asinh(|u| / s), "
        "s = tau_h / (1 + tau_h) (left edge: the foot point), y: log tau_h (1e-9 .. 200; below: closed "
        "form), g = " + std::to_string(g) + ", built in " + std::to_string(mLutMs) + " ms",
        "", ViewKind::Colour, 0.0f, 2.0f, mLut));
    out.intermediates.back().channels = {{"A (near side)", "", ViewKind::Scalar, 0.0f, 2.0f},
                                         {"B (far side)", "", ViewKind::Scalar, 0.0f, 2.0f},
                                         {"C (near side, from P)", "", ViewKind::Scalar, 0.0f, 2.0f}};
    const float worst = lutError(input);
    out.intermediates.push_back(render::textureIntermediate(
        kLutError, "Lookup table error",
        "|lut - analytic| / analytic of the unshadowed [0, d] per pixel (worst light); max " + std::to_string(worst),
        "", ViewKind::Scalar, 0.0f, 0.01f, mLutError));
}

}  // namespace viz::polyvol_detail

namespace viz {

std::unique_ptr<Technique> makePolyvolTechnique() { return std::make_unique<polyvol_detail::PolyvolTechnique>(); }

}  // namespace viz
