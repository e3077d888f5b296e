// The scene's geometry and materials on the GPU: one interleaved vertex buffer (world position, normal,
// uv, material index) and one index buffer for all meshes, materials in an SSBO, base-colour and
// emission textures in one GL_TEXTURE_2D_ARRAY (bilinear, clamp to edge, filtered in the shader).
// The array is GL_RGBA8 holding the sRGB bytes, and shaders decode with the exact IEC 61966-2-1 curve
// (common/lights.glsl): GL_SRGB8_ALPHA8 would decode in the texture unit, but llvmpipe's decode is an
// approximation (measured: 2.5 % relative error at byte 9), far above what the reference comparison needs.
// Draw with shaders/render/scene.vert, which applies the eye-relative model matrix (eye_space.h).
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "gl/buffer.h"
#include "gl/texture.h"
#include "gl/vertex_array.h"
#include "render/host_device.h"
#include "scene/bounds.h"
#include "scene/scene.h"

namespace viz::render {

// Vertex attribute locations of shaders/render/scene.vert.
inline constexpr unsigned kAttribPosition = 0;  // vec3, world space
inline constexpr unsigned kAttribNormal = 1;    // vec3, world space, unit (flat where the mesh has none)
inline constexpr unsigned kAttribUv = 2;        // vec2
inline constexpr unsigned kAttribMaterial = 3;  // uint, index into the material SSBO

struct GpuVertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec2 uv;
    std::uint32_t material;
};
static_assert(sizeof(GpuVertex) == 36);

class GpuScene {
public:
    explicit GpuScene(const scene::Scene& scene);

    // Binds the VAO and draws every triangle; the caller has bound a program (e.g. one built on
    // render/scene.vert with uModel and uViewProj set).
    void draw() const;
    // Materials SSBO at kBindingMaterials, the texture array at kUnitMaterialTextures.
    void bindMaterials() const;

    const scene::Bounds& bounds() const { return mBounds; }  // world space
    int triangleCount() const { return mIndexCount / 3; }
    int materialCount() const { return mMaterialCount; }
    const gl::Buffer& vertexBuffer() const { return mVertices; }
    const gl::Buffer& indexBuffer() const { return mIndices; }
    const gl::Buffer& materialBuffer() const { return mMaterials; }
    const gl::Texture& materialTextures() const { return mTextures; }

private:
    gl::Buffer mVertices;
    gl::Buffer mIndices;
    gl::Buffer mMaterials;
    gl::Texture mTextures;
    gl::VertexArray mVao;
    scene::Bounds mBounds;
    int mIndexCount = 0;
    int mMaterialCount = 0;
};

}  // namespace viz::render
