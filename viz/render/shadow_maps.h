// Shadow maps for every light of a GpuLights. Each map stores a linear distance in scene units (R32F),
// so one bias rule serves all kinds (shaders/common/shadow_map.glsl):
//   spot:        perspective map over the outer cone, distance to the light
//   directional: orthographic map over the scene's bounding sphere, depth dot(p, direction)
//   point, VPL:  cube map (six 90-degree faces), distance to the light
// Storage: three GL_TEXTURE_2D_ARRAYs. Spot and directional maps are one layer each of the first (size);
// a cube is six consecutive layers (+X, -X, +Y, -Y, +Z, -Z) of the second (point lights, size) or the
// third (VPLs, vplSize: VPLs are many, 16 of them at 256^2 take 25 MB). Cubes as plain layers keep the
// lookup a nearest texelFetch with the same face matrices as rendering (no cube-map seams or conventions
// to match). Layers and matrices were assigned by GpuLights; unused arrays get one 1x1 layer so every
// sampler stays valid.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "debug/technique.h"
#include "gl/buffer.h"
#include "gl/framebuffer.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "render/gpu_lights.h"
#include "render/gpu_scene.h"

namespace viz::render {

class ShadowMaps {
public:
    ShadowMaps();

    // size: texels per side of 2D maps and point cubes (the shared `shadow_map` parameter);
    // vplSize: texels per side of VPL cubes. Renders every map (reallocating only when sizes change).
    void build(const GpuScene& scene, const GpuLights& lights, int size, int vplSize);

    // Binds the three arrays at kUnitShadow2D, kUnitShadowCube, kUnitShadowCubeVpl.
    void bind() const;

    // Adds each light's map as an Intermediate (kind Depth): id prefix + ".shadow_map" for the first
    // light, prefix + ".shadow_map.N" for light N > 0 (N = index into GpuLights::lights()). Each names a
    // texture view of its own layers (GL_TEXTURE_2D, or GL_TEXTURE_CUBE_MAP for cubes; no copies), valid
    // until the next build().
    void publish(std::vector<Intermediate>& out, const std::string& prefix) const;

    // Face f of a cube (0..5 = +X, -X, +Y, -Y, +Z, -Z): view direction and up of its lookAt.
    static void cubeFaceBasis(int face, glm::dvec3& forward, glm::dvec3& up);

    // The stored distances of one map face (a 2D map: face 0), texels per side * texels per side floats,
    // row 0 = GL row 0 (ndc.y = -1). Read back at first use after each build() and kept until the next.
    // `light` is one of the lights of the last build() (its map: light.info.z >= 0).
    const std::vector<float>& texels(const GpuLightCpu& light, int face) const;
    // The smallest distance the light's map stores (every face of a cube), at most `upperBound` (an
    // empty map holds 1e30), and at least 0. Reduced on the GPU (render/shadow_nearest.comp); four bytes
    // come back, not the map. Kept until the next build().
    float nearest(const GpuLightCpu& light, float upperBound) const;
    // Texels per side of the light's map (vplSize for VPL cubes).
    int sizeOf(const GpuLightCpu& light) const { return light.info.x == hd::kLightVpl ? mVplSize : mSize; }

    const gl::Texture& maps2D() const { return mMaps2D; }
    const gl::Texture& cubes() const { return mCubes; }
    const gl::Texture& vplCubes() const { return mVplCubes; }
    int size() const { return mSize; }
    int vplSize() const { return mVplSize; }

private:
    void makeViews();

    // Where a light's map lives: its array (0 2D, 1 cubes, 2 VPL cubes) and layers [first, first + count).
    struct MapLayers {
        const gl::Texture* texture;
        int array, first, count;
    };
    MapLayers layersOf(const GpuLightCpu& light) const;

    gl::Program mProgram;
    mutable gl::Program mNearestProgram;  // compiled at first nearest()
    mutable gl::Buffer mNearestBuffer;
    mutable std::map<std::pair<int, int>, float> mNearest;  // nearest(): (array, first layer) -> value
    gl::Texture mMaps2D, mCubes, mVplCubes;
    gl::Texture mDepth, mDepthVpl;  // z-buffers for rendering (size and vplSize)
    gl::Framebuffer mFramebuffer;
    std::vector<GpuLightCpu> mLights;  // copy of what was rendered, for publish()
    std::vector<gl::Handle<gl::TextureTraits>> mViews;  // per light (0 = no map): views for publish()
    int mSize = 0, mVplSize = 0;
    ShadowLayout mLayout;
    // texels(): (array: 0 2D, 1 cubes, 2 VPL cubes; layer) -> the layer's values, cleared by build().
    mutable std::map<std::pair<int, int>, std::vector<float>> mReadback;
};

}  // namespace viz::render
