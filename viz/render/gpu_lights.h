// The lights of a scene on the GPU: an std430 array of GpuLight (shaders/common/host_device.glsl) at
// kBindingLights and the spot cookies in one GL_TEXTURE_2D_ARRAY (GL_RGBA8 holding sRGB bytes, decoded in the
// shader: see gpu_scene.h) at kUnitCookies.
// Area lights become areaSamples x areaSamples virtual point lights (VPLs) at the centres of equal cells
// of the rectangle, each with weight L_e * dA (the cell's mean L_e) and its cell or a cosine emission lobe. Positions are eye-relative
// (computed in double). Shadow layers and matrices are assigned here too, so ShadowMaps only renders.
#pragma once

#include <map>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "gl/buffer.h"
#include "gl/texture.h"
#include "render/host_device.h"
#include "scene/scene.h"

namespace viz::render {


// How many shadow maps of each kind the lights use (layers of ShadowMaps' textures).
struct ShadowLayout {
    int maps2D = 0;     // spot and directional, one layer each
    int cubes = 0;      // point lights, one cube each
    int vplCubes = 0;   // VPLs, one cube each
};

// The lights as the GPU sees them, worked out on the CPU (no GL): what GpuLights uploads, and what a plan
// may look at before any GL object exists (minmax's integrand=auto sets up each light's epipolar frame).
// Throws InputError for areaSamples < 1 and for a cookie or emission texture that does not exist.
struct LightDescription {
    std::vector<GpuLightCpu> lights;
    ShadowLayout layout;
    std::map<int, int> cookieLayers;  // scene texture -> layer of the cookie array, in first-use order
};
// What an area light's VPL stands for (the `vpl_kernel` parameter; shaders/common/lights.glsl,
// vplHasCell): its cell of the emitter, whose solid angle the air and the surfaces see (exact near the
// emitter), or a point with the kernel L_e dA cos(theta_e) / r^2 (which spikes next to the emitter).
enum class VplKernel { Point = 0, Cell = 1 };
LightDescription describeLights(const scene::Scene& scene, glm::dvec3 eye, int areaSamples,
                                VplKernel kernel = VplKernel::Cell);

class GpuLights {
public:
    // areaSamples >= 1 nodes per axis for each area light, each node's VPL with the given kernel.
    // Throws InputError for areaSamples < 1 and when the lights (VPLs included) exceed
    // hd::kMaxGpuLights.
    GpuLights(const scene::Scene& scene, glm::dvec3 eye, int areaSamples, VplKernel kernel = VplKernel::Cell);

    // Binds the light buffer as SSBO at kBindingLights and as uniform block at kBindingLightsUniform
    // (what common/lights.glsl reads), and the cookie array at kUnitCookies.
    void bind() const;
    int count() const { return static_cast<int>(mLights.size()); }
    const std::vector<GpuLightCpu>& lights() const { return mLights; }
    const ShadowLayout& shadowLayout() const { return mLayout; }
    const glm::dvec3& eye() const { return mEye; }
    const gl::Buffer& buffer() const { return mBuffer; }
    // Cookie array (a 1x1 white layer when the scene has no cookie, so the sampler is always valid).
    const gl::Texture& cookies() const { return mCookies; }
    int cookieCount() const { return mCookieCount; }  // layers in use: 0 when cookies() is the placeholder

private:
    std::vector<GpuLightCpu> mLights;
    ShadowLayout mLayout;
    glm::dvec3 mEye{0.0};
    gl::Buffer mBuffer;
    gl::Texture mCookies;
    int mCookieCount = 0;
};

}  // namespace viz::render
