// gl::Texture and gl::Sampler: immutable-storage textures (glTextureStorage*) and sampler objects,
// DSA only, labelled. No hidden binds: bindUnit()/bindImage() are the only calls that touch binding
// points.
#pragma once

#include <epoxy/gl.h>

#include <glm/glm.hpp>
#include <string>

#include "gl/handle.h"

namespace viz::gl {

// size: (width, height, depth-or-layers). GL_TEXTURE_2D ignores z; GL_TEXTURE_2D_ARRAY uses z as
// the layer count; GL_TEXTURE_CUBE_MAP ignores z (always 6 faces, width == height); GL_TEXTURE_3D
// uses z as depth. glm::ivec3 has no two-argument constructor, so write .size = {w, h, 1}.
struct TextureDesc {
    GLenum target = GL_TEXTURE_2D;
    GLenum format =
        0;  // sized internal format: GL_RGBA32F, GL_R32F, GL_DEPTH_COMPONENT32F, GL_R32UI, ...
    glm::ivec3 size{0, 0, 1};
    int levels = 1;
    std::string label{};
};

class Texture {
public:
    Texture() = default;  // empty (id() == 0)
    static Texture create(const TextureDesc& desc);

    GLuint id() const { return mHandle.get(); }
    explicit operator bool() const { return static_cast<bool>(mHandle); }
    glm::ivec3 size() const { return mDesc.size; }
    GLenum format() const { return mDesc.format; }
    GLenum target() const { return mDesc.target; }
    int levels() const { return mDesc.levels; }
    const std::string& label() const { return mDesc.label; }
    // Array layers (2D array), 6 for a cube map, depth for 3D, 1 for 2D.
    int layers() const;

    // Uploads a whole level. pixelFormat/type describe `data` (GL_RGBA + GL_FLOAT, GL_RED +
    // GL_FLOAT, GL_RED_INTEGER + GL_UNSIGNED_INT, ...). Row 0 of `data` becomes GL's row 0 (the
    // bottom); for a cube map, faces follow in +X, -X, +Y, -Y, +Z, -Z order.
    void upload(GLenum pixelFormat, GLenum type, const void* data, int level = 0);
    // Uploads one region: offset/extent in texels (z = layer, cube face or slice).
    void uploadRegion(glm::ivec3 offset, glm::ivec3 extent, GLenum pixelFormat, GLenum type,
                      const void* data, int level = 0);
    // Fills a level with one value (glClearTexImage). `value` matches pixelFormat/type.
    void clear(GLenum pixelFormat, GLenum type, const void* value, int level = 0);
    // Fills a level with (r, g, b, a) for float/normalized colour formats, or depth = value.x.
    void clear(glm::vec4 value, int level = 0);
    void generateMipmaps();
    // Filtering/wrap on the texture object itself (used when no Sampler is bound).
    void setFilter(GLenum minFilter, GLenum magFilter);
    void setWrap(GLenum wrap);

    void bindUnit(GLuint unit) const;  // glBindTextureUnit
    // glBindImageTexture. layer < 0 binds all layers (layered = GL_TRUE).
    void bindImage(GLuint unit, GLenum access, int level = 0, int layer = -1) const;

private:
    Handle<TextureTraits> mHandle;
    TextureDesc mDesc;
};

struct SamplerDesc {
    GLenum minFilter = GL_LINEAR;
    GLenum magFilter = GL_LINEAR;
    GLenum wrap = GL_CLAMP_TO_EDGE;  // S, T and R
    GLenum compareMode = GL_NONE;    // GL_COMPARE_REF_TO_TEXTURE for shadow samplers
    GLenum compareFunc = GL_LEQUAL;
    glm::vec4 borderColour{0.0f};
    std::string label{};
};

class Sampler {
public:
    Sampler() = default;
    static Sampler create(const SamplerDesc& desc);
    GLuint id() const { return mHandle.get(); }
    void bindUnit(GLuint unit) const;  // glBindSampler

private:
    Handle<SamplerTraits> mHandle;
};

}  // namespace viz::gl
