#include "gl/framebuffer.h"

#include <stdexcept>
#include <vector>

#include "core/error.h"

namespace viz::gl {

namespace {

const char* statusName(GLenum status) {
    switch (status) {
        case GL_FRAMEBUFFER_UNDEFINED:
            return "GL_FRAMEBUFFER_UNDEFINED";
        case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT:
            return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
        case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
            return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
        case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER:
            return "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER";
        case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER:
            return "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER";
        case GL_FRAMEBUFFER_UNSUPPORTED:
            return "GL_FRAMEBUFFER_UNSUPPORTED";
        case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE:
            return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
        case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS:
            return "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS";
        default:
            return "unknown status";
    }
}

bool hasStencil(GLenum format) {
    return format == GL_DEPTH24_STENCIL8 || format == GL_DEPTH32F_STENCIL8;
}

}  // namespace

Framebuffer Framebuffer::create(std::string label) {
    Framebuffer f;
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    f.mHandle = Handle<FramebufferTraits>(id);
    f.mLabel = std::move(label);
    setLabel(GL_FRAMEBUFFER, id, f.mLabel);
    // A depth-only framebuffer draws no colour; the list grows as colour attachments are added.
    glNamedFramebufferDrawBuffer(id, GL_NONE);
    glNamedFramebufferReadBuffer(id, GL_NONE);
    return f;
}

void Framebuffer::attachColour(int index, const Texture& texture, int level, int layer) {
    VIZ_CHECK(index >= 0 && index < 8, "color attachment index out of range for '" + mLabel + "'");
    const GLenum attachment = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(index);
    if (layer < 0) {
        glNamedFramebufferTexture(id(), attachment, texture.id(), level);
    } else {
        glNamedFramebufferTextureLayer(id(), attachment, texture.id(), level, layer);
    }
    mColourMask |= 1u << index;
    std::vector<GLenum> buffers;
    for (int i = 0; i < 8; ++i) {
        buffers.push_back((mColourMask & (1u << i)) ? GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i)
                                                   : GL_NONE);
    }
    while (!buffers.empty() && buffers.back() == GL_NONE)
        buffers.pop_back();
    glNamedFramebufferDrawBuffers(id(), static_cast<GLsizei>(buffers.size()), buffers.data());
    if (index == 0)
        glNamedFramebufferReadBuffer(id(), GL_COLOR_ATTACHMENT0);
}

void Framebuffer::attachDepth(const Texture& texture, int layer) {
    const GLenum attachment =
        hasStencil(texture.format()) ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT;
    if (layer < 0) {
        glNamedFramebufferTexture(id(), attachment, texture.id(), 0);
    } else {
        glNamedFramebufferTextureLayer(id(), attachment, texture.id(), 0, layer);
    }
}

void Framebuffer::detachDepth() {
    glNamedFramebufferTexture(id(), GL_DEPTH_ATTACHMENT, 0, 0);
    glNamedFramebufferTexture(id(), GL_STENCIL_ATTACHMENT, 0, 0);
}

void Framebuffer::checkComplete() const {
    const GLenum status = glCheckNamedFramebufferStatus(id(), GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        throw std::runtime_error("framebuffer '" + mLabel +
                                 "' is incomplete: " + statusName(status));
    }
}

void Framebuffer::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, id());
}

void Framebuffer::bindDefault() {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace viz::gl
