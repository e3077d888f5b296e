// slices: parameters, stages, plan and the run (slices_technique.h).
#include "techniques/slices/slices.h"

#include "techniques/slices/slices_technique.h"

#include "core/text.h"
#include "scene/ray_reach.h"

namespace viz::slices_detail {

namespace {

// Deterministic integer hash -> [0, 1).
float hashUnit(std::uint32_t x, std::uint32_t y, std::uint32_t seed) {
    std::uint32_t h = x * 0x8da6b343u ^ y * 0xd8163841u ^ seed * 0xcb1ab31fu;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return float(h >> 8) * (1.0f / 16777216.0f);
}

// Tileable value noise (period = size): two octaves of smoothly interpolated lattice values on periodic
// lattices of 8 and 16 cells. Channel r and g use different seeds (the paper's two noise maps in one texture).
std::vector<std::uint8_t> makeNoise(int size) {
    std::vector<std::uint8_t> rg(std::size_t(size * size * 2));
    auto octave = [&](int x, int y, int cells, std::uint32_t seed) {
        const float fx = float(x) * float(cells) / float(size), fy = float(y) * float(cells) / float(size);
        const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
        float ax = fx - float(x0), ay = fy - float(y0);
        ax = ax * ax * (3.0f - 2.0f * ax);
        ay = ay * ay * (3.0f - 2.0f * ay);
        auto v = [&](int i, int j) {
            return hashUnit(std::uint32_t((i % cells + cells) % cells), std::uint32_t((j % cells + cells) % cells), seed);
        };
        const float a = v(x0, y0) + (v(x0 + 1, y0) - v(x0, y0)) * ax;
        const float b = v(x0, y0 + 1) + (v(x0 + 1, y0 + 1) - v(x0, y0 + 1)) * ax;
        return a + (b - a) * ay;
    };
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            for (int c = 0; c < 2; ++c) {
                const std::uint32_t seed = std::uint32_t(17 + 101 * c);
                const float n = 0.65f * octave(x, y, 8, seed) + 0.35f * octave(x, y, 16, seed + 7);
                rg[std::size_t((y * size + x) * 2 + c)] = std::uint8_t(std::clamp(n, 0.0f, 1.0f) * 255.0f + 0.5f);
            }
    return rg;
}

// integration=auto: the slab integral wherever a light has a position of its own (a spot or point light:
// the integrand's 1/r^2 and cone are stiff along rays that pass it; at 128 planes, 320x240, grate 0.0527 ->
// 0.0065, stained-glass 0.813 -> 0.0044) and for suns alone (one node a slab, cut exactly at the surface:
// the same time, terrain 0.0066 -> 0.0044); the midpoint rule where an area light's VPLs are the only such
// lights (each VPL would run the angle code: tv-room 1.65x the time for 0.76 -> 0.70, the VPLs' own spacing
// limiting the error). Chosen per scene, not per light: one program draws every plane set.
bool autoIntegratesSlabs(const scene::Scene& scene) {
    return render::hasLightOfType(scene, scene::LightType::Spot) ||
           render::hasLightOfType(scene, scene::LightType::Point) ||
           !render::hasLightOfType(scene, scene::LightType::Area);
}

// The plan's word on SLAB_EQUIANGULAR: which integration the run takes and, under auto, why.
std::string slabIntegralWhy(const scene::Scene& scene, const SlicesSettings& s, const Terms& t) {
    const bool automatic = s.integration == SlicesIntegration::Auto;
    if (!t.equiangular) {
        if (!t.physical) return "weighting=artistic: the paper's one sample per plane";
        if (!automatic) return "integration=midpoint: one sample at the plane, weighted by the spacing";
        return "integration=auto, an area light's VPLs the only lights with a position: one sample at the plane (a "
               "slab integral costs each VPL its angle code, 1.65x the time on tv-room, while the VPLs' own spacing "
               "limits the error)";
    }
    const bool onlySuns = !render::hasLightOfType(scene, scene::LightType::Spot) &&
                          !render::hasLightOfType(scene, scene::LightType::Point) &&
                          !render::hasLightOfType(scene, scene::LightType::Area);
    std::string why = !automatic ? ""
                      : onlySuns ? "integration=auto, only suns: "
                                 : "integration=auto, a spot or point light: ";
    why += onlySuns ? "each plane integrates its slab as one node at the middle of its part before the surface (the "
                      "midpoint rule's cost, but cut exactly at the surface)"
                    : "each plane integrates its slab (cut to the surface and a spot's cone) with nodes at most "
                      "slab_angle = " + format("%g", s.slabAngle) + " rad apart as seen from the light";
    return why + "; planes and clip planes widened by the slab";
}

}  // namespace

const ParamTable<SlicesSettings>& slicesParams() {
    using S = SlicesSettings;
    static const ParamTable<S> table =
        ParamTable<S>()
            .add(&S::planes, {"planes", "N, sampling planes per light (substeps of the planes stage)", 128, 1, 4096, true})
            .declare({"planes_drawn", "draw only the k farthest planes (stepping, 1..N); 0: all", 0, 0, 4096, true})
            .add(&S::physical, {"weighting", "artistic (0: the paper's formula and constants) or physical (1: "
                                "converges to reference)", 1, 0, 1, true, {"artistic", "physical"}})
            .add(&S::integration,
                 {"integration", "physical weighting: midpoint (0: one sample at the plane, the spacing its weight, "
                  "the paper's), equiangular (1: each plane integrates its slab along the ray, cut to the surface "
                  "and a spot's cone, with nodes equally spaced in the angle seen from the light, 1/r^2 exact) or "
                  "auto (2: equiangular, except midpoint where an area light's VPLs are the only lights with a "
                  "position; the plan says which)",
                  2, 0, 2, true, {"midpoint", "equiangular", "auto"}})
            .add(&S::slabAngle, {"slab_angle", "the slab integral (integration=equiangular, or auto's choice): the "
                                 "largest angle (radians) between two nodes of a slab seen from the light (at most 64 "
                                 "nodes a slab)", 0.1, 0.05, 3.15, false})
            .add(&S::accum, {"accum", "accumulation target: rgba8 (0), rgba8-mask (1: channel mask), rgba16f (2), "
                             "rgba32f (3)", 3, 0, 3, true, {"rgba8", "rgba8-mask", "rgba16f", "rgba32f"}})
            .add(&S::accumRange, {"accum_range", "value stored as 1.0 in the 8-bit targets (rgba8-mask: per "
                                  "channel, x4 finer)", 2.0, 1e-6, 1e6, false})
            .add(&S::shadow, {"shadow", "shadow-map test: off, nearest (one texel, the paper) or pcf (3x3)", 1, 0, 2,
                              true, {"off", "nearest", "pcf"}})
            .add(&S::spotFalloff, {"spot_falloff", "1: spot angular attenuation A_spot", 1, 0, 1, true})
            .add(&S::cookie, {"cookie", "1: project the spot's cookie (when it has one)", 1, 0, 1, true})
            .add(&S::noise, {"noise", "1: two scrolling tiled noise layers modulate the density", 0, 0, 1, true})
            .add(&S::noiseTiles, {"noise_tiles", "noise repeats across the light's frustum", 2, 0.01, 100, false})
            .declare(animationTimeParam("scrolls the noise layers"))
            .add(&S::falloff, {"falloff", "artistic: 1/d^2 falloff on (0: constant intensity)", 1, 0, 1, true})
            .add(&S::ambient, {"ambient", "artistic: add the paper's ambient term 0.35 to 1/d^2", 1, 0, 1, true})
            .add(&S::artisticUnits, {"artistic_units", "artistic: paper units per scene unit in 20000/d^2", 100, 1e-6,
                                     1e6, false})
            .add(&S::blur, {"blur", "1: the paper's small blur on composite (3x3 tent)", 0, 0, 1, true})
            .add(&S::clip, {"clip", "1: clip the planes to the light frustum with gl_ClipDistance", 1, 0, 1, true})
            .add(&S::userClip, {"user_clip", "1: also clip with the user planes y >= clip_y_min and y <= clip_y_max "
                                "(world)", 0, 0, 1, true})
            .add(&S::clipYMin, {"clip_y_min", "user floor plane height (world y)", 0, -1e6, 1e6, false})
            .add(&S::clipYMax, {"clip_y_max", "user ceiling / window plane height (world y)", 1e6, -1e6, 1e6, false})
            .add(&S::directionalBox,
                 {"directional_box", "1: a directional light's planes fill and are clipped to its shadow map's box "
                  "(misses lit air outside it); 0: the camera frustum up to zfar", 0, 0, 1, true})
            .add(&S::worldGrid,
                 {"plane_grid", "fitted: the paper's N planes spread over the light volume's depth range (they move "
                  "whenever that range does); world: slabs on a world-fixed grid, spacing the fitted one rounded up "
                  "to a power of 2^(1/4), so planes stay put as the light moves (fewer crawling shadow edges)",
                  0, 0, 1, true, {"fitted", "world"}})
            .add(&S::distanceScale, {"distance_scale", "reference distance: beyond it N shrinks as reference / "
                                     "distance (min 8); 0: off", 0, 0, 1e6, false})
            .add(&S::depthTest, {"depth_test", "1 (default): the planes are drawn after the scene against its depth "
                                 "buffer, as in the paper, so a plane's fragments whose part of the ray lies wholly behind "
                                 "the first surface are rejected before they are shaded (the image is the same); 0: every "
                                 "fragment is shaded and the shader drops those", 1, 0, 1, true})
            .add(&S::countFragments, {"count_fragments", "1: count shaded fragments and those outside the light "
                                      "frustum (atomic counter)", 0, 0, 1, true})
            .add(&S::meshView, {"mesh_view", "1: draw the planes from an orbit camera of its own, with the scene, the "
                                "camera frustum and the lights (slices.plane_view)", 0, 0, 1, true})
            .declare(orbitParams("mesh_view"))
            .declare(pickParam('x', "planes slices.ray_planes lists"))
            .declare(pickParam('y', "planes slices.ray_planes lists"))
            .add(&S::rayPlanes, {"ray_planes", "1: record the picked pixel's planes (slices.ray_planes: the planes "
                                 "drawn again at that pixel alone, a replay of its blend, a readback); 0: off", 1, 0,
                                 1, true})
            .add(&S::forceFeatures, forceFeaturesParam())
            .declare(render::SceneViewPasses::params());
    VIZ_CHECK(table.missing().empty(), "slices declares a shared parameter the shared lists lack");
    return table;
}

SlicesTechnique::SlicesTechnique()
    : GlTechnique({.id = "slices",
                   .description = "Mitchell 2004: view-aligned sampling planes through the light frustum, "
                                  "additively blended",
                   .controls = {.pickedPixel = true, .orbitCamera = true, .animationTime = true}},
                  slicesParams()) {
    mStages = {
        render::SceneViewPasses::shadowStage("slices", {kCookies, kNoise}),
        render::SceneViewPasses::surfaceStage("slices"),
        {kStagePlanes, "Sampling planes",
         "N view-aligned planes per light, clipped to its frustum, added back to front",
         {"planes", "planes_drawn", "weighting", "integration", "slab_angle", "accum", "accum_range", "shadow", "spot_falloff", "cookie",
          "noise", "noise_tiles", "time", "falloff", "ambient", "artistic_units", "clip", "user_clip",
          "clip_y_min", "clip_y_max", "directional_box", "plane_grid", "distance_scale", "depth_test", "count_fragments",
          "mesh_view", "mesh_yaw", "mesh_pitch", "mesh_zoom", "pick_x", "pick_y", "ray_planes", "force_features"},
         {kAccum, kPlane, kPlaneMesh, kPlaneView, kFragments, kRayPlanes, kRayPlanesChart}, 128, "planes_drawn", "planes",
         {kPlaneMesh, kPlane}},
        {kStageResolve, "Resolve", "accumulation -> L_air: undo the 8-bit scale, sum the mask channels, blur",
         {"blur"}, {kAirlight}, 1},
        render::SceneViewPasses::composeStage("slices"),
    };
    checkStageOrder(mStages, kStageOrder);
}

std::vector<StabilisingOption> SlicesTechnique::stabilisingOptions(const scene::Scene& scene) const {
    // Only a spot light's planes follow a box that moves (the unbounded lights' planes fill the camera
    // frustum from the eye to zfar, which no motion changes).
    if (!render::hasLightOfType(scene, scene::LightType::Spot)) return {};
    // 64 planes: few enough that plane positions show.
    return {{"plane_grid=world", "the planes follow the light volume's depth range",
             {{"planes", 64.0}},
             {{"planes", 64.0}, {"plane_grid", 1.0}}}};
}

std::vector<QualitySetting> SlicesTechnique::qualitySweep(bool quick) const {
    // The plane count at the default integration=auto (each plane integrating its slab where a light has a
    // position or for suns: grate at 640x480 reaches 0.47 % with 2 planes, whose slabs' nodes by angle then
    // march each ray, and 0.80 % with 8; the midpoint rule 5.2 % with 128).
    std::vector<QualitySetting> sweep;
    const std::vector<int> counts = quick ? std::vector<int>{2, 8, 32, 128, 512}
                                          : std::vector<int>{2, 4, 8, 16, 32, 64, 128, 256, 512};
    for (int n : counts) sweep.push_back({"planes=" + std::to_string(n), {{"planes", double(n)}}});
    // accum codes as declared in params(): rgba8 0, rgba8-mask 1, rgba16f 2 (rgba32f 3 above).
    const std::vector<std::pair<std::string, double>> accums =
        quick ? std::vector<std::pair<std::string, double>>{{"rgba8-mask", 1}}
              : std::vector<std::pair<std::string, double>>{{"rgba8", 0}, {"rgba8-mask", 1}, {"rgba16f", 2}};
    for (const auto& [name, code] : accums)
        sweep.push_back({"planes=256 " + name, {{"planes", 256.0}, {"accum", code}}});
    // The paper's one sample per plane (integration=midpoint), for the comparison.
    const std::vector<int> midpointCounts = quick ? std::vector<int>{128} : std::vector<int>{32, 128, 512};
    for (int n : midpointCounts)
        sweep.push_back({"planes=" + std::to_string(n) + " midpoint", {{"planes", double(n)}, {"integration", 0.0}}});
    return sweep;
}

std::optional<StiffBound> SlicesTechnique::stiffBound(const std::string& caseClass) const {
    static const std::map<std::string, StiffBound> kBounds = {
        {"medium", {0.3, "at sigma_t = 50 the lit near field (1/sigma_t = 0.02) is shorter than the plane "
                         "spacing (0.012 at N = 512) plus znear, and a slab's nodes follow the angle from the light, "
                         "not the transmittance: 0.20 measured (one sample per plane: 0.21)"}},
        {"intensity", {0.01, "linear in the intensity (rgba32f accumulation)"}},
        {"scale", {0.01, "eye-relative planes and distance-valued shadow maps are scale-free"}},
        {"singular-ray", {0.005, "the pixels at the light are left out; a slab node on the light takes the ray's "
                                 "direction (0.0019 measured)"}},
        {"near-light", {0.003, "each plane integrates its slab with nodes by angle from the light (integration="
                               "auto), so the 1/r^2 peak of the ray passing 1e-6 from it is integrated exactly: "
                               "0.0013 measured (one sample per plane missed it: 1.0)"}},
        {"epipole", {0.05, "unbounded planes for the sun; grazing sun is the worst (shadow-map bias)"}},
        {"camera-placement", {0.03, "the nearest slab reaches the eye (its plane drawn just beyond znear)"}},
        {"geometry", {0.05, "shadow-map rasterisation drops slivers the reference still hits"}},
        {"leak", {0.03, "the planes use the medium lookup: no band of light behind thin walls (0.0031 measured)"}},
        {"depth-range", {0.03, "distance-valued R32F maps keep the precision near the occluders"}},
        {"phase", {0.05, "the HG lobe is sampled plane by plane; g = 0.99 is the worst"}},
    };
    return boundOf(kBounds, caseClass);
}

Plan SlicesTechnique::plan(const scene::Scene& scene, const Settings& settings) const {
    const SlicesSettings s = slicesParams().read(settings);
    Plan p = planEveryStage(mStages);
    const bool hasSpot = render::hasLightOfType(scene, scene::LightType::Spot);
    const bool hasDir = render::hasLightOfType(scene, scene::LightType::Directional);
    const bool hasOther = render::hasLightOfType(scene, scene::LightType::Point) || render::hasLightOfType(scene, scene::LightType::Area);
    if (scene.medium.sigma_s == 0.0) {
        p.stages[kPlanesIndex].runs = false;
        p.stages[kPlanesIndex].why = "sigma_s = 0: the medium scatters nothing, L_air = 0";
    } else if (scene.lights.empty()) {
        p.stages[kPlanesIndex].runs = false;
        p.stages[kPlanesIndex].why = "no light: L_air = 0";
    }
    const bool boxedDir = s.directionalBox;
    const bool unbounded = hasOther || (hasDir && !boxedDir);
    p.features.push_back({"UNBOUNDED_PLANES", unbounded,
                          unbounded ? "point / area (VPL) / directional lights share N unclipped planes over "
                                      "the camera frustum to zfar (no light frustum bounds their light)"
                                    : "only spot (or boxed directional) lights: planes in each light's frustum"});
    const Terms t = terms(scene, s);
    const double reach = t.planesEnd;
    p.features.push_back({"FAR_TAIL", t.farTail,
                          t.farTail ? "zfar " + format("%g", scene.camera.zfar) +
                                          " reaches far past the scene: the unbounded planes end at its far side (" +
                                          format("%.3g", reach) +
                                          "), and each ray past it gets 8 shadow-tested samples per unbounded light, "
                                          "placed by the light"
                                    : reach < scene.camera.zfar
                                          ? "weighting=artistic or no unbounded light: the planes end at the scene's far side"
                                          : "the planes reach zfar (" + format("%g", scene.camera.zfar) + ")"});
    p.features.push_back({"PHYSICAL", t.physical,
                          t.physical ? "weight = integrand of L_air x plane spacing along the ray"
                                     : "weighting=0: the paper's artistic formula and constants"});
    p.features.push_back({"SLAB_EQUIANGULAR", t.equiangular, slabIntegralWhy(scene, s, t)});
    p.features.push_back({"SPOT_FALLOFF", t.spot,
                          t.spot ? "A_spot (KHR angular attenuation)"
                                 : (hasSpot ? "spot_falloff=0" : "no spot light in the scene")});
    const bool hasCookie = std::any_of(scene.lights.begin(), scene.lights.end(), [](const scene::Light& l) {
        return l.type == scene::LightType::Spot && l.cookie >= 0;
    });
    p.features.push_back({"COOKIE", t.cookie,
                          t.cookie ? "cookie texture projected over the outer cone"
                                   : (hasCookie ? "cookie=0" : "no spot light has a cookie")});
    p.features.push_back({"SHADOW", t.shadow, t.shadow ? "shadow-map test per plane sample" : "shadow=0"});
    p.features.push_back({"PCF", t.pcf, t.pcf ? "3x3 percentage-closer filtering"
                                              : "nearest texel (the paper's pick-nearest)"});
    p.features.push_back({"NOISE", t.noise, t.noise ? "two scrolling tiled noise layers" : "noise=0"});
    p.features.push_back({"CHANNEL_MASK", t.mask,
                          t.mask ? "plane i -> channel i mod 4 of an RGBA8 target; monochrome light colour"
                                 : "accum is not rgba8-mask"});
    p.features.push_back({"BLUR", t.blur, t.blur ? "3x3 tent on composite" : "blur=0"});
    p.features.push_back({"DEPTH_TEST", t.depthTest,
                          t.depthTest ? "the planes are tested against the surface's depth before they are shaded: a "
                                        "fragment whose part of the ray lies behind the first surface costs no shading"
                          : s.depthTest ? "count_fragments=1: every fragment of the planes is shaded and counted (the "
                                          "shader drops those behind the first surface)"
                                      : "depth_test=0: every fragment of every plane is shaded, and those behind the "
                                        "first surface are dropped by the shader"});
    p.features.push_back({"CLIP", t.clip,
                          t.clip               ? "gl_ClipDistance against the light frustum's 6 planes"
                          : !s.clip ? "clip=0: whole planes over the frustum's bounding box"
                                                : "no spot light (and directional_box=0): every light's planes "
                                                  "are unbounded, there is no light frustum to clip against"});
    if (hasDir) {
        const bool box = s.directionalBox;
        p.features.push_back({"DIRECTIONAL_BOX", box,
                              box ? "directional planes fill and are clipped to the shadow map's box"
                                  : "a directional light lights all space: planes fill the camera frustum to "
                                    "zfar, no frustum clipping"});
    }
    const bool scaled = s.distanceScale > 0.0;
    p.features.push_back({"DISTANCE_SCALED_PLANES", scaled,
                          scaled ? "N shrinks beyond distance_scale from the light volume (spacing compensates)"
                                 : "distance_scale=0: always N planes"});
    const bool worldGrid = s.worldGrid;
    p.features.push_back({"WORLD_GRID_PLANES", worldGrid,
                          worldGrid ? "plane_grid=world: slabs on a world-fixed grid (N + 2 at most), planes do "
                                      "not follow the light volume's depth range"
                                    : "plane_grid=fitted: N planes spread over the light volume's depth range"});
    p.features.push_back({"PICK_RAY", t.pick,
                          t.pick ? "the picked pixel's planes recorded (slices.ray_planes): the planes drawn "
                                   "again scissored to that pixel (PICK_RAY shader, colour writes off), a "
                                   "replay of its blend in the accumulation's format, one readback; the "
                                   "frame's own draw is unchanged (README: what it costs)"
                                 : "ray_planes=0: none of it runs, costs nothing"});
    p.features.push_back({"USER_CLIP", t.userClip, t.userClip ? "planes y >= clip_y_min, y <= clip_y_max"
                                                             : "user_clip=0"});
    p.features.push_back({"SPOT_LIGHTS", t.spots,
                          t.spots ? "a spot light: its cone and cookie code compiled in"
                                  : "no spot light: spot code compiled out (LIGHTS_NO_SPOT)"});
    p.features.push_back({"SHADOW_MAPS_CUBE", t.cubes,
                          t.cubes ? "point lights / area-light VPLs: cube shadow maps"
                                  : "no point or area light: cube-map code compiled out (SHADOW_NO_CUBE)"});
    render::planCulledLights(scene, p);
    p.features.push_back({"PERMUTATION", true, permutationKey(t)});
    if (s.forceFeatures) {
        SlicesSettings unforced = s;
        unforced.forceFeatures = false;
        const Terms t0 = terms(scene, unforced);
        for (FeaturePlan& f : p.features)
            if ((f.feature == "SPOT_FALLOFF" && t.spot != t0.spot) || (f.feature == "COOKIE" && t.cookie != t0.cookie) ||
                (f.feature == "CLIP" && t.clip != t0.clip) || (f.feature == "SHADOW_MAPS_CUBE" && t.cubes != t0.cubes) ||
                (f.feature == "SPOT_LIGHTS" && t.spots != t0.spots))
                f.why = "forced on (force_features=1); the plan would leave it out for this scene";
        forcePlan(p, true, {});
    }
    return p;
}

FrameOutput SlicesTechnique::run(const FrameInput& input) {
    const scene::Scene& scene = *input.scene;
    FrameOutput out;
    const SlicesSettings& s = startRun(input, out);
    gl::StageClock clock;
    StageRunner stages(mStages, input, out, mReuse, clock);

    if (!mTriangle) {
        mTriangle = std::make_unique<render::FullscreenTriangle>();
        mVao = gl::VertexArray::create("slices.planes_vao");
        mFramebuffer = gl::Framebuffer::create("slices.fbo");
        mCounters = gl::Buffer::create({.bytes = 8, .label = "slices.fragment_counters"});
        const std::vector<std::uint8_t> noise = makeNoise(kNoiseSize);
        mNoise = gl::Texture::create(
            {.target = GL_TEXTURE_2D, .format = GL_RG8, .size = {kNoiseSize, kNoiseSize, 1}, .label = kNoise});
        mNoise.upload(GL_RG, GL_UNSIGNED_BYTE, noise.data());
        mNoise.setFilter(GL_LINEAR, GL_LINEAR);
        mNoise.setWrap(GL_REPEAT);
    }
    // Shadow maps (with the cookies and the noise they project) and the camera view: the shared stages.
    if (!mView.runSharedStages(stages, input, "slices", out, [&] {
            out.intermediates.push_back(render::textureIntermediate(
                kCookies, "Cookies",
                mView.lights().cookieCount() > 0
                    ? "spot cookie textures (sRGB bytes), one layer per cookie"
                    : "no light in this scene has a cookie: a 1x1 white placeholder (a cookie of 1 changes nothing)",
                "",
                ViewKind::Colour, 0.0f, 1.0f, mView.lights().cookies()));
            out.intermediates.push_back(render::textureIntermediate(
                kNoise, "Noise", "two tileable value-noise layers (r, g), generated, projected from the light", "",
                ViewKind::Colour, 0.0f, 1.0f, mNoise));
        }))
        return out;

    // ---- sampling planes ----
    Terms t;
    const bool toResolve = stages.run(
        kPlanesIndex,
        [&] {
            t = terms(scene, s);
            t.lastPlane = input.shows(kPlane);
            allocateTargets(input.width, input.height, s.accum);
            const float zero[4] = {0, 0, 0, 0};
            glClearTexImage(mAccum.id(), 0, GL_RGBA, GL_FLOAT, zero);
            glClearTexImage(mPlane.id(), 0, GL_RGBA, GL_FLOAT, zero);
            mCounters.clearZero();
            mQueryCounts[0] = mQueryCounts[1] = 0.0;
            mPlaneQueriesUsed = 0;
            mPlanesUsed.clear();
            mPolygons.clear();
            mRayPlanes.reset();
            if (out.plan.stages[kPlanesIndex].runs) drawPlanes(scene, input, t);
        },
        [&] {
            const int n = mPlanesUsed.empty() ? s.planes : mPlanesUsed.front();
            const int drawnLimit = int(substepLimit(input, kPlanesIndex));
            const int drawn = drawnLimit > 0 ? std::min(n, drawnLimit) : n;
            out.intermediates.push_back(render::textureIntermediate(
                kAccum, "Accumulation after " + std::to_string(drawn) + " of " + std::to_string(n) + " planes",
                t.mask ? "plane i added to channel i mod 4 (r, g, b, a), times the store scale"
                       : "sum of the planes drawn so far (back to front), times the store scale",
                "stored value", ViewKind::Colour, 0.0f, 1.0f, mAccum));
            out.intermediates.push_back(planeIntermediate(drawn, t.lastPlane));
            out.intermediates.push_back(polygonIntermediate());
            // Shown in the window, the planes' table is drawn as the orbit view too (as polyvol's mesh):
            // a table of vertices stretched into an image says nothing.
            const std::size_t tableIndex = out.intermediates.size() - 1;
            const bool tableShown = input.shows(kPlaneMesh);
            if (s.meshView || tableShown) {
                mMeshView.begin(scene, mView.gpuScene(), render::orbitOf(input.controls),
                                input.width, input.height);
                // Each drawn plane's outline, far planes dim and near ones bright (the drawing order).
                const std::size_t count = mPolygons.size();
                for (std::size_t row = 0; row < count; ++row) {
                    const auto& polygon = mPolygons[row];
                    std::vector<glm::vec3> edges;
                    for (std::size_t v = 0; v < polygon.size(); ++v) {
                        edges.push_back(glm::vec3(polygon[v]));
                        edges.push_back(glm::vec3(polygon[(v + 1) % polygon.size()]));
                    }
                    const float near = count > 1 ? float(row) / float(count - 1) : 1.0f;
                    mMeshView.lines(edges, glm::vec4(0.25f + 0.75f * near, 0.45f + 0.4f * near, 0.2f, 1.0f));
                }
                gl::Framebuffer::bindDefault();
                Intermediate view = render::textureIntermediate(
                    kPlaneView, "Sampling planes (orbit view)",
                    "the drawn planes' outlines (far dim, near bright) with the scene, the camera frustum (blue) and the "
                    "lights (yellow); mesh_yaw, mesh_pitch, mesh_zoom move the camera",
                    "", ViewKind::Colour, 0.0f, 1.0f, mMeshView.texture());
                view.orbit = true;  // the window turns it by dragging
                view.picture = true;
                if (tableShown) {
                    Intermediate asTable = view;
                    asTable.id = kPlaneMesh;
                    asTable.label = "Sampling planes (mesh)";
                    if (!s.meshView) asTable.note += "; drawn because this view is shown (its time counts in the planes stage)";
                    out.intermediates[tableIndex] = std::move(asTable);
                }
                if (s.meshView) out.intermediates.push_back(std::move(view));
            }
            if (mRayPlanes) {
                Intermediate i;
                i.id = kRayPlanes;
                i.label = "Planes along pixel (" + std::to_string(mPickPixel.x) + ", " + std::to_string(mPickPixel.y) +
                          ")'s ray";
                i.note = "one row per plane drawn (sets of lights in turn, back to front); columns of rgba: 0 (plane i, "
                         "view depth s, t, dt), 1 (status: 1 added, 2 beyond the surface d, 3 clipped by the light "
                         "frustum, 4 by a user plane, 5 outside the plane's quad; V (-1 untested), mask channel, d), 2 "
                         "shader output, 3 added after the blend's quantisation, 4 accumulation after it (stored "
                         "units), 5 (light, set, L_air added, unquantised L_air)";
                i.units = "stored value";
                i.kind = ViewKind::Buffer;
                i.image = mRayPlanes;
                i.extent = {mRayPlanes->width, mRayPlanes->height, 1};
                i.rayView = true;
                out.intermediates.push_back(std::move(i));
                Intermediate chart;
                chart.id = kRayPlanesChart;
                chart.label = "Planes along pixel (" + std::to_string(mPickPixel.x) + ", " +
                              std::to_string(mPickPixel.y) + ")'s ray (chart)";
                chart.note = "nearest plane left, t grows to the right; bars: each plane's L_air as shaded (grey) and "
                             "as stored (orange), scaled to the largest; strip: green added, blue beyond the surface, "
                             "grey clipped by the light frustum, purple by a user plane, black outside the quad; "
                             "bottom: shadow test V (white lit, black shadowed, blue untested)";
                chart.kind = ViewKind::Colour;
                chart.image = std::make_shared<Image>(slices::rayPlanesChart(*mRayPlanes));
                chart.extent = {chart.image->width, chart.image->height, 1};
                chart.rayView = true;
                chart.picture = true;
                out.intermediates.push_back(std::move(chart));
            }
            if (t.count) {
                std::uint32_t counts[2] = {0, 0};
                mCounters.download(0, sizeof(counts), counts);
                auto img = std::make_shared<Image>(2, 2, 1);
                img->at(0, 0) = float(mQueryCounts[0]);
                img->at(1, 0) = float(mQueryCounts[1]);
                img->at(0, 1) = float(counts[0]);
                img->at(1, 1) = float(counts[1]);
                Intermediate i;
                i.id = kFragments, i.label = "Fragment counts";
                i.note = "x = 0: fragments outside the light frustum, x = 1: all fragments; row 0 by occlusion "
                         "query, row 1 by atomic counters";
                i.kind = ViewKind::Buffer;
                i.image = img;
                i.extent = {2, 2, 1};
                out.intermediates.push_back(i);
            }
        });
    if (!toResolve) return out;

    // ---- resolve ----
    const bool toCompose = stages.run(
        kResolveIndex, [&] { resolve(t, scene, input); },
        [&] {
            out.intermediates.push_back(render::textureIntermediate(
                kAirlight, "L_air", "single-scattered light reaching the eye, decoded from the accumulation",
                "radiance", ViewKind::Colour, 0.0f, 1.0f, mAirlight));
            render::readBackAirlight(input, mAirlight, out);
        });
    if (!toCompose) return out;

    mView.runCompose(stages, kComposeIndex, input, mAirlight, out, "slices");
    return out;
}

Terms SlicesTechnique::terms(const scene::Scene& scene, const SlicesSettings& s) {
    Terms t;
    const bool hasSpot = render::hasLightOfType(scene, scene::LightType::Spot);
    const bool hasCookie = std::any_of(scene.lights.begin(), scene.lights.end(), [](const scene::Light& l) {
        return l.type == scene::LightType::Spot && l.cookie >= 0;
    });
    // force_features=1 compiles in what this scene would not need (to measure what leaving it out saves).
    const bool force = s.forceFeatures;
    t.physical = s.physical;
    t.equiangular = s.physical && (s.integration == SlicesIntegration::Equiangular ||
                                   (s.integration == SlicesIntegration::Auto && autoIntegratesSlabs(scene)));
    t.spot = (hasSpot || force) && s.spotFalloff;
    t.cookie = (hasCookie || force) && s.cookie;
    t.shadow = s.shadow != 0;
    t.pcf = s.shadow == 2;
    t.noise = s.noise;
    t.mask = s.accum == SlicesAccum::Rgba8Mask;
    t.blur = s.blur;
    // Only spot lights (and directional lights boxed by directional_box=1) have a frustum to clip to.
    const bool boxedDirectional = render::hasLightOfType(scene, scene::LightType::Directional) &&
                                  s.directionalBox;
    t.clip = s.clip && (hasSpot || boxedDirectional || force);
    t.userClip = s.userClip;
    t.count = s.countFragments;
    // count_fragments counts every fragment of the planes twice (atomic counter, occlusion query): under the
    // depth test the query would count only those in front of the surface and the counter all of them.
    t.depthTest = s.depthTest && !s.countFragments;
    t.pick = s.rayPlanes;
    t.spots = hasSpot || force;
    t.cubes = render::hasLightOfType(scene, scene::LightType::Point) ||
              render::hasLightOfType(scene, scene::LightType::Area) || force;
    // The unbounded lights' planes end at the scene's far side under a far camera; the rest of each ray is
    // then added on resolve (physical weighting only: the artistic one is no integral to continue).
    const bool unbounded = t.cubes || (render::hasLightOfType(scene, scene::LightType::Directional) && !s.directionalBox);
    t.planesEnd = scene::depthOfInterest(scene);
    t.farTail = t.physical && unbounded && t.planesEnd < scene.camera.zfar;
    return t;
}

}  // namespace viz::slices_detail

namespace viz {

std::unique_ptr<Technique> makeSlicesTechnique() { return std::make_unique<slices_detail::SlicesTechnique>(); }

}  // namespace viz
