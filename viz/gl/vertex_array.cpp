#include "gl/vertex_array.h"

namespace viz::gl {

VertexArray VertexArray::create(std::string label) {
    VertexArray v;
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    v.mHandle = Handle<VertexArrayTraits>(id);
    setLabel(GL_VERTEX_ARRAY, id, label);
    return v;
}

void VertexArray::bind() const {
    glBindVertexArray(id());
}

void VertexArray::vertexBuffer(GLuint binding, const Buffer& buffer, size_t offset, int stride) {
    glVertexArrayVertexBuffer(id(), binding, buffer.id(), static_cast<GLintptr>(offset), stride);
}

void VertexArray::elementBuffer(const Buffer& buffer) {
    glVertexArrayElementBuffer(id(), buffer.id());
}

void VertexArray::attribute(GLuint location, GLuint binding, int components, GLenum type,
                            GLuint offset, bool normalized) {
    glEnableVertexArrayAttrib(id(), location);
    glVertexArrayAttribFormat(id(), location, components, type, normalized ? GL_TRUE : GL_FALSE,
                              offset);
    glVertexArrayAttribBinding(id(), location, binding);
}

void VertexArray::attributeInt(GLuint location, GLuint binding, int components, GLenum type,
                               GLuint offset) {
    glEnableVertexArrayAttrib(id(), location);
    glVertexArrayAttribIFormat(id(), location, components, type, offset);
    glVertexArrayAttribBinding(id(), location, binding);
}

}  // namespace viz::gl
