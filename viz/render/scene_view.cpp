#include "render/scene_view.h"

#include <algorithm>
#include <cmath>

#include "render/intermediates.h"
#include "render/shadow_map_markers.h"
#include "render/vpl_cells_view.h"
#include "scene/camera.h"
#include "scene/scene_source.h"

namespace viz::render {

std::vector<ParamInfo> SceneViewPasses::params() {
    return {
        {"shadow_map", "shadow-map size in texels per side (2D maps and point-light cube faces)", 1024, 16, 8192, true},
        {"area_samples", "virtual point lights per axis of each area light (the centres of equal cells)", 4, 1, 16, true},
        {"vpl_kernel", "what an area light's VPL stands for: point (L_e dA cos / r^2, which peaks next to the "
                       "emitter) or cell (its cell of the emitter: near it the air and the surfaces see the "
                       "cell's solid angle)", 1, 0, 1, true, {"point", "cell"}},
    };
}

VplKernel SceneViewPasses::vplKernel(const Settings& settings) {
    return settingOr(settings, "vpl_kernel", 1.0) != 0.0 ? VplKernel::Cell : VplKernel::Point;
}

std::string SceneViewPasses::vplKernelText(const Settings& settings) {
    return vplKernel(settings) == VplKernel::Cell ? "each its cell of the emitter (vpl_kernel=cell)"
                                                  : "each a point (vpl_kernel=point)";
}

std::vector<QualitySetting> SceneViewPasses::areaSampleSweep(bool quick, int largest, const std::string& march,
                                                             int marchValue) {
    std::vector<QualitySetting> sweep;
    for (int n : quick ? std::vector<int>{8, 16} : std::vector<int>{8, 12, 16}) {
        if (n > largest) continue;
        const std::string label = "area_samples=" + std::to_string(n);
        sweep.push_back({label, {{"area_samples", double(n)}}});
        if (!march.empty())
            sweep.push_back({label + " " + march + "=" + std::to_string(marchValue),
                             {{"area_samples", double(n)}, {march, double(marchValue)}}});
    }
    return sweep;
}

StageInfo SceneViewPasses::shadowStage(const std::string& prefix, const std::vector<std::string>& extraIntermediates) {
    StageInfo stage{prefix + ".shadow_maps", "Shadow maps", "render every light's shadow map (linear distance)",
                    {"shadow_map", "area_samples", "vpl_kernel"}, {prefix + ".shadow_map", prefix + ".vpl_cells"}, 1};
    stage.keepsOutputs = true;  // the instance's shadow maps
    stage.intermediates.insert(stage.intermediates.end(), extraIntermediates.begin(), extraIntermediates.end());
    return stage;
}

StageInfo SceneViewPasses::surfaceStage(const std::string& prefix) {
    StageInfo stage{prefix + ".surface", "Camera view",
                    "distance d to the first surface and the unattenuated surface radiance", {},
                    {prefix + ".distance", prefix + ".surface"}, 1};
    stage.keepsOutputs = true;  // the instance's surface targets
    return stage;
}

StageInfo SceneViewPasses::composeStage(const std::string& prefix) {
    return {prefix + ".compose", "Compose", "final = surface * exp(-sigma_t d) + L_air", {}, {prefix + ".final"}, 1};
}

void SceneViewPasses::buildShadows(const scene::Scene& scene, const Settings& settings, std::vector<Intermediate>& out,
                                   const std::string& prefix) {
    buildShadows(scene, int(settings.at("shadow_map")), int(settings.at("area_samples")), out, prefix,
                 vplKernel(settings));
}

void SceneViewPasses::createPasses() {
    if (mShadows) return;
    mShadows = std::make_unique<ShadowMaps>();
    mSurface = std::make_unique<SurfacePass>();
    mComposer = std::make_unique<Composer>();
}

void SceneViewPasses::buildShadows(const scene::Scene& scene, int shadowMapSize, int areaSamples,
                                   std::vector<Intermediate>& out, const std::string& prefix, VplKernel kernel) {
    createPasses();
    // Geometry is uploaded once per scene; a camera move (the window) reuses it. The key is the content
    // hash of meshes, materials and textures, not the scene's address or counts: an edited or rescaled
    // scene at the same address kept its stale upload. A stamped scene has it without hashing.
    const std::uint64_t fingerprint = scene::geometryKeyOf(scene);
    if (mSceneSource != &scene || mSceneFingerprint != fingerprint || !mGpuScene) {
        mGpuScene = std::make_unique<GpuScene>(scene);
        mSceneSource = &scene;
        mSceneFingerprint = fingerprint;
    }
    mLights = std::make_unique<GpuLights>(scene, scene.camera.position, areaSamples, kernel);
    mCamera = scene.camera;
    mSurfaceCurrent = false;
    mFrameSize = glm::ivec2(0);  // known again from runSharedStages or renderSurface
    mShadows->build(*mGpuScene, *mLights, shadowMapSize, std::min(shadowMapSize, kMaxVplShadowSize));
    mShadows->publish(out, prefix);
    for (Intermediate& view : vplCellsViews(scene, *mLights, prefix)) out.push_back(std::move(view));
}

void SceneViewPasses::renderSurface(const scene::Scene& scene, int width, int height, std::vector<Intermediate>& out,
                                    const std::string& prefix) {
    mSurface->run(*mGpuScene, *mLights, *mShadows, scene, width, height);
    mFrameSize = {width, height};
    mSurfaceCurrent = true;
    out.push_back(textureIntermediate(prefix + ".distance", "Distance d",
                                      "Euclidean distance to the first surface along the pixel ray (zfar: sky)",
                                      "scene units", ViewKind::Depth, 0.0f, float(scene.camera.zfar),
                                      mSurface->distance()));
    out.push_back(textureIntermediate(prefix + ".surface", "Surface radiance",
                                      "emission + Lambert with shadow maps, before the medium's attenuation",
                                      "radiance", ViewKind::Colour, 0.0f, 1.0f, mSurface->surfaceRadiance()));
}

void SceneViewPasses::compose(const scene::Scene& scene, const gl::Texture& airlight,
                              std::vector<Intermediate>& out, const std::string& prefix) {
    const glm::ivec3 size = airlight.size();
    if (!mFinal || mFinal.size() != size)
        mFinal = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_RGBA32F, .size = size, .label = prefix + ".final"});
    mComposer->run(mSurface->surfaceRadiance(), mSurface->distance(), airlight, scene.medium, mFinal);
    out.push_back(textureIntermediate(prefix + ".final", "Final", "surface * exp(-sigma_t d) + L_air", "radiance",
                                      ViewKind::Colour, 0.0f, 1.0f, mFinal));
}

Image SceneViewPasses::readFinal() const { return readRgb(mFinal); }

bool SceneViewPasses::runSharedStages(StageRunner& stages, const FrameInput& input, const std::string& prefix,
                                      FrameOutput& out, const std::function<void()>& publishShadows) {
    // The scene upload is counted with the shadow maps: it is part of the technique's cost.
    const bool more = stages.run(
        0, [&] { buildShadows(*input.scene, input.settings, out.intermediates, prefix); },
        [&] {
            if (publishShadows) publishShadows();
        });
    mFrameSize = {input.width, input.height};
    return more &&
           stages.run(1, [&] { renderSurface(*input.scene, input.width, input.height, out.intermediates, prefix); });
}

void SceneViewPasses::runCompose(StageRunner& stages, int stage, const FrameInput& input,
                                 const gl::Texture& airlight, FrameOutput& out, const std::string& prefix) {
    stages.run(stage, [&] { compose(*input.scene, airlight, out.intermediates, prefix); },
               [&] {
                   if (input.readBack) out.final = readFinal();
               });
}

bool SceneViewPasses::pixelRay(glm::ivec2 pixel, glm::dvec3& w, double& tEnd) const {
    if (!mLights || pixel.x < 0 || pixel.y < 0 || pixel.x >= mFrameSize.x || pixel.y >= mFrameSize.y) return false;
    w = scene::pixelRay(mCamera, mFrameSize.x, mFrameSize.y, pixel.x, pixel.y);
    tEnd = mCamera.zfar;
    if (mSurfaceCurrent && mSurface && mSurface->distance() && mSurface->width() == mFrameSize.x &&
        mSurface->height() == mFrameSize.y) {
        const gl::Texture& distance = mSurface->distance();
        float d = 0.0f;
        // GL row 0 is the bottom of the frame.
        glGetTextureSubImage(distance.id(), 0, pixel.x, mFrameSize.y - 1 - pixel.y, 0, 1, 1, 1, GL_RED, GL_FLOAT,
                             sizeof d, &d);
        if (std::isfinite(d) && d > 0.0f) tEnd = std::min(double(d), tEnd);
    }
    return true;
}

std::vector<ViewMarker> SceneViewPasses::shadowMapMarkers(glm::ivec2 pixel, const std::string& id,
                                                          const std::string& prefix) const {
    const int index = shadowMapIndexOf(id, prefix);
    if (index < 0 || !mLights || !mShadows || index >= mLights->count()) return {};
    const GpuLightCpu& light = mLights->lights()[std::size_t(index)];
    glm::dvec3 w;
    double tEnd = 0.0;
    if (light.info.z < 0 || !pixelRay(pixel, w, tEnd)) return {};
    return render::shadowMapMarkers(*mShadows, light, w, tEnd);
}

}  // namespace viz::render
