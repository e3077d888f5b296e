// gl::Buffer: immutable-storage buffer (glNamedBufferStorage), DSA only, labelled.
#pragma once

#include <epoxy/gl.h>

#include <cstddef>
#include <string>
#include <vector>

#include "gl/handle.h"

namespace viz::gl {

struct BufferDesc {
    size_t bytes = 0;
    const void* data = nullptr;  // initial contents, or nullptr (zero-filled)
    GLbitfield flags = GL_DYNAMIC_STORAGE_BIT;
    std::string label{};
};

class Buffer {
public:
    Buffer() = default;  // empty (id() == 0)
    static Buffer create(const BufferDesc& desc);

    GLuint id() const { return mHandle.get(); }
    explicit operator bool() const { return static_cast<bool>(mHandle); }
    size_t bytes() const { return mBytes; }
    const std::string& label() const { return mLabel; }

    // glNamedBufferSubData; needs GL_DYNAMIC_STORAGE_BIT. offset + bytes must fit.
    void upload(size_t offset, size_t bytes, const void* data);
    // glGetNamedBufferSubData into dst.
    void download(size_t offset, size_t bytes, void* dst) const;
    template <typename T>
    std::vector<T> download() const {
        std::vector<T> out(mBytes / sizeof(T));
        download(0, out.size() * sizeof(T), out.data());
        return out;
    }
    // Sets every byte to zero (glClearNamedBufferData).
    void clearZero();

    // glBindBufferBase / glBindBufferRange for indexed targets (GL_SHADER_STORAGE_BUFFER,
    // GL_UNIFORM_BUFFER, GL_ATOMIC_COUNTER_BUFFER).
    void bindBase(GLenum target, GLuint index) const;
    void bindRange(GLenum target, GLuint index, size_t offset, size_t bytes) const;
    // glBindBuffer for non-indexed targets (GL_DRAW_INDIRECT_BUFFER, GL_DISPATCH_INDIRECT_BUFFER,
    // ...).
    void bind(GLenum target) const;

private:
    Handle<BufferTraits> mHandle;
    size_t mBytes = 0;
    std::string mLabel;
};

}  // namespace viz::gl
