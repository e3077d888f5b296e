// Handle<Traits>: owns one GL name, move-only. The destructor deletes the name through
// Traits::destroy; a moved-from handle holds 0 and deletes nothing. Every wrapper type (Texture,
// Buffer, ...) holds one, so liveHandleCount() is the number of GL objects our code owns (the soak test
// checks it stays flat).
#pragma once

#include <epoxy/gl.h>

#include <string>
#include <utility>

namespace viz::gl {

// GL names currently owned by a Handle, all types together (creations minus deletions and releases).
long liveHandleCount();
void countHandle(int delta);

template <typename Traits>
class Handle {
public:
    Handle() = default;
    explicit Handle(GLuint id) : mId(id) {
        if (id != 0) countHandle(+1);
    }
    ~Handle() { reset(); }

    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    Handle(Handle&& other) noexcept : mId(std::exchange(other.mId, 0u)) {}
    Handle& operator=(Handle&& other) noexcept {
        if (this != &other) {
            reset();
            mId = std::exchange(other.mId, 0u);
        }
        return *this;
    }

    GLuint get() const { return mId; }
    explicit operator bool() const { return mId != 0; }

    // Deletes the owned name now (if any).
    void reset() {
        if (mId != 0) {
            Traits::destroy(mId);
            countHandle(-1);
        }
        mId = 0;
    }
    // Gives up ownership without deleting.
    GLuint release() {
        if (mId != 0) countHandle(-1);
        return std::exchange(mId, 0u);
    }

private:
    GLuint mId = 0;
};

struct TextureTraits {
    static void destroy(GLuint id) { glDeleteTextures(1, &id); }
};
struct SamplerTraits {
    static void destroy(GLuint id) { glDeleteSamplers(1, &id); }
};
struct BufferTraits {
    static void destroy(GLuint id) { glDeleteBuffers(1, &id); }
};
struct FramebufferTraits {
    static void destroy(GLuint id) { glDeleteFramebuffers(1, &id); }
};
struct VertexArrayTraits {
    static void destroy(GLuint id) { glDeleteVertexArrays(1, &id); }
};
// A program deleted while current stays current, under a name that is no longer a program, until another
// is used; code that saves and restores the current program (the UI renderer) would then bind that name
// back (GL_INVALID_VALUE). Unbinding it first leaves no such name behind. (A vertex array deleted while
// bound is unbound by GL itself.)
struct ProgramTraits {
    static void destroy(GLuint id) {
        GLint current = 0;
        glGetIntegerv(GL_CURRENT_PROGRAM, &current);
        if (GLuint(current) == id) glUseProgram(0);
        glDeleteProgram(id);
    }
};
struct ShaderTraits {
    static void destroy(GLuint id) { glDeleteShader(id); }
};
struct QueryTraits {
    static void destroy(GLuint id) { glDeleteQueries(1, &id); }
};

// glObjectLabel with an explicit length; an empty label is skipped.
// identifier: GL_TEXTURE, GL_BUFFER, GL_FRAMEBUFFER, GL_VERTEX_ARRAY, GL_PROGRAM, GL_SAMPLER, ...
void setLabel(GLenum identifier, GLuint id, const std::string& label);

}  // namespace viz::gl
