// The passes every GPU technique starts and ends with: the scene on the GPU (uploaded once per scene and
// reused when only the camera moves), its lights, their shadow maps, the camera view (distance d and the
// surface radiance) and the final composite. A technique owns one and calls the stages it needs.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "debug/stage_runner.h"
#include "debug/technique.h"
#include "gl/texture.h"
#include "render/compose.h"
#include "render/gpu_lights.h"
#include "render/gpu_scene.h"
#include "render/shadow_maps.h"
#include "render/surface_pass.h"
#include "scene/scene.h"

namespace viz::render {

// VPL cube maps are many (area_samples^2 of them): their faces are at most this many texels per side.
inline constexpr int kMaxVplShadowSize = 256;

class SceneViewPasses {
public:
    // ---- declarations, so that a technique lists these stages and parameters exactly as they run ----
    // `shadow_map` (texels per side, shared by every shadow-map technique), `area_samples` and `vpl_kernel`.
    static std::vector<ParamInfo> params();
    // The `vpl_kernel` of settings (the cell when they do not set it), and what it makes an area light's
    // VPL, for a plan's reason: "each its cell of the emitter (vpl_kernel=cell)" or "each a point
    // (vpl_kernel=point)".
    static VplKernel vplKernel(const Settings& settings);
    static std::string vplKernelText(const Settings& settings);
    // A quality sweep over `area_samples` (Technique::areaLightSweep), labelled "area_samples=N": 8, 12
    // and 16 per axis (8 and 16 when quick), those above `largest` left out. Both ends: a report
    // interpolates between neighbouring points of a front, and 16 alone left a technique whose sweep
    // spends samples at its accurate end (raymarch's N=1024) with a 5 % time between 8.3 % at 3.6 s and
    // 1.6 % at 5.2 s. tv-room, raymarch against the reference at 160x120: 8.4 % at the default 4, 3.9 % at
    // 8, 1.5 % at 16, each VPL count costing about its square (5 s at 16 against 0.3 s; 64 s at 640x480).
    // `march`, the knob that sets how finely the technique integrates each VPL's ray: each VPL count also
    // at `march` = `marchValue` ("area_samples=8 samples=16"), since the front crosses two knobs there: on
    // tv-room raymarch at 8^2 VPLs reaches 4.3 % with N=16 in 0.44 s against 3.9 % with the default N=64 in
    // 1.15 s, and a front holding only the latter put its 5 % time between N=256 on 4^2 VPLs and 8^2 at
    // N=64, 1.18 s; slices' default 128 planes hold it at 6.1 % on 8^2 VPLs, 256 planes reach 4.4 %.
    static std::vector<QualitySetting> areaSampleSweep(bool quick, int largest = 16, const std::string& march = "",
                                                       int marchValue = 0);
    // prefix.shadow_maps, publishing prefix.shadow_map and `extraIntermediates`.
    static StageInfo shadowStage(const std::string& prefix, const std::vector<std::string>& extraIntermediates = {});
    // prefix.surface, publishing prefix.distance and prefix.surface.
    static StageInfo surfaceStage(const std::string& prefix);
    // prefix.compose, publishing prefix.final.
    static StageInfo composeStage(const std::string& prefix);

    // buildShadows with the `shadow_map`, `area_samples` and `vpl_kernel` of completed settings.
    void buildShadows(const scene::Scene& scene, const Settings& settings, std::vector<Intermediate>& out,
                      const std::string& prefix);
    // Uploads the geometry when the scene changed, lays out the lights (area lights as areaSamples^2
    // VPLs with the given kernel, gpu_lights.h), renders every shadow map and publishes
    // them as prefix.shadow_map[.N].
    void buildShadows(const scene::Scene& scene, int shadowMapSize, int areaSamples,
                      std::vector<Intermediate>& out, const std::string& prefix, VplKernel kernel = VplKernel::Cell);
    // The camera view; publishes prefix.distance and prefix.surface.
    void renderSurface(const scene::Scene& scene, int width, int height, std::vector<Intermediate>& out,
                       const std::string& prefix);
    // final = surface radiance * exp(-sigma_t d) + airlight (same size as airlight); publishes
    // prefix.final. It reads nothing back, so that the compose stage's clock times the GPU's work alone:
    // the debugger's read-back (readFinal) is not a cost a real-time renderer pays.
    void compose(const scene::Scene& scene, const gl::Texture& airlight, std::vector<Intermediate>& out,
                 const std::string& prefix);
    // The last compose's final image read back as RGB.
    Image readFinal() const;

    // The two stages every GPU technique starts with, at stage indices 0 (shadow maps, settings
    // `shadow_map` and `area_samples`) and 1 (camera view), run by the technique's stage runner (timed,
    // or carried over from the last run). `publishShadows`, when given, publishes what else the
    // technique shows with the shadow maps (slices: its cookies and noise). Returns false when the run
    // stops after one of them.
    bool runSharedStages(StageRunner& stages, const FrameInput& input, const std::string& prefix, FrameOutput& out,
                         const std::function<void()>& publishShadows = {});
    // The compose stage every GPU technique ends with, at stage index `stage`: compose (timed) and the
    // final image read back into out.final (not timed; not at all for a caller that reads no CPU images,
    // FrameInput::readBack).
    void runCompose(StageRunner& stages, int stage, const FrameInput& input, const gl::Texture& airlight,
                    FrameOutput& out, const std::string& prefix);

    // ---- linked cursors (the window's marks for a hovered frame pixel; render/shadow_map_markers.h) ----
    // The eye ray of frame pixel `pixel` (row 0 at the top) of the last run: unit direction w (world axes;
    // the eye is the origin of eye-relative space) and its end, the surface distance d when the camera view
    // ran after the last buildShadows, else the camera's zfar. False outside the frame, before a run, and
    // when the frame size is not known (buildShadows called alone, without runSharedStages).
    bool pixelRay(glm::ivec2 pixel, glm::dvec3& w, double& tEnd) const;
    // The marks of `pixel` in `id` when `id` is one of the maps published as prefix.shadow_map[.N] by the
    // last buildShadows: the eye ray's projection and its lit/shadow changes by the map's own test. Empty
    // for other ids and pixels outside the frame.
    std::vector<ViewMarker> shadowMapMarkers(glm::ivec2 pixel, const std::string& id, const std::string& prefix) const;

    const GpuScene& gpuScene() const { return *mGpuScene; }
    const GpuLights& lights() const { return *mLights; }
    const ShadowMaps& shadows() const { return *mShadows; }
    const SurfacePass& surface() const { return *mSurface; }

private:
    void createPasses();

    const scene::Scene* mSceneSource = nullptr;
    std::uint64_t mSceneFingerprint = 0;
    std::unique_ptr<GpuScene> mGpuScene;
    std::unique_ptr<GpuLights> mLights;
    // Created at first use: their programs need a current GL context, listing a technique does not.
    std::unique_ptr<ShadowMaps> mShadows;
    std::unique_ptr<SurfacePass> mSurface;
    std::unique_ptr<Composer> mComposer;
    gl::Texture mFinal;
    // What pixelRay needs: the camera of the last buildShadows, the frame size, whether the camera view
    // (the distance d) belongs to it.
    scene::Camera mCamera{};
    glm::ivec2 mFrameSize{0};
    bool mSurfaceCurrent = false;
};

}  // namespace viz::render
