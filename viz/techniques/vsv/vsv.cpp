// vsv: parameters, stages, plan and the run (vsv_technique.h).
#include "techniques/vsv/vsv.h"

#include "techniques/vsv/vsv_technique.h"

#include "scene/ray_reach.h"

namespace viz::vsv_detail {

const ParamTable<VsvSettings>& vsvParams() {
    using S = VsvSettings;
    static const ParamTable<S> table =
        ParamTable<S>()
            .add(&S::voxels, {"voxels", "epipolar grid cells per axis (alpha, theta, phi; phi rounded up to a multiple "
                              "of 32), or AxBxC per axis", 128, 32, 1024, true, {}, {"voxels_alpha", "voxels_theta", "voxels_phi"}})
            .add(&S::voxelsAlpha, {"voxels_alpha", "alpha cells (0: `voxels`)", 0, 0, 1024, true})
            .add(&S::voxelsTheta, {"voxels_theta", "theta cells (0: `voxels`)", 0, 0, 1024, true})
            .add(&S::voxelsPhi, {"voxels_phi", "phi bits (0: `voxels`; rounded up to a multiple of 32)", 0, 0, 1024, true})
            .add(&S::exactCombine, {"combine", "fraction: lit fraction x unshadowed airlight; exact: sum of airlight "
                                    "over lit runs", 1, 0, 1, true, {"fraction", "exact"}})
            .add(&S::alphaBias, {"alpha_bias", "occluder alpha offset in cells (negative: shadow starts further from "
                                 "the light; the paper's -2.25)", 0, -16, 16, false})
            .add(&S::phiBias, {"phi_bias", "light-ray phi offset in cells (negative: shadow moves away from the eye; "
                               "the paper's -1)", 0, -16, 16, false})
            .add(&S::interp, {"interp", "1: two texels along theta; 0: nearest", 1, 0, 1, true})
            .add(&S::dynamicRange, {"dynamic_range", "1: the grid covers only the visible part of epipolar space; 0: "
                                    "all of it", 1, 0, 1, true})
            .add(&S::epipole, {"epipole", "rays within one alpha cell of an epipole: off reads the grid; march tests "
                               "the shadow map along the ray (direct_segments); paper compares the fragment with the "
                               "light (the eye's visibility at the antipode), Wyman and Dai Sec. 5",
                               1, 0, 2, true, {"off", "march", "paper"}})
            .add(&S::directBins, {"direct_bins", "rays crossing fewer phi bins than this test the shadow map directly "
                                  "(0: only rays at an epipole)", 4, 0, 1024, false})
            .add(&S::directSegments, {"direct_segments", "shadow-map tests along a direct ray (epipole or too few phi "
                                      "bins)", 128, 1, 4096, true})
            .add(&S::runBins, {"run_bins", "longest run of phi bins per airlight segment (spot falloff averaged over "
                               "it)", 8, 1, 1024, true})
            .declare({"scan_passes", "stop the alpha scan after this many passes (-1: all; stepping)", -1, -1,
                      kMaxScanPasses, true})
            .declare(pickParam('x', "voxel column"))
            .declare(pickParam('y', "voxel column"))
            .add(&S::pickTheta, {"pick_theta", "theta cell of the unwrapped alpha x phi slices (-1: that of the "
                                 "picked pixel)", -1, -1, 1024, true})
            .add(&S::light, {"light", "which light's grid the intermediates show (index among the scene's lights)", 0,
                             0, 255, true})
            .declare(render::SceneViewPasses::params())
            .add(&S::forceFeatures, forceFeaturesParam());
    return table;
}

VsvTechnique::VsvTechnique()
    : GlTechnique({.id = "vsv",
                   .description = "voxelized shadow volumes (Wyman 2011): epipolar voxel grid, prefix-OR extrusion, one texel per ray",
                   .controls = {.pickedPixel = true}},
                  vsvParams()) {
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
    checkStageOrder(mStages, kStageOrder);
}

std::vector<double> VsvTechnique::substepValues(int stage, const Settings& settings) const {
    if (stage != kScanIndex) return Technique::substepValues(stage, settings);
    const VsvSettings s = vsvParams().read(settings);
    const int alpha = s.voxelsAlpha > 0 ? s.voxelsAlpha : s.voxels;
    std::vector<double> values;
    for (int k = 0; k < scanPassCount(alpha); ++k) values.push_back(double(k));
    values.push_back(-1.0);
    return values;
}

std::vector<QualitySetting> VsvTechnique::qualitySweep(bool quick) const {
    std::vector<QualitySetting> sweep;
    const std::vector<int> sizes = quick ? std::vector<int>{64, 128} : std::vector<int>{32, 64, 128, 256, 512};
    for (int n : sizes) sweep.push_back({"voxels=" + std::to_string(n), {{"voxels", double(n)}}});
    return sweep;
}

Plan VsvTechnique::plan(const scene::Scene& scene, const Settings& settings) const {
    // Without an image size, the camera's aspect ratio (or 4:3) decides what is in view.
    const int h = 120;
    const int w = scene.camera.aspectRatio > 0.0 ? int(std::lround(h * scene.camera.aspectRatio)) : 160;
    return planFor(scene, settings, w, h);
}

FrameOutput VsvTechnique::run(const FrameInput& input) {
    const scene::Scene& scene = *input.scene;
    FrameOutput out;
    const VsvSettings& s = startRun(input, out);
    const std::vector<int> lights = shadedLights(scene);
    const GridSize size = gridSize(s);
    gl::StageClock clock;
    mMark.reset();

    StageRunner stages(mStages, input, out, mReuse, clock);
    if (!mView.runSharedStages(stages, input, "vsv", out)) return out;

    // One grid per light; the stages below run light after light and time the sum. The intermediates
    // show the light chosen by `light`.
    const int shown = std::clamp(s.light, 0, std::max(0, int(lights.size()) - 1));
    const bool dynamic = s.dynamicRange;
    std::vector<vsv::EpipolarGrid> grids;
    for (int li : lights)
        grids.push_back(vsv::gridForLight(scene, scene.lights[std::size_t(li)], input.width, input.height,
                                          size.alpha, size.theta, size.phi, dynamic));
    allocate(size, input.width, input.height, int(lights.size()));
    const bool gatherRuns = out.plan.stages[kGatherIndex].runs;
    const glm::ivec2 pick = pickedPixel(input);
    const int pickX = pick.x, pickY = pick.y;
    int pickTheta = 0;
    if (!lights.empty()) {
        const vsv::EpipolarGrid& g = grids[std::size_t(shown)];
        const vsv::EpipolarFrame f = vsv::frameForLight(scene, scene.lights[std::size_t(lights[std::size_t(shown)])]);
        const glm::dvec3 ray = scene::pixelRay(scene.camera, input.width, input.height, pickX, pickY);
        pickTheta = std::clamp(int(std::floor(vsv::thetaCoord(g, vsv::thetaOf(f, ray)))), 0, g.nTheta - 1);
        if (s.pickTheta >= 0) pickTheta = std::min(s.pickTheta, g.nTheta - 1);
        mMark = MarkState{f, g, scene.camera, {input.width, input.height}, pickTheta};
    }

    // ---- voxelize ----
    const bool toScan = stages.run(
        kVoxelizeIndex,
        [&] {
            for (std::size_t i = 0; i < lights.size(); ++i) voxelize(scene, s, lights[i], grids[i], int(i));
        },
        [&] {
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
                    ViewKind::Mask, vsv::sliceImage(mGrid[std::size_t(shown)], 0, size.alpha, pickTheta, size.phi)));
            }
        });
    if (!toScan) return out;

    // The picked pixel's column as voxelized, for the gather's column view (the scan overwrites the
    // grid): one texel per 128 phi bits, read only when the gather will run.
    if (!lights.empty() && stages.reaches(kGatherIndex)) {
        const glm::ivec2 cell = pickedCell(scene, input, lights[std::size_t(shown)], grids[std::size_t(shown)], pickX, pickY);
        mPreScanColumn = vsv::readGridRow(mGrid[std::size_t(shown)], cell.x, 1, cell.y);
    }

    // ---- scan ----
    const int passSetting = int(substepLimit(input, kScanIndex));
    const int passLimit = passSetting < 0 ? kMaxScanPasses : passSetting;
    const bool toGather = stages.run(
        kScanIndex, [&] { for (std::size_t i = 0; i < lights.size(); ++i) scan(int(i), size, passLimit); },
        [&] {
            if (!lights.empty()) {
                const int passes = std::min(passLimit, scanPassCount(size.alpha));
                out.intermediates.push_back(cpuIntermediate(
                    kScanSlice, "Voxels after " + std::to_string(passes) + " scan passes",
                    "alpha x phi slice at theta cell " + std::to_string(pickTheta) +
                        ": white = shadowed (after all passes: one run from the occluder to the end of alpha)",
                    ViewKind::Mask, vsv::sliceImage(*mResult[std::size_t(shown)], 0, size.alpha, pickTheta, size.phi)));
            }
        });
    if (!toGather) return out;

    // ---- gather ----
    const bool toCompose = stages.run(
        kGatherIndex,
        [&] {
            mAirlight.clear(glm::vec4(0.0f));
            mVisibility.clear(glm::vec4(1.0f, 1.0f, 0.0f, 0.0f));
            if (gatherRuns) {
                if (!lights.empty()) {
                    const gl::Program& program = gatherProgram(out.plan);
                    if (featureEnabled(out.plan, "FAR_TAIL")) program.set("uFarSpan", float(scene::farSpan(scene)));
                    for (std::size_t i = 0; i < lights.size(); ++i)
                        gather(program, scene, input, lights[i], grids[i], int(i));
                }
                if (featureEnabled(out.plan, "AREA_LIGHTS_BY_IVSV")) addAreaLights(input);
            }
        },
        [&] {
            if (!lights.empty()) {
                out.intermediates.push_back(cpuIntermediate(
                    kColumn, "Voxel column of pixel (" + std::to_string(pickX) + ", " + std::to_string(pickY) + ")",
                    "the 128 phi bits its eye ray reads; top row as voxelized (1 occluder), bottom row after the scan "
                    "(1 shadowed, 0 lit); 0.5 beyond the fragment (not read)",
                    ViewKind::Mask,
                    columnImage(scene, input, lights[std::size_t(shown)], grids[std::size_t(shown)], shown, pickX,
                                pickY)));
                out.intermediates.back().rayView = true;
                out.intermediates.back().sentinels = {{0.5f, "beyond the fragment: not read"}};
            }
            out.intermediates.push_back(render::textureIntermediate(
                kAirlight, "L_air", "single-scattered light reaching the eye", "radiance", ViewKind::Colour, 0.0f, 1.0f,
                mAirlight));
            out.intermediates.push_back(render::textureIntermediate(
                kVisibility, "Visibility",
                std::string(lights.empty() ? "all 0 here: no point, spot or directional light has a grid (an area "
                                             "light is ivsv's, inside this run); "
                                           : "") +
                    "r: phi-uniform lit fraction of the ray's bits; g: interpolated visibility of the fragment's voxel; "
                    "b: alpha cell; a: theta cell, -1 where the epipole case replaced the grid",
                "", ViewKind::Scalar, 0.0f, 1.0f, mVisibility));
            out.intermediates.back().sentinels = {{-1.0f, "epipole case: a direct ray replaced the grid"}};
            out.intermediates.back().channels = {{"lit fraction of the ray", "", ViewKind::Scalar, 0.0f, 1.0f},
                                                 {"visibility of the fragment", "", ViewKind::Scalar, 0.0f, 1.0f},
                                                 {"alpha cell", "cells", ViewKind::Scalar, 0.0f, float(size.alpha)},
                                                 {"theta cell", "cells", ViewKind::Scalar, 0.0f, float(size.theta)}};
            render::readBackAirlight(input, mAirlight, out);
        });
    if (!toCompose) return out;

    mView.runCompose(stages, kComposeIndex, input, mAirlight, out, "vsv");
    return out;
}

Plan VsvTechnique::planFor(const scene::Scene& scene, const Settings& settings, int width, int height) const {
    const VsvSettings s = vsvParams().read(settings);
    Plan p = planEveryStage(mStages);
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
    const GridSize size = gridSize(s);
    if (!lights.empty()) {
        p.stages[kScanIndex].why = std::to_string(scanPassCount(size.alpha)) + " passes for " +
                                   std::to_string(size.alpha) + " alpha cells";
        if (size.phi != phiAsked(s))
            p.stages[kVoxelizeIndex].why = "phi " + std::to_string(phiAsked(s)) + " rounded up to " +
                                           std::to_string(size.phi) + " bits (whole 32-bit words)";
    }
    const bool exact = s.exactCombine;
    const bool interp = s.interp;
    bool epipoleInView = false;
    for (int li : lights) {
        const vsv::EpipolarGrid g = vsv::gridForLight(scene, scene.lights[std::size_t(li)], width, height,
                                                      size.alpha, size.theta, size.phi, true);
        epipoleInView = epipoleInView || g.epipoleToward || g.epipoleAway;
    }
    const bool epipole = epipoleInView && s.epipole != 0;
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
         epipole ? (s.epipole == 2
                        ? "an epipole is in view: rays within one alpha cell of it compare the fragment with the "
                          "light (the paper's rule)"
                        : "an epipole is in view: rays within one alpha cell of it test the shadow map directly")
                 : (epipoleInView ? "epipole=off: the grid is read even at the epipole"
                                  : "no epipole in view (the light and its antipode are off screen)")});
    // A far camera (scene/ray_reach.h): the grid's phi range ends at the scene's far side.
    const bool farTail = scene::depthOfInterest(scene) < scene.camera.zfar;
    p.features.push_back({"FAR_TAIL", farTail,
                          farTail ? "zfar reaches far past the scene: the grid's phi range ends at its far side; a ray "
                                    "going on past it adds the rest with 8 shadow-map tests placed by the light, and "
                                    "direct rays place their segments by the light"
                                  : "the grid's phi range reaches zfar"});
    p.features.push_back({"DYNAMIC_RANGE", s.dynamicRange,
                          s.dynamicRange
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
                          hasArea ? "the area light is shaded by an inner ivsv (its defaults, vsv's vpl_kernel) in the "
                                    "gather stage"
                                  : "no area light"});
    render::planCulledLights(scene, p);
    // Scene-pruned features (force_features=1 turns them on; the image must not change): light types
    // and cookies compiled out, the epipole rays when no epipole is in view (the grid flags then keep
    // every ray on the grid), the inner ivsv without an area light (it adds zero).
    std::vector<std::string> pruned = {"SPOT", "COOKIE", "SHADOW_MAPS_CUBE", "SHADOW_MAPS_2D", "AREA_LIGHTS_BY_IVSV"};
    if (s.epipole != 0) pruned.push_back("EPIPOLE");
    forcePlan(p, s.forceFeatures, pruned);
    annotatePermutations(p, kDefines);
    return p;
}

}  // namespace viz::vsv_detail

namespace viz {

std::unique_ptr<Technique> makeVsvTechnique() { return std::make_unique<vsv_detail::VsvTechnique>(); }

}  // namespace viz
