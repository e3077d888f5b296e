// minmax: parameters, stages, plan and the run (minmax_technique.h).
#include "techniques/minmax/minmax.h"

#include "scene/ray_reach.h"
#include "techniques/minmax/minmax_technique.h"

namespace viz::minmax_detail {

const ParamTable<MinmaxSettings>& minmaxParams() {
    using S = MinmaxSettings;
    static const ParamTable<S> table =
        ParamTable<S>()
            .add(&S::slices, {"slices", "epipolar slices (rows of the rectified map); 0: automatic, every ray within "
                              "1/(2k) pixel of a slice (k = slice_oversampling) up to 16384 slices; past that the run "
                              "notes the gap", 0, 0, minmax::kMaxSlices, true})
            .add(&S::sliceOversampling, {"slice_oversampling", "automatic slices: k puts every camera ray within "
                                         "1/(2k) pixel of a slice", 2, 1, 64, true})
            .add(&S::fixedFrame,
                 {"slice_frame", "screen: the paper's slices, centred on the image centre's slice and as many as the "
                  "screen needs, so they turn and respace with every view; fixed: alpha = k 2 pi / 2^m from a "
                  "world-fixed direction about the eye-light axis (slices stay put while that axis does)",
                  0, 0, 1, true, {"screen", "fixed"}})
            .add(&S::columns, {"columns", "gamma texels per slice (rounded up to a power of two); 0: the shadow map's "
                               "size", 0, 0, minmax::kMaxColumns, true})
            .add(&S::integrand, {"integrand", "analytic: the segment integral per lit run (closed form for suns, "
                                 "Gauss-Legendre panels for point and spot lights); svd: rank-N approximation with "
                                 "prefix sums; auto: svd where its rank-N approximation holds the scene's integrand "
                                 "(the faster one), analytic elsewhere (the plan says which and why)",
                                 2, 0, 2, true, {"analytic", "svd", "auto"}})
            .add(&S::rank, {"rank", "singular vectors kept by integrand=svd", 4, 1, 8, true})
            .add(&S::textureColumns, {"texture_columns", "integrand=svd: gamma texels of the prefix-sum tables of "
                                      "Gamma_i T (the light texture's own resolution, lower than the shadow map's)",
                                      256, 16, 4096, true})
            .add(&S::prefixScan, {"prefix_sums", "integrand=svd: how a table row is summed; sequential: one "
                                  "invocation adds the row's texels in order; log2: one work group per row, its "
                                  "chunk sums scanned in log2 passes in shared memory (Chen et al. 2011 Sec. 3.4); "
                                  "auto: sequential unless a row is too long for llvmpipe's loop limit",
                                  2, 0, 2, true, {"sequential", "log2", "auto"}})
            .add(&S::blendRows, {"slice_blend", "integrand=svd, spot lights: where a ray reads its slice's "
                                 "prefix sums of Gamma_i T; nearest: the nearest slice's (the paper), whose cone "
                                 "edge and cookie are up to half a slice off the ray's; linear: interpolated "
                                 "between the two slices either side of the ray", 1, 0, 1, true,
                                 {"nearest", "linear"}})
            .add(&S::linear, {"traversal", "tree: min-max mipmap walk (Figure 5); linear: scan every texel of the row",
                              0, 0, 1, true, {"tree", "linear"}})
            .add(&S::marchPoints, {"point_lights", "epipolar: point lights rectified from their cube maps; march: "
                                   "marched per pixel (the fallback before point lights had an epipolar path, for "
                                   "comparison)", 0, 0, 1, true, {"epipolar", "march"}})
            // Each piece is one pointSegment call; llvmpipe stops every loop of a shader invocation after
            // 65535 iterations in total (all loops together), which more pieces would exceed (README).
            .add(&S::spotPieces, {"spot_pieces", "spot lights with a cookie, integrand=analytic: pieces across the "
                                  "cone, each with its own A_spot * cookie (without a cookie each lit run is cut "
                                  "at the cones)", 64, 1, 128, true})
            .add(&S::epipoleRadius, {"epipole_radius", "pixels around the (anti-)epipole marched by brute force", 4, 0,
                                     1000, false})
            .add(&S::marchSamples, {"march_samples", "brute-force samples per ray (near the epipole, and point "
                                    "lights with point_lights=march)", 512, 1, 16384, true})
            // An area light's VPL stands for its cell (vpl_kernel): its integrand is bounded and smooth on
            // the cell's scale, and 64 samples come within 0.4 % of a converged march on tv-room (README,
            // "Area lights").
            .add(&S::vplSamples, {"vpl_samples", "brute-force samples per ray for each area-light VPL", 64, 1,
                                  16384, true})
            .declare({"mip_levels", "mipmap passes to run (0: all); fewer stops the frame after the mipmap stage", 0,
                      0, 13, true})
            .declare(pickParam('x', "slice row, tree walk and ray chart"))
            .declare(pickParam('y', "slice row, tree walk and ray chart"))
            .declare({"trace_steps", "picked pixel's walk: show its first k nodes (0: all); steps the traversal node "
                      "by node", 0, 0, 100000, true})
            .add(&S::shadowMap, render::SceneViewPasses::params(), "shadow_map")
            .declare(render::SceneViewPasses::params(), "area_samples")
            .declare(render::SceneViewPasses::params(), "vpl_kernel")
            .add(&S::forceFeatures, forceFeaturesParam());
    VIZ_CHECK(table.missing().empty(), "minmax declares a shared parameter the shared passes lack");
    return table;
}

MinmaxTechnique::MinmaxTechnique()
    : GlTechnique({.id = "minmax",
                   .description = "1D min-max mipmaps in epipolar space (Chen, Baran, Durand, Jarosz 2011)",
                   .controls = {.pickedPixel = true}},
                  minmaxParams()) {
    mStages = {
        render::SceneViewPasses::shadowStage("minmax"),
        render::SceneViewPasses::surfaceStage("minmax"),
        {kStageRectify, "Rectify", "shadow map -> S[alpha, gamma] = beta of the occluder on each light ray "
         "(point lights: each slice's gamma range first, then their cube map); integrand=svd: SVD of "
         "I(beta, gamma) and prefix sums of Gamma_i T per slice",
         {"slices", "slice_oversampling", "slice_frame", "columns", "integrand", "rank", "texture_columns", "prefix_sums", "point_lights"},
         {kRectified, kRectifiedView, kRowGamma, kSingularValues, kBasis, kPrefixSums, kReconstructionError}, 1},
        {kStageMipmap, "Min-max mipmap", "per row of S: a 1D min-max tree, one pass per level",
         {"mip_levels"}, {kTree, kPyramid}, 1, "mip_levels"},
        {kStageTraverse, "Traverse", "per pixel: walk the slice's tree, integrate the lit segments",
         {"integrand", "rank", "slice_blend", "traversal", "point_lights", "spot_pieces", "epipole_radius", "march_samples",
          "vpl_samples", "pick_x", "pick_y", "trace_steps", "force_features"},
         {kAirlight, kVisited, kNearMask, kRayCoords, kTrace}, 1, "trace_steps"},
        render::SceneViewPasses::composeStage("minmax"),
    };
    // The rectified maps and the trees stay in LightWork between runs.
    mStages[kRectifyIndex].keepsOutputs = mStages[kMipmapIndex].keepsOutputs = true;
    mStages[kTraverseIndex].substepsPerRun = true;  // the picked ray's walk sets the count
    checkStageOrder(mStages, kStageOrder);
}

std::vector<double> MinmaxTechnique::substepValues(int stage, const Settings& settings) const {
    if (stage != kMipmapIndex && stage != kTraverseIndex) return Technique::substepValues(stage, settings);
    const MinmaxSettings s = minmaxParams().read(settings);
    const int wanted = s.columns > 0 ? s.columns : s.shadowMap;
    const int columns = minmax::rectifiedColumns(wanted);
    const int last = stage == kMipmapIndex ? std::bit_width(unsigned(columns)) - 1 : 2 * columns - 1;
    std::vector<double> values;
    for (int k = 1; k < last; ++k) values.push_back(double(k));
    values.push_back(0.0);
    return values;
}

std::vector<StabilisingOption> MinmaxTechnique::stabilisingOptions(const scene::Scene& scene) const {
    // Epipolar slices are those of spot, point and directional lights (an area light is not walked).
    if (std::none_of(scene.lights.begin(), scene.lights.end(),
                     [](const scene::Light& l) { return l.type != scene::LightType::Area; }))
        return {};
    return {{"slice_frame=fixed", "the slices turn and respace with every view", {{"slice_frame", 0.0}},
             {{"slice_frame", 1.0}}}};
}

std::vector<QualitySetting> MinmaxTechnique::qualitySweep(bool quick) const {
    std::vector<QualitySetting> sweep;
    // The grid leaves the integrand at its default (auto: svd where its tables hold, the closed form for
    // suns alone), so the sweep measures minmax as a user runs it; map=1024 slices=auto is the default.
    auto grid = [&](int map, int slices, int pieces, int samples) {
        sweep.push_back({"map=" + std::to_string(map) + " slices=" + (slices ? std::to_string(slices) : "auto"),
                         {{"shadow_map", double(map)}, {"slices", double(slices)},
                          {"spot_pieces", double(pieces)}, {"march_samples", double(samples)}}});
    };
    if (quick) {
        grid(256, 64, 32, 128);
        grid(1024, 0, 64, 512);  // the default
        grid(2048, 0, 64, 512);  // the accurate end: at 640x480 the map's resolution bounds the error
        return sweep;
    }
    grid(256, 64, 32, 128);
    grid(512, 256, 32, 256);
    grid(1024, 512, 64, 256);
    grid(1024, 0, 64, 512);
    grid(2048, 0, 64, 512);
    grid(4096, 0, 128, 1024);
    // Each integrand forced at the default's other settings, whatever auto would take.
    sweep.push_back({"analytic", {{"integrand", 0.0}}});
    for (int rank : {1, 2, 4, 8})
        sweep.push_back({"svd rank=" + std::to_string(rank), {{"integrand", 1.0}, {"rank", double(rank)}}});
    return sweep;
}

std::optional<StiffBound> MinmaxTechnique::stiffBound(const std::string& caseClass) const {
    static const std::map<std::string, StiffBound> kBounds = {
        {"medium", {0.02, "closed-form segments are exact in sigma_t; thin media show only the shadow-map and "
                          "slice sampling"}},
        {"intensity", {0.015, "linear in the intensity: float S, trees and segments carry no absolute scale"}},
        {"scale", {0.015, "eye-relative frame, angles alpha, beta, gamma and distance-valued maps are scale-free"}},
        {"singular-ray", {0.03, "the light's own pixel and the rays within epipole_radius px are marched with the "
                                "closed form per interval; elsewhere point lights take the epipolar path, and the "
                                "grate's bars run parallel to the view axis, so their shadow edges are epipolar "
                                "planes: four pixels whose rays lie within 1/8 px of such an edge take the slice "
                                "on its other side (0.0148, was 0.00034 marched)"}},
        {"near-light", {1e-4, "the light's own pixel is marched with the closed form per interval, "
                              "which keeps the ray's own distance from the light (9.3e-7)"}},
        {"epipole", {0.045, "rays within epipole_radius px of an epipole, and rays on the epipolar axis, are "
                           "marched; grazing sun is the worst (shadow-map bias across long light rays)"}},
        {"camera-placement", {0.008, "the frame is eye-relative; a closed box gives d small and S above beta"}},
        {"geometry", {0.05, "slice quantisation: a shadow edge along an epipolar plane is placed to the nearest "
                            "slice (centre line exact); slivers the rasteriser drops"}},
        {"leak", {0.045, "the rectified map reads the reconstructed depth but keeps the surface bias (its gamma "
                  "columns need it): a band under the grazing ceiling stays lit (0.019 measured)"}},
        {"depth-range", {0.022, "S stores angles beta, not depths: the 1e6 range costs no precision"}},
        {"phase", {0.04, "the HG lobe is inside the segment integral of each lit run; g = +-0.99 is the worst"}},
    };
    return boundOf(kBounds, caseClass);
}

Plan MinmaxTechnique::plan(const scene::Scene& scene, const Settings& settings) const {
    const MinmaxSettings s = minmaxParams().read(settings);
    Plan p = planEveryStage(mStages);
    const bool marchPoints = s.marchPoints;
    const auto epipolar = [&](const scene::Light& l) {
        return epipolarLight(l) && !(marchPoints && l.type == scene::LightType::Point);
    };
    const bool anyEpipolar = std::any_of(scene.lights.begin(), scene.lights.end(), epipolar);
    if (scene.medium.sigma_s == 0.0) {
        for (int i : {kRectifyIndex, kMipmapIndex, kTraverseIndex}) {
            p.stages[std::size_t(i)].runs = false;
            p.stages[std::size_t(i)].why = "sigma_s = 0: the medium scatters nothing, L_air = 0";
        }
    } else if (!anyEpipolar) {
        for (int i : {kRectifyIndex, kMipmapIndex}) {
            p.stages[std::size_t(i)].runs = false;
            p.stages[std::size_t(i)].why = "no spot or directional light and no point light: nothing to "
                                           "rectify (area lights' VPLs are marched by brute force in the "
                                           "traverse stage)";
        }
    }
    const bool fixedFrame = s.fixedFrame;
    p.features.push_back({"FIXED_SLICE_FRAME", fixedFrame,
                          fixedFrame ? "slice_frame=fixed: slices at multiples of 2 pi / 2^m from a world-fixed "
                                       "direction (up to twice the paper's count)"
                                     : "slice_frame=screen: the paper's slices, centred on the image centre"});
    bool svd = s.integrand == Integrand::Svd;
    std::string integrandWhy = svd ? "rank-" + std::to_string(s.rank) + " SVD of I(beta, gamma) with prefix sums of Gamma_i"
                                   : "integrand=analytic: closed form (airlight.glsl pointSegment / directionalSegment) "
                                     "per lit segment";
    if (s.integrand == Integrand::Auto) {
        const minmax::IntegrandChoice choice = mIntegrandChooser.choose(scene, s.rank, s.textureColumns, marchPoints);
        svd = choice.svd;
        integrandWhy = choice.why;
    }
    p.features.push_back({"INTEGRAND_SVD", svd, integrandWhy});
    if (svd) {
        const bool spot = render::hasLightOfType(scene, scene::LightType::Spot);
        const bool sun = render::hasLightOfType(scene, scene::LightType::Directional);
        p.features.push_back(
            {"TEXTURED_PREFIX_SUMS", spot,
             spot ? "spot: T = colour * I * A_spot * cookie varies with alpha: prefix sums of Gamma_i T per slice"
                  : "no spot light: T is the constant colour * I, one prefix-sum row shared by every slice"});
        if (sun && spot) p.features.back().why += "; directional lights share one row";
        if (render::hasLightOfType(scene, scene::LightType::Point) && !marchPoints)
            p.features.back().why += "; point lights: T is constant, but each slice has its own gamma range, "
                                     "so each has its own table too";
        const bool fits = sequentialScanFits(s.textureColumns, s.rank);
        const bool log2 = s.prefixScan == PrefixScan::Log2 || (s.prefixScan == PrefixScan::Auto && !fits);
        const std::string row = std::to_string(s.textureColumns) + " texels at rank " + std::to_string(s.rank);
        std::string why = s.prefixScan == PrefixScan::Log2 ? "prefix_sums=log2: a work group per table row, log2 "
                                                             "passes over its chunk sums in shared memory"
                          : log2 ? "prefix_sums=auto: log2 passes: a sequential scan of " + row +
                                       " would pass llvmpipe's 65,535 loop iterations per invocation"
                                 : "prefix_sums=" + std::string(s.prefixScan == PrefixScan::Auto ? "auto" : "sequential") +
                                       ": one invocation per table row adds its texels in order (cheaper on a CPU "
                                       "renderer)";
        if (!log2 && !fits)
            why += "; warning: " + row + " passes llvmpipe's loop limit, where the rows' ends are left unsummed";
        p.features.push_back({"PREFIX_LOG2_PASSES", log2, why});
    }
    const bool linear = s.linear;
    p.features.push_back({"TREE_TRAVERSAL", !linear,
                          linear ? "traversal=linear: every texel of the row up to the ray's end (run-time branch)"
                                 : "stackless walk of Figure 5, climb <= 1 level, delayed update (run-time branch)"});
    // Near-epipole marching: only when an epipolar light's epipole or anti-epipole is on or near the
    // screen (within a quarter of the screen beyond its edges).
    bool near = false;
    std::string nearWhy = "no spot, directional or point light";
    for (const scene::Light& l : scene.lights) {
        if (!epipolar(l) || minmax::atEye(l, scene.camera.position)) continue;
        const glm::dvec3 axis = minmax::epipolarAxis(l, scene.camera.position);
        if (minmax::epipoleNearScreen(scene.camera, axis, 0.25)) {
            near = true;
            nearWhy = "epipole of light '" + l.name + "' on or near the screen: brute-force march within " +
                      std::to_string(int(s.epipoleRadius)) + " px of it";
        } else if (!near) {
            nearWhy = "epipole far off screen (more than a quarter screen beyond every edge): no pixel is "
                      "near it";
        }
    }
    if (s.epipoleRadius <= 0.0 && near) {
        near = false;
        nearWhy = "epipole_radius = 0";
    }
    p.features.push_back({"NEAR_EPIPOLE", near, nearWhy});
    const bool hasSpot = render::hasLightOfType(scene, scene::LightType::Spot);
    const bool hasCookie = std::any_of(scene.lights.begin(), scene.lights.end(),
                                       [](const scene::Light& l) { return l.cookie >= 0; });
    p.features.push_back({"SPOT", hasSpot,
                          hasSpot ? (hasCookie ? "spot: A_spot * cookie per gamma piece of each lit run (analytic)"
                                               : "spot: each lit run cut at the cones, the penumbra's A_spot "
                                                 "integrated as the square of a lobe (analytic)")
                                  : "no spot light in the scene"});
    p.features.push_back({"COOKIE", hasCookie,
                          hasCookie ? "cookie texture sampled per gamma piece" : "no light has a cookie"});
    const bool hasPoint = render::hasLightOfType(scene, scene::LightType::Point);
    std::string pointWhy = "no point light in the scene";
    if (hasPoint && marchPoints) {
        pointWhy = "point_lights=march: point lights are marched per pixel";
    } else if (hasPoint) {
        const auto it = std::find_if(scene.lights.begin(), scene.lights.end(),
                                     [](const scene::Light& l) { return l.type == scene::LightType::Point; });
        pointWhy = "point light '" + it->name + "': rectified from its cube map, each slice over the gamma "
                   "range [0, gamma(beta, d)] its pixels' rays reach (gamma_range.comp)";
    }
    p.features.push_back({"EPIPOLAR_POINT", hasPoint && !marchPoints, pointWhy});
    // Area lights are integrated over their emitter as VPLs (cube maps of their own, a different light
    // position per VPL): marched per pixel.
    const bool area = render::hasLightOfType(scene, scene::LightType::Area);
    const auto eyeLight = std::find_if(scene.lights.begin(), scene.lights.end(), [&](const scene::Light& l) {
        return minmax::atEye(l, scene.camera.position);
    });
    const bool atEye = eyeLight != scene.lights.end();
    const bool brute = area || (hasPoint && marchPoints) || atEye;
    std::string bruteWhy = "every light has an epipolar path (spot, directional, point)";
    if (area)
        bruteWhy = "area lights: each VPL (a cube-mapped point-like light of its own) is marched per pixel with " +
                   std::to_string(s.vplSamples) + " samples (vpl_samples), not rectified";
    if (hasPoint && marchPoints) bruteWhy = (area ? bruteWhy + "; " : std::string()) + pointWhy;
    if (atEye)
        bruteWhy = (area || (hasPoint && marchPoints) ? bruteWhy + "; " : std::string()) + "light '" + eyeLight->name +
                   "' sits at the eye: every camera ray starts at it and there is no epipolar axis, so its rays are "
                   "marched with " + std::to_string(s.marchSamples) + " samples (march_samples)";
    p.features.push_back({"BRUTE_FORCE_LIGHTS", brute, bruteWhy});
    const bool cubes = render::hasLightOfType(scene, scene::LightType::Point) ||
                       render::hasLightOfType(scene, scene::LightType::Area);
    p.features.push_back({"SHADOW_MAPS_CUBE", cubes,
                          cubes ? "point lights / VPLs need omnidirectional maps" : "no point or area light"});
    const bool maps2D = hasSpot || render::hasLightOfType(scene, scene::LightType::Directional);
    p.features.push_back({"SHADOW_MAPS_2D", maps2D, maps2D ? "spot / directional lights" : "no spot or directional light"});
    // A far camera (scene/ray_reach.h): the brute-force marches sample a long span by the light.
    const bool farRays = scene::farRaysPossible(scene);
    p.features.push_back({"FAR_RAYS", farRays,
                          farRays ? "spans longer than 8 radii of the scene's bounds: the marches (VPLs, near the "
                                    "epipole) sample them by the light, and end where the shadow map ends"
                                  : "every lit span fits in 8 radii of the scene's bounds: uniform march samples"});
    render::planCulledLights(scene, p);
    // force_features=1: every stage runs and every permutation pruned by the scene is compiled in (the
    // traverse shader then carries spot, cookie, cube-map and near-epipole code the scene does not use).
    forcePlan(p, s.forceFeatures,
              {"NEAR_EPIPOLE", "EPIPOLAR_POINT", "SPOT", "COOKIE", "SHADOW_MAPS_CUBE", "SHADOW_MAPS_2D"});
    annotatePermutations(p, kDefines);
    return p;
}

FrameOutput MinmaxTechnique::run(const FrameInput& input) {
    const scene::Scene& scene = *input.scene;
    FrameOutput out;
    startRun(input, out);
    mMarkCamera = scene.camera;
    mMarkSize = {input.width, input.height};
    gl::StageClock clock;
    StageRunner stages(mStages, input, out, mReuse, clock);
    if (!stages.substepOnly(kTraverseIndex)) mMarkTraversed = false;
    if (!mView.runSharedStages(stages, input, "minmax", out)) return out;

    // The plan decides (sigma_s = 0 skips the epipolar stages unless force_features=1 runs them).
    const auto runs = [&](int stage) { return out.plan.stages[std::size_t(stage)].runs; };
    // ---- rectify ----
    mSvd = findFeature(out.plan, "INTEGRAND_SVD")->enabled;  // integrand=auto: the plan's choice
    const bool svd = mSvd;
    const FeaturePlan* log2 = findFeature(out.plan, "PREFIX_LOG2_PASSES");
    mLog2Prefix = log2 && log2->enabled;
    const bool toMipmap = stages.run(
        kRectifyIndex,
        [&] {
            prepareLights(scene, input, out.notes);
            if (runs(kRectifyIndex)) {
                for (LightWork& w : mWork) {
                    if (w.point()) measureRowGamma(w, scene, input);
                    rectify(w);
                    if (svd) prefixSums(w, scene);
                }
            }
        },
        [&] {
            publishRectified(out, input);
            if (runs(kRectifyIndex)) publishRowGamma(out);
            if (svd && runs(kRectifyIndex)) publishLowRank(out);
        });
    if (!toMipmap) return out;

    // ---- mipmap ----
    const bool toTraverse = stages.run(
        kMipmapIndex,
        [&] {
            const int wantedLevels = int(substepLimit(input, kMipmapIndex));
            if (runs(kMipmapIndex))
                for (LightWork& w : mWork) buildTree(w, wantedLevels);
        },
        [&] { publishTree(out, input); });
    // A tree stepped to fewer levels than it has cannot be walked.
    bool complete = true;
    for (const LightWork& w : mWork) complete = complete && (!runs(kMipmapIndex) || w.levelsBuilt == levelCount(w));
    if (!toTraverse || !complete) return out;

    // ---- traverse ----
    // Stepping the picked pixel's walk (the cursor's sub-step alone changed): the traversal's images
    // stand; only the walk's view is drawn again, and that is the stage's time.
    const bool walkOnly = stages.substepOnly(kTraverseIndex);
    const bool toCompose = stages.run(
        kTraverseIndex,
        [&] {
            if (walkOnly) {
                publishTraverse(out, input);
                return;
            }
            allocateTargets(input.width, input.height);
            mAirlight.clear(glm::vec4(0.0f));
            mVisited.clear(glm::vec4(0.0f));
            mNearMask.clear(glm::vec4(0.0f));
            mRayCoords.clear(glm::vec4(0.0f));
            if (runs(kTraverseIndex)) {
                const gl::Program& program = traverseProgram(out.plan);
                for (std::size_t i = 0; i < mWork.size(); ++i)
                    traverse(program, scene, input, &mWork[i], mWork[i].gpuIndex, i == 0);
                for (int li : mBruteLights) traverse(program, scene, input, nullptr, li, false);
            }
        },
        [&] {
            if (!walkOnly) {
                mMarkTraversed = runs(kTraverseIndex) && !mWork.empty();
                publishTraverse(out, input);
            }
            render::readBackAirlight(input, mAirlight, out);
        });
    if (!toCompose) return out;

    mView.runCompose(stages, kComposeIndex, input, mAirlight, out, "minmax");
    return out;
}

}  // namespace viz::minmax_detail

namespace viz {

std::unique_ptr<Technique> makeMinmaxTechnique() { return std::make_unique<minmax_detail::MinmaxTechnique>(); }

}  // namespace viz
