#include "render/scene_view.h"

#include <algorithm>

#include "render/intermediates.h"

namespace viz::render {

namespace {
// VPL cube maps are many (area_samples^2 of them): cap their size to keep memory in check.
constexpr int kMaxVplShadowSize = 256;
}  // namespace

void SceneViewPasses::createPasses() {
    if (mShadows) return;
    mShadows = std::make_unique<ShadowMaps>();
    mSurface = std::make_unique<SurfacePass>();
    mComposer = std::make_unique<Composer>();
}

void SceneViewPasses::buildShadows(const scene::Scene& scene, int shadowMapSize, int areaSamples,
                                   std::vector<Intermediate>& out, const std::string& prefix) {
    createPasses();
    // Geometry is uploaded once per scene; a camera move (the window) reuses it.
    const std::size_t fingerprint = geometryFingerprint(scene);
    if (mSceneSource != &scene || mSceneFingerprint != fingerprint || !mGpuScene) {
        mGpuScene = std::make_unique<GpuScene>(scene);
        mSceneSource = &scene;
        mSceneFingerprint = fingerprint;
    }
    mLights = std::make_unique<GpuLights>(scene, scene.camera.position, areaSamples);
    mShadows->build(*mGpuScene, *mLights, shadowMapSize, std::min(shadowMapSize, kMaxVplShadowSize));
    mShadows->publish(out, prefix);
}

void SceneViewPasses::renderSurface(const scene::Scene& scene, int width, int height, std::vector<Intermediate>& out,
                                    const std::string& prefix) {
    mSurface->run(*mGpuScene, *mLights, *mShadows, scene, width, height);
    out.push_back(textureIntermediate(prefix + ".distance", "Distance d",
                                      "Euclidean distance to the first surface along the pixel ray (zfar: sky)",
                                      "scene units", ViewKind::Scalar, 0.0f, float(scene.camera.zfar),
                                      mSurface->distance()));
    out.push_back(textureIntermediate(prefix + ".surface", "Surface radiance",
                                      "emission + Lambert with shadow maps, before the medium's attenuation",
                                      "radiance", ViewKind::Color, 0.0f, 1.0f, mSurface->surfaceRadiance()));
}

Image SceneViewPasses::compose(const scene::Scene& scene, const gl::Texture& airlight,
                              std::vector<Intermediate>& out, const std::string& prefix) {
    const glm::ivec3 size = airlight.size();
    if (!mFinal || mFinal.size() != size)
        mFinal = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_RGBA32F, .size = size, .label = prefix + ".final"});
    mComposer->run(mSurface->surfaceRadiance(), mSurface->distance(), airlight, float(scene.medium.sigma_t()), mFinal);
    out.push_back(textureIntermediate(prefix + ".final", "Final", "surface * exp(-sigma_t d) + L_air", "radiance",
                                      ViewKind::Color, 0.0f, 1.0f, mFinal));
    return readRgb(mFinal);
}

}  // namespace viz::render
