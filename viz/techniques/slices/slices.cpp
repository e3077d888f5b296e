#include "techniques/slices/slices.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "gl/buffer.h"
#include "gl/framebuffer.h"
#include "gl/program.h"
#include "gl/readback.h"
#include "gl/stage_clock.h"
#include "gl/texture.h"
#include "gl/vertex_array.h"
#include "render/mesh_view.h"
#include "render/compose.h"
#include "render/eye_space.h"
#include "render/gpu_lights.h"
#include "render/gpu_scene.h"
#include "render/intermediates.h"
#include "render/light_culling.h"
#include "render/scene_view.h"
#include "render/shadow_maps.h"
#include "render/surface_pass.h"
#include "scene/camera.h"
#include "techniques/slices/ray_planes.h"
#include "techniques/slices/slice_geometry.h"

namespace viz {
namespace {

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

enum StageIndex { kShadowMapsIndex = 0, kSurfaceIndex, kPlanesIndex, kResolveIndex, kComposeIndex };

// The paper's example draws at most 100 planes; its per-plane scale is 9 / (N / 100).
constexpr double kPaperMaxPlanes = 100.0;
constexpr double kPaperAmbient = 0.35;
constexpr int kNoiseSize = 64;
// distance_scale never goes below this many planes.
constexpr int kMinScaledPlanes = 8;


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

struct Terms {
    bool physical = true;
    bool spot = false, cookie = false, shadow = false, pcf = false, noise = false;
    bool mask = false, blur = false, clip = true, userClip = false, count = false, cubes = false;
    bool pick = false;  // record the picked pixel's planes (slices.ray_planes)
};

// One draw set as the pick replay needs it again.
struct PickSet {
    int light = -1;  // index into Scene::lights, -1: the unbounded lights together
    int base = 0;    // first record
    int drawn = 0;
    bool clipLight = false;
    float depthFar = 0.0f, spacing = 0.0f, drawNear = 0.0f;
    glm::vec2 boxMin{0.0f}, boxMax{0.0f};
    glm::mat4 volume{1.0f};
};

class SlicesTechnique final : public Technique {
public:
    SlicesTechnique() {
        mParams = {
            {"planes", "N, sampling planes per light (substeps of the planes stage)", 128, 1, 4096, true},
            {"planes_drawn", "draw only the k farthest planes (stepping, 1..N); 0: all", 0, 0, 4096, true},
            {"weighting", "artistic (0: the paper's formula and constants) or physical (1: converges to reference)",
             1, 0, 1, true, {"artistic", "physical"}},
            {"accum", "accumulation target: rgba8 (0), rgba8-mask (1: channel mask), rgba16f (2), rgba32f (3)", 3, 0,
             3, true, {"rgba8", "rgba8-mask", "rgba16f", "rgba32f"}},
            {"accum_range", "value stored as 1.0 in the 8-bit targets (rgba8-mask: per channel, x4 finer)", 2.0,
             1e-6, 1e6, false},
            {"shadow", "shadow-map test: off, nearest (one texel, the paper) or pcf (3x3)", 1, 0, 2, true,
             {"off", "nearest", "pcf"}},
            {"spot_falloff", "1: spot angular attenuation A_spot", 1, 0, 1, true},
            {"cookie", "1: project the spot's cookie (when it has one)", 1, 0, 1, true},
            {"noise", "1: two scrolling tiled noise layers modulate the density", 0, 0, 1, true},
            {"noise_tiles", "noise repeats across the light's frustum", 2, 0.01, 100, false},
            {"time", "seconds: scrolls the noise layers", 0, 0, 1e6, false},
            {"falloff", "artistic: 1/d^2 falloff on (0: constant intensity)", 1, 0, 1, true},
            {"ambient", "artistic: add the paper's ambient term 0.35 to 1/d^2", 1, 0, 1, true},
            {"artistic_units", "artistic: paper units per scene unit in 20000/d^2", 100, 1e-6, 1e6, false},
            {"blur", "1: the paper's small blur on composite (3x3 tent)", 0, 0, 1, true},
            {"clip", "1: clip the planes to the light frustum with gl_ClipDistance", 1, 0, 1, true},
            {"user_clip", "1: also clip with the user planes y >= clip_y_min and y <= clip_y_max (world)", 0, 0, 1,
             true},
            {"clip_y_min", "user floor plane height (world y)", 0, -1e6, 1e6, false},
            {"clip_y_max", "user ceiling / window plane height (world y)", 1e6, -1e6, 1e6, false},
            {"directional_box", "1: a directional light's planes fill and are clipped to its shadow map's box "
             "(misses lit air outside it); 0: the camera frustum up to zfar", 0, 0, 1, true},
            {"distance_scale", "reference distance: beyond it N shrinks as reference / distance (min 8); 0: off", 0,
             0, 1e6, false},
            {"count_fragments", "1: count shaded fragments and those outside the light frustum (atomic counter)",
             0, 0, 1, true},
            {"mesh_view", "1: draw the planes from an orbit camera of its own, with the scene, the camera frustum "
             "and the lights (slices.plane_view)", 0, 0, 1, true},
            {"mesh_yaw", "mesh_view: orbit camera's angle about the vertical (degrees)", 35, -360, 360, false},
            {"mesh_pitch", "mesh_view: orbit camera's angle above the horizon (degrees)", 25, -89, 89, false},
            {"mesh_zoom", "mesh_view: orbit camera's zoom (1 fits the scene and the camera)", 1, 0.05, 50, false},
            {"pick_x", "picked pixel (column, 0 = left) whose planes slices.ray_planes lists; -1: image centre", -1,
             -1, 16384, true},
            {"pick_y", "picked pixel (row, 0 = top); -1: image centre", -1, -1, 16384, true},
            {"ray_planes", "1: record the picked pixel's planes (slices.ray_planes: the planes drawn again at that "
             "pixel alone, a replay of its blend, a readback); 0: off", 1, 0, 1, true},
            forceFeaturesParam(),
        };
        for (ParamInfo& p : render::SceneViewPasses::params()) mParams.push_back(std::move(p));
        mStages = {
            render::SceneViewPasses::shadowStage("slices", {kCookies, kNoise}),
            render::SceneViewPasses::surfaceStage("slices"),
            {kStagePlanes, "Sampling planes",
             "N view-aligned planes per light, clipped to its frustum, added back to front",
             {"planes", "planes_drawn", "weighting", "accum", "accum_range", "shadow", "spot_falloff", "cookie",
              "noise", "noise_tiles", "time", "falloff", "ambient", "artistic_units", "clip", "user_clip",
              "clip_y_min", "clip_y_max", "directional_box", "distance_scale", "count_fragments", "mesh_view",
              "mesh_yaw", "mesh_pitch", "mesh_zoom", "pick_x", "pick_y", "ray_planes", "force_features"},
             {kAccum, kPlane, kPlaneMesh, kPlaneView, kFragments, kRayPlanes, kRayPlanesChart}, 128, "planes_drawn", "planes"},
            {kStageResolve, "Resolve", "accumulation -> L_air: undo the 8-bit scale, sum the mask channels, blur",
             {"blur"}, {kAirlight}, 1},
            render::SceneViewPasses::composeStage("slices"),
        };
    }

    std::string id() const override { return "slices"; }
    std::string description() const override {
        return "Mitchell 2004: view-aligned sampling planes through the light frustum, additively blended";
    }
    const std::vector<StageInfo>& stages() const override { return mStages; }
    const std::vector<ParamInfo>& params() const override { return mParams; }
    bool needsGl() const override { return true; }

    // Plane count in float accumulation, then the precision lab's targets at one plane count.
    std::vector<QualitySetting> qualitySweep(bool quick) const override {
        std::vector<QualitySetting> sweep;
        const std::vector<int> counts = quick ? std::vector<int>{32, 128, 512} : std::vector<int>{16, 32, 64, 128, 256, 512};
        for (int n : counts) sweep.push_back({"planes=" + std::to_string(n), {{"planes", double(n)}}});
        // accum codes as declared in params(): rgba8 0, rgba8-mask 1, rgba16f 2 (rgba32f 3 above).
        const std::vector<std::pair<std::string, double>> accums =
            quick ? std::vector<std::pair<std::string, double>>{{"rgba8-mask", 1}}
                  : std::vector<std::pair<std::string, double>>{{"rgba8", 0}, {"rgba8-mask", 1}, {"rgba16f", 2}};
        for (const auto& [name, code] : accums)
            sweep.push_back({"planes=256 " + name, {{"planes", 256.0}, {"accum", code}}});
        // The report times the technique, not the inspector's recording of one pixel.
        for (QualitySetting& q : sweep) q.settings["ray_planes"] = 0.0;
        return sweep;
    }

    Settings stiffSettings() const override { return {{"planes", 512.0}, {"ray_planes", 0.0}}; }
    // Mitchell 2004: the artistic formula and constants, the RGBA8 target with the channel mask, 100
    // planes (the example application's count, Figure 8.1.11c).
    Settings paperSettings() const override { return {{"weighting", 0.0}, {"accum", 1.0}, {"planes", 100.0}}; }

    // Measured by `airlight report --suite stiff` at 33x25 (figures in README.md), bounds about twice that.
    std::optional<StiffBound> stiffBound(const std::string& caseClass) const override {
        static const std::map<std::string, StiffBound> kBounds = {
            {"medium", {0.3, "a midpoint rule over planes: at sigma_t = 50 the lit near field (1/sigma_t = 0.02) "
                             "is shorter than the plane spacing (0.012 at N = 512) plus znear; 0.21 measured"}},
            {"intensity", {0.01, "linear in the intensity (rgba32f accumulation)"}},
            {"scale", {0.01, "eye-relative planes and distance-valued shadow maps are scale-free"}},
            {"singular-ray", {0.005, "no plane sample lands on the light; its own pixel is left out"}},
            {"near-light", {1.0, "planes sample each ray at fixed depths: none lands within 1e-6 of the light, so "
                                 "the one pixel that holds nearly all of the image's airlight is missed (1.0)"}},
            {"epipole", {0.05, "unbounded planes for the sun; grazing sun is the worst (shadow-map bias)"}},
            {"camera-placement", {0.03, "the nearest slab reaches the eye (its plane drawn just beyond znear)"}},
            {"geometry", {0.05, "shadow-map rasterisation drops slivers the reference still hits"}},
            {"leak", {0.03, "the planes use the medium lookup: no band of light behind thin walls (0.0045 measured)"}},
            {"depth-range", {0.03, "distance-valued R32F maps keep the precision near the occluders"}},
            {"phase", {0.05, "the HG lobe is sampled plane by plane; g = 0.99 is the worst"}},
        };
        const auto it = kBounds.find(caseClass);
        return it == kBounds.end() ? std::nullopt : std::optional<StiffBound>(it->second);
    }

    // Linked cursors: in every light's shadow map the pixel's eye ray and where it enters or leaves
    // shadow by the map's own test (render/shadow_map_markers.h). They follow the camera-view stage.
    std::vector<ViewMarker> markersFor(glm::ivec2 pixel, const std::string& id) const override {
        return mView.shadowMapMarkers(pixel, id, "slices");
    }

    Plan plan(const scene::Scene& scene, const Settings& s) const override {
        Plan p;
        for (const StageInfo& st : mStages) p.stages.push_back({st.id, true, ""});
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
        const bool boxedDir = s.at("directional_box") != 0.0;
        const bool unbounded = hasOther || (hasDir && !boxedDir);
        p.features.push_back({"UNBOUNDED_PLANES", unbounded,
                              unbounded ? "point / area (VPL) / directional lights share N unclipped planes over "
                                          "the camera frustum to zfar (no light frustum bounds their light)"
                                        : "only spot (or boxed directional) lights: planes in each light's frustum"});
        const Terms t = terms(scene, s);
        p.features.push_back({"PHYSICAL", t.physical,
                              t.physical ? "weight = integrand of L_air x plane spacing along the ray"
                                         : "weighting=0: the paper's artistic formula and constants"});
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
        p.features.push_back({"CLIP", t.clip,
                              t.clip               ? "gl_ClipDistance against the light frustum's 6 planes"
                              : s.at("clip") == 0.0 ? "clip=0: whole planes over the frustum's bounding box"
                                                    : "no spot light (and directional_box=0): every light's planes "
                                                      "are unbounded, there is no light frustum to clip against"});
        if (hasDir) {
            const bool box = s.at("directional_box") != 0.0;
            p.features.push_back({"DIRECTIONAL_BOX", box,
                                  box ? "directional planes fill and are clipped to the shadow map's box"
                                      : "a directional light lights all space: planes fill the camera frustum to "
                                        "zfar, no frustum clipping"});
        }
        const bool scaled = s.at("distance_scale") > 0.0;
        p.features.push_back({"DISTANCE_SCALED_PLANES", scaled,
                              scaled ? "N shrinks beyond distance_scale from the light volume (spacing compensates)"
                                     : "distance_scale=0: always N planes"});
        p.features.push_back({"PICK_RAY", t.pick,
                              t.pick ? "the picked pixel's planes recorded (slices.ray_planes): the planes drawn "
                                       "again scissored to that pixel (PICK_RAY shader, colour writes off), a "
                                       "replay of its blend in the accumulation's format, one readback; the "
                                       "frame's own draw is unchanged (README: what it costs)"
                                     : "ray_planes=0: none of it runs, costs nothing"});
        p.features.push_back({"USER_CLIP", t.userClip, t.userClip ? "planes y >= clip_y_min, y <= clip_y_max"
                                                                 : "user_clip=0"});
        p.features.push_back({"SHADOW_MAPS_CUBE", t.cubes,
                              t.cubes ? "point lights / area-light VPLs: cube shadow maps"
                                      : "no point or area light: cube-map code compiled out (SHADOW_NO_CUBE)"});
        render::planCulledLights(scene, p);
        p.features.push_back({"PERMUTATION", true, permutationKey(t)});
        if (s.at("force_features") != 0.0) {
            Settings unforced = s;
            unforced["force_features"] = 0.0;
            const Terms t0 = terms(scene, unforced);
            for (FeaturePlan& f : p.features)
                if ((f.feature == "SPOT_FALLOFF" && t.spot != t0.spot) || (f.feature == "COOKIE" && t.cookie != t0.cookie) ||
                    (f.feature == "CLIP" && t.clip != t0.clip) || (f.feature == "SHADOW_MAPS_CUBE" && t.cubes != t0.cubes))
                    f.why = "forced on (force_features=1); the plan would leave it out for this scene";
            forcePlan(p, true, {});
        }
        return p;
    }

    FrameOutput run(const FrameInput& input) override {
        const scene::Scene& scene = *input.scene;
        const Settings& s = input.settings;
        FrameOutput out;
        out.plan = plan(scene, s);
        out.timing.clock = gl::StageClock::method();
        const int stop = input.stopAfterStage < 0 ? kComposeIndex : input.stopAfterStage;
        gl::StageClock clock;

        // ---- shadow maps ----
        mReuse.begin(input, out);
        if (mReuse.carries(kShadowMapsIndex)) {
            mReuse.carry(kShadowMapsIndex, out);
        } else {
            clock.begin();
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
            mView.buildShadows(scene, s, out.intermediates, "slices");
            out.timing.stages.push_back({mStages[kShadowMapsIndex].id, clock.endMilliseconds()});
            out.intermediates.push_back(render::textureIntermediate(kCookies, "Cookies", "spot cookie textures (sRGB bytes), one layer per cookie", "",
                                                            ViewKind::Color, 0.0f, 1.0f, mView.lights().cookies()));
            out.intermediates.push_back(render::textureIntermediate(
                kNoise, "Noise", "two tileable value-noise layers (r, g), generated, projected from the light", "",
                ViewKind::Color, 0.0f, 1.0f, mNoise));
            mReuse.ran(kShadowMapsIndex, out);
        }
        out.lastStageRun = kShadowMapsIndex;
        if (stop == kShadowMapsIndex) return out;

        // ---- camera view ----
        if (mReuse.carries(kSurfaceIndex)) {
            mReuse.carry(kSurfaceIndex, out);
        } else {
            clock.begin();
            mView.renderSurface(scene, input.width, input.height, out.intermediates, "slices");
            out.timing.stages.push_back({mStages[kSurfaceIndex].id, clock.endMilliseconds()});
            mReuse.ran(kSurfaceIndex, out);
        }
        out.lastStageRun = kSurfaceIndex;
        if (stop == kSurfaceIndex) return out;

        // ---- sampling planes ----
        clock.begin();
        const Terms t = terms(scene, s);
        allocateTargets(input.width, input.height, SlicesAccum(int(s.at("accum"))));
        const float zero[4] = {0, 0, 0, 0};
        glClearTexImage(mAccum.id(), 0, GL_RGBA, GL_FLOAT, zero);
        glClearTexImage(mPlane.id(), 0, GL_RGBA, GL_FLOAT, zero);
        mCounters.clearZero();
        mQueryCounts[0] = mQueryCounts[1] = 0.0;
        mPlanesUsed.clear();
        mPolygons.clear();
        mRayPlanes.reset();
        if (out.plan.stages[kPlanesIndex].runs) drawPlanes(scene, input, t);
        out.timing.stages.push_back({kStagePlanes, clock.endMilliseconds()});
        const int n = mPlanesUsed.empty() ? int(s.at("planes")) : mPlanesUsed.front();
        const int drawnLimit = int(substepLimit(input, kPlanesIndex));
        const int drawn = drawnLimit > 0 ? std::min(n, drawnLimit) : n;
        out.intermediates.push_back(render::textureIntermediate(
            kAccum, "Accumulation after " + std::to_string(drawn) + " of " + std::to_string(n) + " planes",
            t.mask ? "plane i added to channel i mod 4 (r, g, b, a), times the store scale"
                   : "sum of the planes drawn so far (back to front), times the store scale",
            "stored value", ViewKind::Color, 0.0f, 1.0f, mAccum));
        out.intermediates.push_back(render::textureIntermediate(
            kPlane, "Plane " + std::to_string(drawn), "the last plane drawn alone (every light), float",
            "stored value", ViewKind::Color, 0.0f, 0.05f, mPlane));
        out.intermediates.push_back(polygonIntermediate());
        if (s.at("mesh_view") != 0.0) {
            mMeshView.begin(scene, mView.gpuScene(), {s.at("mesh_yaw"), s.at("mesh_pitch"), s.at("mesh_zoom")},
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
                "", ViewKind::Color, 0.0f, 1.0f, mMeshView.texture());
            view.orbit = true;  // the window turns it by dragging
            view.picture = true;
            out.intermediates.push_back(std::move(view));
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
            chart.kind = ViewKind::Color;
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
        out.lastStageRun = kPlanesIndex;
        if (stop == kPlanesIndex) return out;

        // ---- resolve ----
        clock.begin();
        resolve(t);
        out.timing.stages.push_back({kStageResolve, clock.endMilliseconds()});
        out.intermediates.push_back(render::textureIntermediate(
            kAirlight, "L_air", "single-scattered light reaching the eye, decoded from the accumulation",
            "radiance", ViewKind::Color, 0.0f, 1.0f, mAirlight));
        out.airlight = render::readRgb(mAirlight);
        out.lastStageRun = kResolveIndex;
        if (stop == kResolveIndex) return out;

        // ---- compose ----
        clock.begin();
        out.final = mView.compose(scene, mAirlight, out.intermediates, "slices");
        out.timing.stages.push_back({mStages[kComposeIndex].id, clock.endMilliseconds()});
        out.lastStageRun = kComposeIndex;
        return out;
    }

private:
    static Terms terms(const scene::Scene& scene, const Settings& s) {
        Terms t;
        const bool hasSpot = render::hasLightOfType(scene, scene::LightType::Spot);
        const bool hasCookie = std::any_of(scene.lights.begin(), scene.lights.end(), [](const scene::Light& l) {
            return l.type == scene::LightType::Spot && l.cookie >= 0;
        });
        // force_features=1 compiles in what this scene would not need (to measure what leaving it out saves).
        const bool force = s.at("force_features") != 0.0;
        t.physical = s.at("weighting") != 0.0;
        t.spot = (hasSpot || force) && s.at("spot_falloff") != 0.0;
        t.cookie = (hasCookie || force) && s.at("cookie") != 0.0;
        t.shadow = s.at("shadow") != 0.0;
        t.pcf = s.at("shadow") == 2.0;
        t.noise = s.at("noise") != 0.0;
        t.mask = SlicesAccum(int(s.at("accum"))) == SlicesAccum::Rgba8Mask;
        t.blur = s.at("blur") != 0.0;
        // Only spot lights (and directional lights boxed by directional_box=1) have a frustum to clip to.
        const bool boxedDirectional = render::hasLightOfType(scene, scene::LightType::Directional) &&
                                      s.at("directional_box") != 0.0;
        t.clip = s.at("clip") != 0.0 && (hasSpot || boxedDirectional || force);
        t.userClip = s.at("user_clip") != 0.0;
        t.count = s.at("count_fragments") != 0.0;
        t.pick = s.at("ray_planes") != 0.0;
        t.cubes = render::hasLightOfType(scene, scene::LightType::Point) ||
                  render::hasLightOfType(scene, scene::LightType::Area) || force;
        return t;
    }

    // The defines of the plane shader, in a fixed order: also the cache key and what plan() reports.
    // pick: the picked pixel's recording draw (PICK_RAY, no fragment counting); the frame's draw is without.
    static gl::ShaderDefines planeDefines(const Terms& t, bool pick = false) {
        gl::ShaderDefines d;
        if (t.physical) d.push_back({"PHYSICAL", "1"});
        if (t.spot) d.push_back({"SPOT_FALLOFF", "1"});
        if (t.cookie) d.push_back({"COOKIE", "1"});
        else d.push_back({"LIGHTS_NO_COOKIE", "1"});
        if (t.shadow) d.push_back({"SHADOW", "1"});
        if (t.pcf) d.push_back({"PCF", "1"});
        if (t.noise) d.push_back({"NOISE", "1"});
        if (t.mask) d.push_back({"CHANNEL_MASK", "1"});
        if (t.count && !pick) d.push_back({"COUNT_OUTSIDE", "1"});
        if (t.clip) d.push_back({"CLIP", "1"});
        if (t.userClip) d.push_back({"USER_CLIP", "1"});
        if (pick) d.push_back({"PICK_RAY", "1"});
        // Cube maps serve point lights and area-light VPLs only.
        if (!t.cubes) d.push_back({"SHADOW_NO_CUBE", "1"});
        return d;
    }
    static std::string permutationKey(const Terms& t, bool pick = false) {
        std::string key;
        for (const auto& [name, value] : planeDefines(t, pick)) key += (key.empty() ? "" : ";") + name;
        return key;
    }

    void allocateTargets(int width, int height, SlicesAccum accum) {
        const GLenum format = accum == SlicesAccum::Rgba32f ? GL_RGBA32F
                              : accum == SlicesAccum::Rgba16f ? GL_RGBA16F
                                                              : GL_RGBA8;
        if (mAccum && mAccum.size().x == width && mAccum.size().y == height && mAccum.format() == format) return;
        mAccum = gl::Texture::create(
            {.target = GL_TEXTURE_2D, .format = format, .size = {width, height, 1}, .label = kAccum});
        mPlane = gl::Texture::create(
            {.target = GL_TEXTURE_2D, .format = GL_RGBA32F, .size = {width, height, 1}, .label = kPlane});
        mAirlight = gl::Texture::create(
            {.target = GL_TEXTURE_2D, .format = GL_RGBA32F, .size = {width, height, 1}, .label = kAirlight});
    }

    double storeScale(const Terms& t, const Settings& s) const {
        const SlicesAccum accum = SlicesAccum(int(s.at("accum")));
        if (accum == SlicesAccum::Rgba8) return 1.0 / s.at("accum_range");
        if (accum == SlicesAccum::Rgba8Mask) return 4.0 / s.at("accum_range");
        (void)t;
        return 1.0;
    }

    const gl::Program& planeProgram(const Terms& t, bool pick) {
        const std::string key = permutationKey(t, pick);
        auto it = mPlanePrograms.find(key);
        if (it == mPlanePrograms.end()) {
            it = mPlanePrograms
                     .emplace(key, gl::Program::compile({.stages = {"slices/plane.vert", "slices/plane.frag"},
                                                         .defines = planeDefines(t, pick),
                                                         .label = "slices.plane_program"}))
                     .first;
        }
        return it->second;
    }

    // The camera's view volume up to zfar as a clip matrix (eye-relative world -> clip), for planeRange.
    static glm::dmat4 cameraVolume(const scene::Camera& cam, int width, int height) {
        const glm::dmat4 view = glm::lookAt(glm::dvec3(0.0), cam.forward, cam.up);
        return glm::perspective(cam.yfov, scene::aspectOf(cam, width, height), cam.znear, cam.zfar) * view;
    }

    void drawPlanes(const scene::Scene& scene, const FrameInput& input, const Terms& t) {
        const Settings& s = input.settings;
        const scene::Camera& cam = scene.camera;
        const int n = int(s.at("planes"));
        const gl::Program& program = planeProgram(t, false);
        // The pick draw's program: the same shader with PICK_RAY; both get every uniform.
        const gl::Program* pick = t.pick ? &planeProgram(t, true) : nullptr;
        auto setBoth = [&](const char* name, auto value) {
            program.set(name, value);
            if (pick) pick->set(name, value);
        };
        mPlanesUsed.clear();
        mPolygons.clear();
        const CameraBasis basis{cam.forward, scene::cameraRight(cam), cam.up};

        program.use();
        setBoth("uViewProj", render::eyeRelativeViewProjection(cam, input.width, input.height));
        setBoth("uRight", glm::vec3(basis.right));
        setBoth("uUp", glm::vec3(basis.up));
        setBoth("uForward", glm::vec3(basis.forward));
        setBoth("uSize", glm::vec2(float(input.width), float(input.height)));
        setBoth("uTanHalf", float(std::tan(cam.yfov * 0.5)));
        setBoth("uAspect", float(scene::aspectOf(cam, input.width, input.height)));
        setBoth("uSigmaS", float(scene.medium.sigma_s));
        setBoth("uSigmaT", float(scene.medium.sigma_t()));
        setBoth("uG", float(scene.medium.g));
        mLastStoreScale = storeScale(t, s);
        setBoth("uStoreScale", float(mLastStoreScale));
        setBoth("uArtisticUnits", float(s.at("artistic_units")));
        setBoth("uAmbient", float(s.at("ambient") != 0.0 ? kPaperAmbient : 0.0));
        setBoth("uFalloff", int(s.at("falloff")));
        setBoth("uNoiseTiles", float(s.at("noise_tiles")));
        // Two layers scrolling in different directions (slowly: a few hundredths of a tile per second).
        const float time = float(s.at("time"));
        setBoth("uScroll", glm::vec4(0.031f * time, 0.017f * time, -0.023f * time, 0.029f * time));
        setBoth("uPlaneWeight", 1.0f);
        // User planes: world y >= clip_y_min and y <= clip_y_max, written in eye-relative space.
        const double eyeY = cam.position.y;
        setBoth("uUserPlane0", glm::vec4(0, 1, 0, float(eyeY - s.at("clip_y_min"))));
        setBoth("uUserPlane1", glm::vec4(0, -1, 0, float(s.at("clip_y_max") - eyeY)));

        mView.lights().bind();
        mView.shadows().bind();
        mView.surface().distance().bindUnit(render::hd::kFirstFreeTextureUnit);
        mNoise.bindUnit(render::hd::kFirstFreeTextureUnit + 1);
        mCounters.bindBase(GL_ATOMIC_COUNTER_BUFFER, 0);
        mVao.bind();

        glViewport(0, 0, input.width, input.height);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_CULL_FACE);
        // Additive blending: dst = dst + src (the paper's accumulation; saturates in RGBA8).
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(GL_ONE, GL_ONE);
        const int clipPlanes = (t.clip ? 6 : 0) + (t.userClip ? 2 : 0);
        for (int i = 0; i < 8; ++i)
            i < clipPlanes ? glEnable(GLenum(GL_CLIP_DISTANCE0 + i)) : glDisable(GLenum(GL_CLIP_DISTANCE0 + i));

        const auto& lights = mView.lights().lights();
        const bool boxedDirectional = s.at("directional_box") != 0.0;
        // Channel mask: one scalar per plane (mean of rgb); the colour ratio of the first light is put back
        // on resolve (exact for one light colour, the paper's monochrome assumption).
        mMaskColor = glm::vec3(1.0f);
        if (!lights.empty()) {
            const glm::dvec3 c = scene.lights[std::size_t(lights.front().info.w)].color;
            const double mean = (c.r + c.g + c.b) / 3.0;
            if (mean > 0.0) mMaskColor = glm::vec3(c / mean);
        }
        // Draw sets: each spot light (and, with directional_box, each directional light) gets N planes in
        // its own frustum's box, clipped to it. Every other light (point, area-light VPL, directional) lights
        // unbounded space: they share one set of N planes over the camera frustum up to zfar, unclipped
        // (a directional map's box only bounds where shadows are known; outside it V = 1).
        struct DrawSet {
            int light;  // index into lights, or -1: the unbounded lights together
            glm::dmat4 volume;
        };
        std::vector<DrawSet> sets;
        bool unbounded = false;
        for (std::size_t li = 0; li < lights.size(); ++li) {
            const int type = lights[li].info.x;
            if (type == render::hd::kLightSpot || (type == render::hd::kLightDirectional && boxedDirectional))
                sets.push_back({int(li), glm::dmat4(lights[li].shadowMatrix)});
            else
                unbounded = true;
        }
        if (unbounded) sets.push_back({-1, cameraVolume(cam, input.width, input.height)});
        setBoth("uLightCount", mView.lights().count());
        setBoth("uBoxedDirectional", boxedDirectional ? 1 : 0);
        // The picked pixel's records: at most N per draw set (distance scaling only lowers the count).
        mPickSets.clear();
        mPickPixel = pickedPixel(input);
        int pickBase = 0;
        if (t.pick) {
            const std::size_t need = std::max<std::size_t>(1, sets.size() * std::size_t(n)) * sizeof(PickRecord);
            if (!mPickRecords || mPickRecords.bytes() < need)
                mPickRecords = gl::Buffer::create({.bytes = need, .label = "slices.pick_records"});
            mPickRecords.clearZero();
            mPickRecords.bindBase(GL_SHADER_STORAGE_BUFFER, render::hd::kFirstFreeSsboBinding);
            pick->set("uPickPixel", glm::ivec2(mPickPixel.x, input.height - 1 - mPickPixel.y));
        }

        for (const DrawSet& set : sets) {
            const bool boxed = set.light >= 0;
            PlaneRange range = planeRange(set.volume, basis, cam.znear, cam.zfar, n);
            if (range.empty) continue;
            // Fewer planes far from the light volume (eye at the origin; distance to the view-space box).
            const glm::dvec3 lo(range.minXY, range.near), hi(range.maxXY, range.far);
            const double distance = glm::length(glm::max(glm::max(lo, -hi), glm::dvec3(0.0)));
            const int planes = scaledPlaneCount(n, distance, s.at("distance_scale"), kMinScaledPlanes);
            range = planeRange(set.volume, basis, cam.znear, cam.zfar, planes);
            const int drawnLimit = int(substepLimit(input, kPlanesIndex));
            const int drawn = drawnLimit > 0 ? std::min(planes, drawnLimit) : planes;
            mPlanesUsed.push_back(planes);
            for (auto& poly : planePolygons(range, basis, set.volume, drawn, t.clip && boxed))
                mPolygons.push_back(std::move(poly));
            setBoth("uClipLight", boxed ? 1 : 0);
            setBoth("uFractionOfMaxShells", float(double(planes) / kPaperMaxPlanes));
            setBoth("uLight", set.light);
            setBoth("uLightMatrix", glm::mat4(set.volume));
            setBoth("uBoxMinXY", glm::vec2(range.minXY));
            setBoth("uBoxMaxXY", glm::vec2(range.maxXY));
            setBoth("uDepthFar", float(range.far));
            setBoth("uSpacing", float(range.spacing));
            setBoth("uDrawNear", float(range.drawNear));
            if (t.pick) {
                mPickSets.push_back({boxed ? lights[std::size_t(set.light)].info.w : -1, pickBase, drawn,
                                     t.clip && boxed, float(range.far), float(range.spacing), float(range.drawNear),
                                     glm::vec2(range.minXY), glm::vec2(range.maxXY), glm::mat4(set.volume)});
                pick->set("uPickBase", pickBase);
                pickBase += drawn;
            }
            // Back to front: plane 0 is the farthest, so the first k planes are the k farthest.
            mFramebuffer.attachColor(0, mAccum);
            mFramebuffer.checkComplete();
            mFramebuffer.bind();
            glDrawArrays(GL_TRIANGLES, 0, 6 * drawn);
            // The last plane alone, for stepping and the per-plane readback.
            mFramebuffer.attachColor(0, mPlane);
            mFramebuffer.bind();
            glDrawArrays(GL_TRIANGLES, 6 * (drawn - 1), 6);
            if (pick) {
                // The picked pixel alone with colour writes off: the same planes through the same shader
                // (PICK_RAY), which records what each plane computes there. The frame pays one pixel.
                const glm::ivec2 glPixel(mPickPixel.x, input.height - 1 - mPickPixel.y);
                pick->use();
                glEnable(GL_SCISSOR_TEST);
                glScissor(glPixel.x, glPixel.y, 1, 1);
                glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
                glDrawArrays(GL_TRIANGLES, 0, 6 * drawn);
                glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
                glDisable(GL_SCISSOR_TEST);
                program.use();
            }
            if (t.count) countFragments(program, drawn);
        }
        for (int i = 0; i < 8; ++i) glDisable(GLenum(GL_CLIP_DISTANCE0 + i));
        if (t.pick) replayPick(input, basis, t);
        glDisable(GL_BLEND);
        glMemoryBarrier(GL_ATOMIC_COUNTER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
        gl::Framebuffer::bindDefault();
    }

    glm::ivec2 pickedPixel(const FrameInput& input) const {
        int x = int(input.settings.at("pick_x")), y = int(input.settings.at("pick_y"));
        if (x < 0) x = input.width / 2;
        if (y < 0) y = input.height / 2;
        return {std::min(x, input.width - 1), std::min(y, input.height - 1)};
    }

    // The picked pixel's blend replayed (pick_replay.*): every record in drawing order (draw sets in turn)
    // over a target in the accumulation's format, so texel k holds the pixel's accumulation after records
    // 0..k as this blend quantises it. Then the records and the replay are read back into mRayPlanes.
    // Runs with the plane pass's blend state (dst + src).
    void replayPick(const FrameInput& input, const CameraBasis& basis, const Terms& t) {
        mRayPlanes.reset();
        if (mPickSets.empty()) return;
        // The plane pass's SSBO writes, visible to the replay's reads.
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        const int count = mPickSets.back().base + mPickSets.back().drawn;
        if (count <= 0) return;
        const int columns = std::min(count, kReplayColumns);
        const int rows = (count + columns - 1) / columns;
        const GLenum format = GLenum(mAccum.format());
        if (!mReplay || mReplay.size().x != columns || mReplay.size().y != rows || GLenum(mReplay.format()) != format)
            mReplay = gl::Texture::create(
                {.target = GL_TEXTURE_2D, .format = format, .size = {columns, rows, 1}, .label = "slices.pick_replay"});
        const float zero[4] = {0, 0, 0, 0};
        glClearTexImage(mReplay.id(), 0, GL_RGBA, GL_FLOAT, zero);
        if (!mReplayProgram)
            mReplayProgram = gl::Program::compile(
                {.stages = {"slices/pick_replay.vert", "slices/pick_replay.frag"}, .label = "slices.pick_replay"});
        const gl::Program& program = mReplayProgram;
        const scene::Camera& cam = input.scene->camera;
        program.use();
        program.set("uRows", rows);
        program.set("uColumns", columns);
        program.set("uSeedRow", -1);
        program.set("uPickPixel", glm::ivec2(mPickPixel.x, input.height - 1 - mPickPixel.y));
        program.set("uSize", glm::vec2(float(input.width), float(input.height)));
        program.set("uTanHalf", float(std::tan(cam.yfov * 0.5)));
        program.set("uAspect", float(scene::aspectOf(cam, input.width, input.height)));
        program.set("uForward", glm::vec3(basis.forward));
        program.set("uRight", glm::vec3(basis.right));
        program.set("uUp", glm::vec3(basis.up));
        program.set("uUserClip", t.userClip ? 1 : 0);
        const double eyeY = cam.position.y;
        program.set("uUserPlane0", glm::vec4(0, 1, 0, float(eyeY - input.settings.at("clip_y_min"))));
        program.set("uUserPlane1", glm::vec4(0, -1, 0, float(input.settings.at("clip_y_max") - eyeY)));
        mView.surface().distance().bindUnit(0);
        mReplay.bindUnit(1);
        mFramebuffer.attachColor(0, mReplay);
        mFramebuffer.checkComplete();
        mFramebuffer.bind();
        glViewport(0, 0, columns, rows);
        mVao.bind();
        for (int row = 0; row < rows; ++row) {
            const int k0 = row * columns, k1 = std::min(count, k0 + columns);
            if (row > 0) {
                // The row starts from the accumulation at the end of the row before.
                glTextureBarrier();
                program.set("uSeedRow", row);
                glDrawArrays(GL_TRIANGLES, 0, 6);
                program.set("uSeedRow", -1);
            }
            for (const PickSet& ps : mPickSets) {
                const int j0 = std::max(k0, ps.base) - ps.base, j1 = std::min(k1, ps.base + ps.drawn) - ps.base;
                if (j0 >= j1) continue;
                program.set("uPickBase", ps.base);
                program.set("uDepthFar", ps.depthFar);
                program.set("uSpacing", ps.spacing);
                program.set("uDrawNear", ps.drawNear);
                program.set("uClipLight", ps.clipLight ? 1 : 0);
                program.set("uLightMatrix", ps.volume);
                program.set("uBoxMinXY", ps.boxMin);
                program.set("uBoxMaxXY", ps.boxMax);
                glDrawArrays(GL_TRIANGLES, 6 * j0, 6 * (j1 - j0));
            }
        }
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
        std::vector<PickRecord> records(static_cast<std::size_t>(count));
        mPickRecords.download(0, records.size() * sizeof(PickRecord), records.data());
        const Image replay = gl::readTexture(mReplay);  // row 0 at the top: GL row height - 1
        mRayPlanes = rayPlaneTable(records, replay, t);
    }

    // slices.ray_planes as a table: one row per record, RayPlaneColumn columns of four channels.
    std::shared_ptr<Image> rayPlaneTable(const std::vector<PickRecord>& records, const Image& replay,
                                         const Terms& t) const {
        using namespace slices;
        auto table = std::make_shared<Image>(int(kRayPlaneColumns), int(std::max<std::size_t>(records.size(), 1)), 4);
        const float radianceScale =
            float(1.0 / mLastStoreScale) * (t.mask ? (mMaskColor.r + mMaskColor.g + mMaskColor.b) : 1.0f);
        glm::vec4 before(0.0f);  // the accumulation runs on from one draw set into the next
        for (std::size_t r = 0; r < mPickSets.size(); ++r) {
            const PickSet& ps = mPickSets[r];
            for (int i = 0; i < ps.drawn; ++i) {
                const int row = ps.base + i;
                const PickRecord& rec = records[std::size_t(row)];
                glm::vec4 after(0.0f);
                for (int c = 0; c < 4; ++c)
                    after[c] = replay.at(row % replay.width, replay.height - 1 - row / replay.width, c);
                const glm::vec4 added = after - before;
                before = after;
                auto put = [&](int column, glm::vec4 v) {
                    for (int c = 0; c < 4; ++c) table->at(column, row, c) = v[c];
                };
                put(kColWhere, rec.where);
                put(kColTest, rec.test);
                put(kColValue, rec.value);
                put(kColAdded, added);
                put(kColAfter, after);
                // L_air added and the unquantised value, decoded as resolve.frag decodes (sum of rgb).
                const float addedSum = t.mask ? added.r + added.g + added.b + added.a : added.r + added.g + added.b;
                const float valueSum =
                    t.mask ? rec.value.r + rec.value.g + rec.value.b + rec.value.a : rec.value.r + rec.value.g + rec.value.b;
                put(kColSet, {float(ps.light), float(r), addedSum * radianceScale, valueSum * radianceScale});
            }
        }
        return table;
    }

    // The drawn planes as polygons (rows: planes back to front, light after light; columns: vertices;
    // rgb = eye-relative world xyz; NaN pads unused vertices), for viewing the slab stack from outside.
    Intermediate polygonIntermediate() const {
        std::size_t width = 1;
        for (const auto& p : mPolygons) width = std::max(width, p.size());
        auto img = std::make_shared<Image>(int(width), int(std::max<std::size_t>(mPolygons.size(), 1)), 3);
        std::fill(img->pixels.begin(), img->pixels.end(), std::nanf(""));
        for (std::size_t row = 0; row < mPolygons.size(); ++row)
            for (std::size_t v = 0; v < mPolygons[row].size(); ++v)
                for (int c = 0; c < 3; ++c) img->at(int(v), int(row), c) = float(mPolygons[row][v][c]);
        Intermediate i;
        i.id = kPlaneMesh, i.label = "Sampling planes (mesh)";
        i.note = "the drawn planes clipped to the light frustum (when clip=1): rows planes, columns vertices, "
                 "xyz eye-relative world";
        i.units = "scene units";
        i.kind = ViewKind::Mesh;
        i.image = img;
        i.extent = {img->width, img->height, 1};
        return i;
    }

    // Occlusion queries over the same planes with colour writes off: all fragments, then only those the
    // shader finds outside the light frustum (it discards the rest). Adds to mQueryCounts.
    void countFragments(const gl::Program& program, int drawn) {
        GLuint query = 0;
        glCreateQueries(GL_SAMPLES_PASSED, 1, &query);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        for (int pass = 1; pass <= 2; ++pass) {
            program.set("uCountPass", pass);
            glBeginQuery(GL_SAMPLES_PASSED, query);
            glDrawArrays(GL_TRIANGLES, 0, 6 * drawn);
            glEndQuery(GL_SAMPLES_PASSED);
            GLuint samples = 0;
            glGetQueryObjectuiv(query, GL_QUERY_RESULT, &samples);
            mQueryCounts[pass == 1 ? 1 : 0] += double(samples);
        }
        program.set("uCountPass", 0);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glDeleteQueries(1, &query);
    }

    void resolve(const Terms& t) {
        gl::ShaderDefines defines;
        if (t.mask) defines.push_back({"CHANNEL_MASK", "1"});
        if (t.blur) defines.push_back({"BLUR", "1"});
        std::string key = std::string(t.mask ? "m" : "") + (t.blur ? "b" : "");
        auto it = mResolvePrograms.find(key);
        if (it == mResolvePrograms.end()) {
            it = mResolvePrograms
                     .emplace(key, gl::Program::compile({.stages = {"render/fullscreen.vert", "slices/resolve.frag"},
                                                         .defines = defines,
                                                         .label = "slices.resolve_program"}))
                     .first;
        }
        const gl::Program& program = it->second;
        program.use();
        program.set("uInvStoreScale", float(1.0 / mLastStoreScale));
        program.set("uMaskColor", mMaskColor);
        mFramebuffer.attachColor(0, mAirlight);
        mFramebuffer.checkComplete();
        mFramebuffer.bind();
        glViewport(0, 0, mAirlight.size().x, mAirlight.size().y);
        glDisable(GL_BLEND);
        glDisable(GL_DEPTH_TEST);
        mAccum.bindUnit(0);
        mTriangle->draw();
        gl::Framebuffer::bindDefault();
    }

    std::vector<ParamInfo> mParams;
    std::vector<StageInfo> mStages;
    render::SceneViewPasses mView;
    StageReuse mReuse;  // stages carried over from the last run (FrameInput::resumeAtStage)
    std::unique_ptr<render::FullscreenTriangle> mTriangle;
    std::map<std::string, gl::Program> mPlanePrograms, mResolvePrograms;
    gl::VertexArray mVao;
    gl::Framebuffer mFramebuffer;
    gl::Buffer mCounters;
    gl::Texture mNoise, mAccum, mPlane, mAirlight;
    double mLastStoreScale = 1.0;
    std::vector<int> mPlanesUsed;                         // per drawn light, after distance scaling
    render::MeshView mMeshView;
    std::vector<std::vector<glm::dvec3>> mPolygons;       // drawn planes, clipped (eye-relative world)
    double mQueryCounts[2] = {0.0, 0.0};  // occlusion queries: outside the frustum, all
    glm::vec3 mMaskColor{1.0f};
    // The picked pixel's planes (slices.ray_planes).
    gl::Buffer mPickRecords;
    gl::Texture mReplay;
    gl::Program mReplayProgram;
    std::vector<PickSet> mPickSets;
    glm::ivec2 mPickPixel{0};
    std::shared_ptr<Image> mRayPlanes;
};

}  // namespace

std::unique_ptr<Technique> makeSlicesTechnique() { return std::make_unique<SlicesTechnique>(); }

}  // namespace viz
