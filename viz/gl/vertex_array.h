// gl::VertexArray: a vertex array object configured with DSA (glVertexArray*), labelled. An empty
// VAO is what fullscreen passes bind (vertices generated from gl_VertexID).
#pragma once

#include <epoxy/gl.h>

#include <string>

#include "gl/buffer.h"
#include "gl/handle.h"

namespace viz::gl {

class VertexArray {
public:
    VertexArray() = default;
    static VertexArray create(std::string label);

    GLuint id() const { return mHandle.get(); }
    void bind() const;  // glBindVertexArray

    // glVertexArrayVertexBuffer: buffer at binding point `binding`, `stride` bytes per vertex.
    void vertexBuffer(GLuint binding, const Buffer& buffer, size_t offset, int stride);
    // glVertexArrayElementBuffer.
    void elementBuffer(const Buffer& buffer);
    // Enables float attribute `location` read from `binding`: `components` of `type` at `offset`
    // bytes into each vertex (glVertexArrayAttribFormat + glVertexArrayAttribBinding).
    void attribute(GLuint location, GLuint binding, int components, GLenum type, GLuint offset,
                   bool normalized = false);
    // Integer attribute (glVertexArrayAttribIFormat).
    void attributeInt(GLuint location, GLuint binding, int components, GLenum type, GLuint offset);

private:
    Handle<VertexArrayTraits> mHandle;
};

}  // namespace viz::gl
