#include "gl/texture.h"

#include <algorithm>

#include "core/error.h"

namespace viz::gl {

namespace {

bool isDepthFormat(GLenum format) {
    switch (format) {
        case GL_DEPTH_COMPONENT16:
        case GL_DEPTH_COMPONENT24:
        case GL_DEPTH_COMPONENT32:
        case GL_DEPTH_COMPONENT32F:
        case GL_DEPTH24_STENCIL8:
        case GL_DEPTH32F_STENCIL8:
            return true;
        default:
            return false;
    }
}

bool isLayered(GLenum target) {
    return target == GL_TEXTURE_2D_ARRAY || target == GL_TEXTURE_CUBE_MAP ||
           target == GL_TEXTURE_3D;
}

}  // namespace

Texture Texture::create(const TextureDesc& desc) {
    VIZ_CHECK(desc.format != 0, "TextureDesc.format is not set for '" + desc.label + "'");
    VIZ_CHECK(desc.size.x > 0 && desc.size.y > 0, "texture '" + desc.label + "' has an empty size");
    VIZ_CHECK(desc.levels >= 1, "texture '" + desc.label + "' needs at least one level");
    Texture t;
    t.mDesc = desc;
    GLuint id = 0;
    glCreateTextures(desc.target, 1, &id);
    t.mHandle = Handle<TextureTraits>(id);
    switch (desc.target) {
        case GL_TEXTURE_2D:
            t.mDesc.size.z = 1;
            glTextureStorage2D(id, desc.levels, desc.format, desc.size.x, desc.size.y);
            break;
        case GL_TEXTURE_CUBE_MAP:
            VIZ_CHECK(desc.size.x == desc.size.y, "cube map '" + desc.label + "' must be square");
            t.mDesc.size.z = 6;
            glTextureStorage2D(id, desc.levels, desc.format, desc.size.x, desc.size.y);
            break;
        case GL_TEXTURE_2D_ARRAY:
        case GL_TEXTURE_3D:
            VIZ_CHECK(desc.size.z > 0, "texture '" + desc.label + "' needs size.z > 0");
            glTextureStorage3D(id, desc.levels, desc.format, desc.size.x, desc.size.y, desc.size.z);
            break;
        default:
            VIZ_CHECK(false, "unsupported texture target for '" + desc.label + "'");
    }
    // Immutable storage starts with mipmapped minification; a single level would sample as
    // incomplete.
    if (desc.levels == 1) {
        glTextureParameteri(id, GL_TEXTURE_MIN_FILTER,
                            isDepthFormat(desc.format) ? GL_NEAREST : GL_LINEAR);
        glTextureParameteri(id, GL_TEXTURE_MAG_FILTER,
                            isDepthFormat(desc.format) ? GL_NEAREST : GL_LINEAR);
    }
    setLabel(GL_TEXTURE, id, desc.label);
    return t;
}

int Texture::layers() const {
    return isLayered(mDesc.target) ? mDesc.size.z : 1;
}

void Texture::upload(GLenum pixelFormat, GLenum type, const void* data, int level) {
    const glm::ivec3 extent{
        std::max(1, mDesc.size.x >> level), std::max(1, mDesc.size.y >> level),
        mDesc.target == GL_TEXTURE_3D ? std::max(1, mDesc.size.z >> level) : layers()};
    uploadRegion({0, 0, 0}, extent, pixelFormat, type, data, level);
}

void Texture::uploadRegion(glm::ivec3 offset, glm::ivec3 extent, GLenum pixelFormat, GLenum type,
                           const void* data, int level) {
    VIZ_CHECK(id() != 0, "upload to an empty texture");
    // Our CPU arrays are tightly packed; the default unpack alignment of 4 would skew odd-width
    // rows.
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (mDesc.target == GL_TEXTURE_2D) {
        glTextureSubImage2D(id(), level, offset.x, offset.y, extent.x, extent.y, pixelFormat, type,
                            data);
    } else {
        // Cube maps take faces as layers of a 3D upload in DSA (GL 4.5, section 8.6).
        glTextureSubImage3D(id(), level, offset.x, offset.y, offset.z, extent.x, extent.y, extent.z,
                            pixelFormat, type, data);
    }
}

void Texture::clear(GLenum pixelFormat, GLenum type, const void* value, int level) {
    glClearTexImage(id(), level, pixelFormat, type, value);
}

void Texture::clear(glm::vec4 value, int level) {
    if (isDepthFormat(mDesc.format)) {
        glClearTexImage(id(), level, GL_DEPTH_COMPONENT, GL_FLOAT, &value.x);
    } else {
        glClearTexImage(id(), level, GL_RGBA, GL_FLOAT, &value.x);
    }
}

void Texture::generateMipmaps() {
    glGenerateTextureMipmap(id());
}

void Texture::setFilter(GLenum minFilter, GLenum magFilter) {
    glTextureParameteri(id(), GL_TEXTURE_MIN_FILTER, static_cast<GLint>(minFilter));
    glTextureParameteri(id(), GL_TEXTURE_MAG_FILTER, static_cast<GLint>(magFilter));
}

void Texture::setWrap(GLenum wrap) {
    glTextureParameteri(id(), GL_TEXTURE_WRAP_S, static_cast<GLint>(wrap));
    glTextureParameteri(id(), GL_TEXTURE_WRAP_T, static_cast<GLint>(wrap));
    glTextureParameteri(id(), GL_TEXTURE_WRAP_R, static_cast<GLint>(wrap));
}

void Texture::bindUnit(GLuint unit) const {
    glBindTextureUnit(unit, id());
}

void Texture::bindImage(GLuint unit, GLenum access, int level, int layer) const {
    const bool layered = layer < 0 && isLayered(mDesc.target);
    glBindImageTexture(unit, id(), level, layered ? GL_TRUE : GL_FALSE, layer < 0 ? 0 : layer,
                       access, mDesc.format);
}

Sampler Sampler::create(const SamplerDesc& desc) {
    Sampler s;
    GLuint id = 0;
    glCreateSamplers(1, &id);
    s.mHandle = Handle<SamplerTraits>(id);
    glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(desc.minFilter));
    glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(desc.magFilter));
    glSamplerParameteri(id, GL_TEXTURE_WRAP_S, static_cast<GLint>(desc.wrap));
    glSamplerParameteri(id, GL_TEXTURE_WRAP_T, static_cast<GLint>(desc.wrap));
    glSamplerParameteri(id, GL_TEXTURE_WRAP_R, static_cast<GLint>(desc.wrap));
    glSamplerParameteri(id, GL_TEXTURE_COMPARE_MODE, static_cast<GLint>(desc.compareMode));
    glSamplerParameteri(id, GL_TEXTURE_COMPARE_FUNC, static_cast<GLint>(desc.compareFunc));
    glSamplerParameterfv(id, GL_TEXTURE_BORDER_COLOR, &desc.borderColour.x);
    setLabel(GL_SAMPLER, id, desc.label);
    return s;
}

void Sampler::bindUnit(GLuint unit) const {
    glBindSampler(unit, id());
}

}  // namespace viz::gl
