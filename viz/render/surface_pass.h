// The camera view of the scene: per-pixel Euclidean distance from the eye (clamped to camera.zfar; zfar
// for sky pixels and for surfaces beyond zfar, which count as misses), the unattenuated surface
// radiance (emission + Lambert with shadow maps, the definition's surface term) and hardware depth.
// Rendered GL-style (row 0 at the bottom); gl::readTexture flips to row 0 at the top.
#pragma once

#include "gl/framebuffer.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "render/gpu_lights.h"
#include "render/gpu_scene.h"
#include "render/medium_block.h"
#include "render/shadow_maps.h"
#include "scene/scene.h"

namespace viz::render {

class SurfacePass {
public:
    SurfacePass();

    // Leaves the lights, materials and shadow maps bound (the caller may rely on nothing else).
    void run(const GpuScene& gpuScene, const GpuLights& lights, const ShadowMaps& shadows,
             const scene::Scene& scene, int width, int height);

    const gl::Texture& distance() const { return mDistance; }         // R32F, scene units
    const gl::Texture& surfaceRadiance() const { return mRadiance; }  // RGBA32F, a = 1 on geometry
    const gl::Texture& depth() const { return mDepth; }               // DEPTH32F
    int width() const { return mWidth; }
    int height() const { return mHeight; }

private:
    gl::Program mProgram, mDepthProgram;  // shading; the depth prepass
    MediumBlock mMedium;
    gl::Texture mDistance, mRadiance, mDepth;
    gl::Framebuffer mFramebuffer;
    int mWidth = 0, mHeight = 0;
};

}  // namespace viz::render
