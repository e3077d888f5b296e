// gl::Framebuffer: a framebuffer object with texture attachments, DSA only, labelled. Attaching a
// colour texture also updates the draw-buffer list so every attached colour index is written.
#pragma once

#include <epoxy/gl.h>

#include <string>

#include "gl/handle.h"
#include "gl/texture.h"

namespace viz::gl {

class Framebuffer {
public:
    Framebuffer() = default;
    static Framebuffer create(std::string label);

    GLuint id() const { return mHandle.get(); }

    // layer < 0 attaches the whole level (layered rendering for arrays, cubes and 3D textures);
    // layer >= 0 attaches one layer / cube face / slice.
    void attachColour(int index, const Texture& texture, int level = 0, int layer = -1);
    // GL_DEPTH_ATTACHMENT, or GL_DEPTH_STENCIL_ATTACHMENT for depth-stencil formats.
    void attachDepth(const Texture& texture, int layer = -1);
    void detachDepth();  // no depth attachment (nothing to do when there is none)
    // Throws std::runtime_error naming the label and the status when incomplete (programmer error).
    void checkComplete() const;

    // glBindFramebuffer(GL_FRAMEBUFFER, id()); the caller sets the viewport.
    void bind() const;
    static void bindDefault();

private:
    Handle<FramebufferTraits> mHandle;
    std::string mLabel;
    unsigned mColourMask = 0;  // bit i set: GL_COLOR_ATTACHMENT0 + i is attached
};

}  // namespace viz::gl
