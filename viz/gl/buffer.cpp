#include "gl/buffer.h"

#include "core/error.h"

namespace viz::gl {

Buffer Buffer::create(const BufferDesc& desc) {
    VIZ_CHECK(desc.bytes > 0, "buffer '" + desc.label + "' has size 0");
    Buffer b;
    GLuint id = 0;
    glCreateBuffers(1, &id);
    b.mHandle = Handle<BufferTraits>(id);
    b.mBytes = desc.bytes;
    b.mLabel = desc.label;
    glNamedBufferStorage(id, static_cast<GLsizeiptr>(desc.bytes), desc.data, desc.flags);
    // Storage without data is undefined in GL; zero it so reads of unwritten parts are
    // deterministic.
    if (desc.data == nullptr)
        b.clearZero();
    setLabel(GL_BUFFER, id, desc.label);
    return b;
}

void Buffer::upload(size_t offset, size_t bytes, const void* data) {
    VIZ_CHECK(offset + bytes <= mBytes, "upload past the end of buffer '" + mLabel + "'");
    glNamedBufferSubData(id(), static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
}

void Buffer::download(size_t offset, size_t bytes, void* dst) const {
    VIZ_CHECK(offset + bytes <= mBytes, "download past the end of buffer '" + mLabel + "'");
    glGetNamedBufferSubData(id(), static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes),
                            dst);
}

void Buffer::clearZero() {
    const GLuint zero = 0;
    // R8UI with one zero byte clears every byte, whatever the buffer's size.
    glClearNamedBufferData(id(), GL_R8UI, GL_RED_INTEGER, GL_UNSIGNED_BYTE, &zero);
}

void Buffer::bindBase(GLenum target, GLuint index) const {
    glBindBufferBase(target, index, id());
}

void Buffer::bindRange(GLenum target, GLuint index, size_t offset, size_t bytes) const {
    glBindBufferRange(target, index, id(), static_cast<GLintptr>(offset),
                      static_cast<GLsizeiptr>(bytes));
}

void Buffer::bind(GLenum target) const {
    glBindBuffer(target, id());
}

}  // namespace viz::gl
