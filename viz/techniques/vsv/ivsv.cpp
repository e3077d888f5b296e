// ivsv: parameters, stages, plan and the run (ivsv_technique.h).
#include "techniques/vsv/ivsv.h"

#include "techniques/vsv/ivsv_technique.h"

namespace viz::ivsv_detail {

namespace {

// The shared passes' shadow_map as ivsv uses it: the ISM tile or naive cube face, at most 512 texels.
ParamInfo tileParam() {
    for (ParamInfo p : render::SceneViewPasses::params())
        if (p.name == "shadow_map") {
            p.help = "imperfect shadow-map tile / naive cube-face size in texels (rounded up to a power of two)";
            p.defaultValue = 128;
            p.maxValue = 512;
            return p;
        }
    VIZ_CHECK(false, "the shared passes declare no shadow_map");
    return {};
}

// The shared vpl_kernel: the surface term's VPLs take it as every technique does, and so do the gather's
// on a grid (vpl_layout=grid); Halton points have no cells, so `cell` makes each a disc of its area near
// the emitter there.
ParamInfo vplKernelParam() {
    for (ParamInfo p : render::SceneViewPasses::params())
        if (p.name == "vpl_kernel") {
            p.help += "; the gather's VPLs take it on a grid (vpl_layout=grid); Halton points have no cells: with "
                      "cell each acts as a disc of its area dA (the point's 1/r^2 times r^2 / (r^2 + dA / pi))";
            return p;
        }
    VIZ_CHECK(false, "the shared passes declare no vpl_kernel");
    return {};
}

}  // namespace

const ParamTable<IvsvSettings>& ivsvParams() {
    using S = IvsvSettings;
    static const ParamTable<S> table =
        ParamTable<S>()
            .add(&S::vpls, {"vpls", "virtual point lights on the area light", 64, 1, kMaxVpls, true})
            .add(&S::gridLayout, {"vpl_layout", "halton: VPLs at Halton points of the emitter (Wyman and Dai Sec. "
                                  "3.1.1), each L_e at its point times dA; grid: at the centres of vpls equal cells "
                                  "(the factor pair of vpls closest to square cells), each its cell's mean L_e times "
                                  "dA, and with vpl_kernel=cell its cell of the emitter", 1, 0, 1, true,
                                  {"halton", "grid"}})
            .add(&S::voxels, {"voxels", "alpha and theta cells per VPL grid (phi is 128 bits)", 128, 16, 512, true})
            .add(&S::exactCombine, {"combine", "fraction: lit fraction x unshadowed airlight; exact: each quadrature "
                                    "node weighted by the visibility of its own bits", 1, 0, 1, true,
                                    {"fraction", "exact"}})
            .add(&S::gather, {"gather", "full: every pixel x every VPL; interleaved: 1/9 of the VPLs per pixel + 3x3 "
                              "bilateral; quarter: half width and height + bilateral upsampling",
                              0, 0, 2, true, {"full", "interleaved", "quarter"}})
            .add(&S::subsetsPerFrame,
                 {"subsets", "gather=interleaved: fixed: each pixel's ninth of the VPLs is the same on every frame (a "
                  "3x3 screen pattern); per-frame: the pattern steps by one subset each frame of an animation, so "
                  "every pixel sees all nine over nine frames (what temporal accumulation would want)",
                  0, 0, 1, true, {"fixed", "per-frame"}})
            .add(&S::deinterleave,
                 {"deinterleave", "gather=interleaved: on: the invocations run over the nine 3x3 sub-images side by "
                  "side, so every work group gathers one ninth of the VPLs (its pixels read the same VPLs and grid "
                  "tiles); off: in screen order, every group mixes all nine. The same image either way",
                  1, 0, 1, true, {"off", "on"}})
            .add(&S::naive, {"mode", "imperfect: ISMs and one pass per step for all VPLs; naive: cube shadow maps "
                             "and a full VSV per VPL", 0, 0, 1, true, {"imperfect", "naive"}})
            .add(&S::points, {"points", "point cloud size for the imperfect shadow maps (split among the VPLs)",
                              1 << 20, 1024, 1 << 23, true})
            .add(&S::fillLevels, {"fill_levels", "push-pull fills a hole only from a sample within 2^k texels of it "
                                  "(k levels up the pyramid); wider holes stay empty, so directions that see nothing "
                                  "(open sky) stay lit", 1, 0, 12, true})
            .add(&S::alphaBias, {"alpha_bias", "occluder alpha offset in cells (negative: shadow starts further from "
                                 "the light)", -2.25, -16, 16, false})
            .add(&S::phiBias, {"phi_bias", "light-ray phi offset in cells (negative: shadow moves away from the eye)",
                               -1, -16, 16, false})
            .add(&S::interp, {"interp", "1: two texels along theta; 0: nearest", 1, 0, 1, true})
            .add(&S::epipole, {"epipole", "rays within one alpha cell of a VPL's epipole: off reads its grid; paper "
                               "compares the fragment with the VPL (the eye's visibility at the antipode), Wyman and "
                               "Dai Sec. 5", 1, 0, 1, true, {"off", "paper"}})
            .add(&S::chunkBits, {"chunk_bits", "phi bits per quadrature node of the airlight (1, 2, 4, ..., 128)", 8,
                                 1, 128, true})
            .add(&S::bilateralSigma, {"bilateral_sigma", "distance tolerance of the bilateral filters, relative to d",
                                      0.1, 0.001, 10, false})
            .declare({"scan_passes", "stop the segmented alpha scan after this many passes (-1: all; stepping)", -1,
                      -1, kMaxScanPasses, true})
            .declare({"vpl_step", "gather only VPLs 0 .. k (-1: all; stepping VPL by VPL)", -1, -1, kMaxVpls - 1,
                      true})
            .add(&S::pickVpl, {"pick_vpl", "VPL whose shadow map, grid and column the intermediates show", 0, 0,
                               kMaxVpls - 1, true})
            .declare(pickParam('x', "voxel column and per-VPL contributions"))
            .declare(pickParam('y', "voxel column and per-VPL contributions"))
            .add(&S::pickTheta, {"pick_theta", "theta cell of the unwrapped alpha x phi slices (-1: that of the "
                                 "picked pixel)", -1, -1, 512, true})
            .add(&S::tile, tileParam())
            .declare(render::SceneViewPasses::params(), "area_samples")
            .add(&S::vplKernel, vplKernelParam())
            .add(&S::forceFeatures, forceFeaturesParam());
    VIZ_CHECK(table.missing().empty(), "ivsv declares a shared parameter the shared passes lack");
    return table;
}

IvsvTechnique::IvsvTechnique()
    : GlTechnique({.id = "ivsv",
                   .description = "imperfect voxelized shadow volumes (Wyman and Dai 2013): area lights as many VPL shadow volumes",
                   .controls = {.pickedPixel = true}},
                  ivsvParams()) {
    mStages = {
        {kStageVpls, "VPLs", "Halton points or grid cells on the area light: position, normal, L_e dA from the "
         "emission texture", {"vpls", "vpl_layout"}, {kVplImage}, 1},
        {kStageShadows, "Shadow maps",
         "imperfect: point cloud subsets splatted into one paraboloid tile per VPL, push-pull hole filling; "
         "naive: a cube shadow map per VPL",
         {"mode", "points", "fill_levels", "shadow_map"}, {kPointCloud, kIsmRaw, kIsm, "ivsv.naive.shadow_map"}, 1},
        {kStageSurface, "Camera view",
         "the shared surface term: its own shadow maps, distance d and surface radiance", {"area_samples", "vpl_kernel"},
         {"ivsv.shadow_map", "ivsv.vpl_cells", "ivsv.distance", "ivsv.surface"}, 1},
        {kStageVoxelize, "Rectify",
         "every VPL's shadow map resampled into its own epipolar grid tile (one pass, or one per VPL for naive)",
         {"voxels", "alpha_bias", "phi_bias", "pick_vpl", "pick_theta"}, {kVoxelSlice}, 1},
        {kStageScan, "Extrude (segmented scan)", "prefix OR along alpha restarting at every tile boundary",
         {"scan_passes"}, {kScanSlice}, kMaxScanPasses, "scan_passes"},
        {kStageGather, "Gather", "per pixel: sum over VPLs of visibility x airlight (full, interleaved, quarter)",
         {"combine", "gather", "subsets", "deinterleave", "interp", "epipole", "chunk_bits", "vpl_kernel", "bilateral_sigma", "vpl_step", "pick_x", "pick_y",
          "force_features"},
         {kColumn, kPerVpl, kInterleave, kAirlight, kVisibility}, 1, "vpl_step"},
        render::SceneViewPasses::composeStage("ivsv"),
    };
    checkStageOrder(mStages, kStageOrder);
}

std::vector<double> IvsvTechnique::substepValues(int stage, const Settings& settings) const {
    if (stage != kScanIndex && stage != kGatherIndex) return Technique::substepValues(stage, settings);
    const IvsvSettings s = ivsvParams().read(settings);
    std::vector<double> values;
    if (stage == kScanIndex) {
        for (int k = 0; k < scanPassCount(s.voxels); ++k) values.push_back(double(k));
    } else {
        for (int k = 0; k + 1 < s.vpls; ++k) values.push_back(double(k));
    }
    values.push_back(-1.0);
    return values;
}

std::vector<StabilisingOption> IvsvTechnique::stabilisingOptions(const scene::Scene& scene) const {
    // The subsets are the VPLs' (gather=interleaved): without an area light there are none.
    if (!render::hasLightOfType(scene, scene::LightType::Area)) return {};
    return {{"subsets=fixed", "each pixel's ninth of the VPLs changes every frame",
             {{"gather", double(kGatherInterleaved)}, {"subsets", 1.0}},
             {{"gather", double(kGatherInterleaved)}, {"subsets", 0.0}}}};
}

std::vector<QualitySetting> IvsvTechnique::qualitySweep(bool quick) const {
    const std::vector<std::pair<int, int>> steps =
        quick ? std::vector<std::pair<int, int>>{{4, 64}, {16, 128}, {64, 128}}
              : std::vector<std::pair<int, int>>{{4, 64}, {16, 64}, {16, 128}, {64, 128}, {256, 128}, {256, 256}};
    std::vector<QualitySetting> sweep;
    for (const auto& [vpls, voxels] : steps)
        sweep.push_back({"vpls=" + std::to_string(vpls) + " voxels=" + std::to_string(voxels),
                         {{"vpls", double(vpls)}, {"voxels", double(voxels)}}});
    return sweep;
}

Plan IvsvTechnique::plan(const scene::Scene& scene, const Settings& settings) const {
    const IvsvSettings s = ivsvParams().read(settings);
    const scene::Light* area = areaLightOf(scene);
    const bool hasArea = area != nullptr;
    const bool hasOthers = int(scene.lights.size()) > (hasArea ? 1 : 0);
    Plan p = planEveryStage(mStages);
    if (!hasArea) {
        for (int i : {kVplsIndex, kShadowsIndex, kVoxelizeIndex, kScanIndex}) {
            p.stages[std::size_t(i)].runs = false;
            p.stages[std::size_t(i)].why = "no area light: nothing to split into VPLs";
        }
    }
    const bool naive = s.naive;
    const int vpls = s.vpls;
    if (scene.medium.sigma_s == 0.0) {
        p.stages[kGatherIndex].runs = false;
        p.stages[kGatherIndex].why = "sigma_s = 0: the medium scatters nothing, L_air = 0";
    }
    if (hasArea) {
        p.stages[kShadowsIndex].why = naive ? std::to_string(vpls) + " cube shadow maps, one per VPL"
                                            : "one ISM atlas of " + std::to_string(vpls) + " tiles";
        if (tileSize(s) != s.tile)
            p.stages[kShadowsIndex].why += "; shadow_map " + std::to_string(s.tile) + " rounded up to " +
                                           std::to_string(tileSize(s)) + " (a power of two)";
        p.stages[kScanIndex].why = std::to_string(scanPassCount(s.voxels)) + " passes" +
                                   (naive ? " per VPL" : " over all tiles at once");
    }
    const bool exact = s.exactCombine;
    const bool interp = s.interp;
    const int gather = s.gather;
    std::string layout;
    if (hasArea) {
        const bool cell = s.vplKernel != 0.0;
        const glm::ivec2 grid = vsv::vplGridSize(*area, vpls);
        layout = s.gridLayout ? ", the centres of " + std::to_string(grid.x) + " x " + std::to_string(grid.y) +
                                    " equal cells (vpl_layout=grid" +
                                    (cell ? "; each its cell of the emitter, vpl_kernel=cell)" : ")")
                              : " at Halton points (vpl_layout=halton" +
                                    std::string(cell ? "; each a disc of its area near it, vpl_kernel=cell)" : ")");
        p.stages[kVplsIndex].why = std::to_string(vpls) + " VPLs" + layout;
    }
    p.features.push_back({"VPL_PIPELINE", hasArea,
                          hasArea ? "the area light becomes " + std::to_string(vpls) + " VPLs" + layout : "no area light"});
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
    if (gather == kGatherInterleaved) {
        const bool cycle = s.subsetsPerFrame;
        p.features.push_back({"SUBSETS_PER_FRAME", cycle,
                              cycle ? "subsets=per-frame: the 3x3 VPL pattern steps by one subset every frame"
                                    : "subsets=fixed: each pixel keeps its ninth of the VPLs from frame to frame"});
        p.features.push_back({"DEINTERLEAVE", s.deinterleave,
                              s.deinterleave ? "each work group gathers the pixels of one ninth of the VPLs (the "
                                               "3x3 sub-images side by side): coherent VPL and grid reads"
                                             : "deinterleave=off: work groups in screen order mix all nine ninths"});
    }
    p.features.push_back({"INTERP", interp, interp ? "two texels along theta" : "nearest texel"});
    const bool epipole = hasArea && s.epipole;
    p.features.push_back({"EPIPOLE", epipole,
                          epipole ? "rays within one alpha cell of a VPL's epipole (VPLs in view, or behind the eye) "
                                    "compare the fragment with the VPL instead of reading its grid"
                                  : (hasArea ? "epipole=off: every ray reads the grids" : "no area light")});
    p.features.push_back({"INTERLEAVED_GATHER", gather == kGatherInterleaved,
                          gather == kGatherInterleaved ? "1/9 of the VPLs per pixel, 3x3 bilateral filter"
                                                       : "every pixel gathers its VPLs"});
    p.features.push_back({"QUARTER_GATHER", gather == kGatherQuarter,
                          gather == kGatherQuarter ? "half width and height, bilateral upsampling"
                                                   : "full-resolution gather"});
    render::planCulledLights(scene, p);
    // Scene-pruned: the inner vsv without other lights (force_features=1 runs it on none: it adds zero).
    forcePlan(p, s.forceFeatures, {"OTHER_LIGHTS_BY_VSV"});
    annotatePermutations(p, kDefines);
    return p;
}

FrameOutput IvsvTechnique::run(const FrameInput& input) {
    const scene::Scene& scene = *input.scene;
    FrameOutput out;
    const IvsvSettings& s = startRun(input, out);
    const scene::Light* area = areaLightOf(scene);
    const bool naive = s.naive;
    const int count = area ? s.vpls : 0;
    const int cells = s.voxels;
    const int tile = tileSize(s);
    const int shown = std::max(0, std::min(s.pickVpl, count - 1));
    gl::StageClock clock;
    StageRunner stages(mStages, input, out, mReuse, clock);
    mSurfaceRan = mNaiveBuilt = false;
    mMark.reset();

    // ---- VPLs and their epipolar spaces ----
    if (!stages.run(
        kVplsIndex,
        [&] {
            mVpls.clear();
            if (area) {
                mVpls = s.gridLayout ? vsv::gridVpls(scene, *area, count) : vsv::sampleVpls(scene, *area, count);
                mVplArea = 4.0 * glm::length(glm::cross(area->halfU, area->halfV)) / count;
                for (vsv::Vpl& v : mVpls) v.position += kVplOffset * v.normal;
            }
            layOut(std::max(count, 1), cells, tile);
            uploadVpls(scene, input.width, input.height, cells, tile);
        },
        [&] {
            if (!area) return;
            out.intermediates.push_back(cpuIntermediate(
                kVplImage, "VPLs on the emitter",
                "emitter uv square (u right, v down): each VPL's L_e as a dot, on a grid inside its cell (60 %)",
                ViewKind::Colour, vplImage()));
            out.intermediates.back().picture = true;
        }))
        return out;

    // ---- shadow maps ----
    if (!stages.run(
        kShadowsIndex,
        [&] {
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
                buildIsm(scene, *area, s.points, count, tile, s.fillLevels);
            }
        },
        [&] {
            if (area && !naive) {
                out.intermediates.push_back(render::textureIntermediate(
                    kIsmRaw, "ISM atlas (splatted)", "one paraboloid tile per VPL: distance of the nearest point, 0 = hole",
                    "scene units", ViewKind::Depth, 0.0f, 8.0f, mIsmRaw));
                out.intermediates.back().sentinels = {{0.0f, "hole: no point splatted"}};
                out.intermediates.push_back(render::textureIntermediate(
                    kIsm, "ISM atlas (after push-pull)", "holes filled from coarser levels (mean of valid samples within 2^fill_levels texels; wider holes stay empty)",
                    "scene units", ViewKind::Depth, 0.0f, 8.0f, mIsm));
                out.intermediates.push_back(cpuIntermediate(
                    kPointCloud, "Point cloud of VPL " + std::to_string(shown),
                    "the subset of the scene's points splatted into its tile, seen from the camera (nearest distance)",
                    ViewKind::Depth, pointCloudImage(scene, input.width, input.height, shown, count), 0.0f, 8.0f));
            }
        }))
        return out;

    // ---- camera view (the shared surface term) ----
    if (!stages.run(
        kSurfaceIndex,
        [&] {
            mView.buildShadows(scene, input.settings, out.intermediates, "ivsv");
            mView.renderSurface(scene, input.width, input.height, out.intermediates, "ivsv");
            mSurfaceRan = true;
        }))
        return out;

    const glm::ivec2 pick = pickedPixel(input);
    const int pickX = pick.x, pickY = pick.y;
    const glm::dvec3 pickRay = scene::pixelRay(scene.camera, input.width, input.height, pickX, pickY);
    int pickTheta = 0;
    if (area) {
        const vsv::EpipolarFrame f = vsv::makeFrame(mVpls[std::size_t(shown)].position - scene.camera.position);
        const vsv::EpipolarGrid& g = mGrids[std::size_t(shown)];
        pickTheta = std::clamp(int(std::floor(vsv::thetaCoord(g, vsv::thetaOf(f, pickRay)))), 0, cells - 1);
    }
    if (s.pickTheta >= 0) pickTheta = std::min(s.pickTheta, cells - 1);
    const glm::ivec2 shownTile = tileOrigin(shown, cells);
    if (area) mMark = MarkState{shown, pickTheta, tile, naive, scene.camera.position};

    // ---- rectify ----
    if (!stages.run(
        kVoxelizeIndex,
        [&] {
            if (area) rectify(s, count, cells, tile, naive);
        },
        [&] {
            if (area)
                out.intermediates.push_back(cpuIntermediate(
                    kVoxelSlice, "Voxels of VPL " + std::to_string(shown) + " (before scan)",
                    "alpha (x) x phi (y, eye at the top) at theta cell " + std::to_string(pickTheta) +
                        ": white = occluder",
                    ViewKind::Mask, vsv::sliceImage(mGrid, shownTile.x, cells, shownTile.y + pickTheta, kPhiBits)));
        }))
        return out;

    // The picked pixel's column as voxelized, for the gather's column view (the scan overwrites the
    // grid); read only when the gather will run.
    if (area && stages.reaches(kGatherIndex)) {
        const glm::ivec2 cell = pickedCell(scene, input, shown, cells, pickX, pickY);
        mPreScanColumn = vsv::readGridRow(mGrid, shownTile.x + cell.x, 1, shownTile.y + cell.y).front();
    }

    // ---- segmented scan ----
    const int passSetting = int(substepLimit(input, kScanIndex));
    const int passLimit = passSetting < 0 ? kMaxScanPasses : passSetting;
    if (!stages.run(
        kScanIndex,
        [&] {
            if (area) scan(count, cells, passLimit, naive);
        },
        [&] {
            if (area)
                out.intermediates.push_back(cpuIntermediate(
                    kScanSlice,
                    "Voxels of VPL " + std::to_string(shown) + " after " +
                        std::to_string(std::min(passLimit, scanPassCount(cells))) + " scan passes",
                    "alpha x phi at theta cell " + std::to_string(pickTheta) + ": white = shadowed", ViewKind::Mask,
                    vsv::sliceImage(*mResult, shownTile.x, cells, shownTile.y + pickTheta, kPhiBits)));
        }))
        return out;

    // ---- gather ----
    const int gatherMode = s.gather;
    const int vplStep = int(substepLimit(input, kGatherIndex));
    const int gathered = vplStep < 0 ? count : std::min(count, vplStep + 1);
    if (!stages.run(
        kGatherIndex,
        [&] {
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
        },
        [&] {
            if (area) {
                out.intermediates.push_back(cpuIntermediate(
                    kColumn, "Voxel column of pixel (" + std::to_string(pickX) + ", " + std::to_string(pickY) + "), VPL " +
                                 std::to_string(shown),
                    "its 128 phi bits; top row as voxelized (1 occluder), bottom row after the scan (1 shadowed, 0 lit); "
                    "0.5 beyond the fragment (not read)", ViewKind::Mask,
                    columnImage(scene, input, shown, cells, pickX, pickY)));
                out.intermediates.back().rayView = true;
                out.intermediates.back().sentinels = {{0.5f, "beyond the fragment: not read"}};
                const std::shared_ptr<Image> perVpl = perVplImage(count);
                out.intermediates.push_back(cpuIntermediate(
                    kPerVpl, "Per-VPL airlight of pixel (" + std::to_string(pickX) + ", " + std::to_string(pickY) + ")",
                    "x = VPL index: its unscaled contribution to L_air (only VPLs this pixel gathered)", ViewKind::Colour,
                    perVpl, 0.0f, 0.0f));
                out.intermediates.back().plots = {perVplPlot(*perVpl)};
                out.intermediates.back().rayView = true;
                out.intermediates.push_back(
                    interleaveIntermediate(input.width, input.height, gatherMode, phaseShift(s, input)));
            }
            out.intermediates.push_back(render::textureIntermediate(
                kAirlight, "L_air", "single-scattered light reaching the eye", "radiance", ViewKind::Colour, 0.0f, 1.0f,
                mAirlight));
            out.intermediates.push_back(render::textureIntermediate(
                kVisibility, "Visibility",
                std::string(count == 0 ? "all 1 here: no area light, so no VPL (the other lights are the inner "
                                         "vsv's); "
                                       : "") +
                    "mean over the gathered VPLs of the phi-uniform lit fraction of the ray",
                "", ViewKind::Scalar, 0.0f, 1.0f, mVisibility));
            render::readBackAirlight(input, mAirlight, out);
        }))
        return out;

    // ---- compose ----
    mView.runCompose(stages, kComposeIndex, input, mAirlight, out, "ivsv");
    return out;
}

}  // namespace viz::ivsv_detail

namespace viz {

std::unique_ptr<Technique> makeIvsvTechnique() { return std::make_unique<ivsv_detail::IvsvTechnique>(); }

}  // namespace viz
