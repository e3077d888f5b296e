// gl::Program: a linked program built from shader files (one per stage) through loadShaderSource,
// with typed uniform setters (glProgramUniform*, so no bind is needed). Compile and link failures
// throw ShaderError whose message starts with the original "file:line:".
#pragma once

#include <cstdint>

#include <epoxy/gl.h>

#include <glm/glm.hpp>
#include <string>
#include <utility>
#include <vector>

#include "gl/handle.h"
#include "gl/shader_source.h"

namespace viz::gl {

struct ProgramDesc {
    // Paths relative to the shader dir, e.g. "raymarch/march.frag". The stage comes from the
    // extension: .vert .frag .comp .geom (.tesc .tese too).
    std::vector<std::string> stages{};
    ShaderDefines defines{};  // {"NAME", "VALUE"} -> #define NAME VALUE in every stage
    std::string label{};
};

class Program {
public:
    Program() = default;
    static Program compile(const ProgramDesc& desc);

    GLuint id() const { return mHandle.get(); }
    explicit operator bool() const { return static_cast<bool>(mHandle); }
    const std::string& label() const { return mLabel; }
    void use() const;  // glUseProgram

    // Uniform setters by name; a uniform the linker removed (or never declared) is silently
    // ignored.
    void set(const char* name, float v) const;
    void set(const char* name, int v) const;
    void set(const char* name, unsigned v) const;
    void set(const char* name, bool v) const { set(name, v ? 1 : 0); }
    void set(const char* name, glm::vec2 v) const;
    void set(const char* name, glm::vec3 v) const;
    void set(const char* name, glm::vec4 v) const;
    void set(const char* name, glm::ivec2 v) const;
    void set(const char* name, glm::ivec3 v) const;
    void set(const char* name, glm::ivec4 v) const;
    void set(const char* name, const glm::mat3& v) const;
    void set(const char* name, const glm::mat4& v) const;
    // -1 when the uniform does not exist.
    GLint location(const char* name) const;

    // Work-group size of a compute program (glGetProgramiv GL_COMPUTE_WORK_GROUP_SIZE).
    glm::ivec3 workGroupSize() const;

private:
    Handle<ProgramTraits> mHandle;
    std::string mLabel;
};

// How many programs Program::compile has built on the calling thread so far. gl::StageClock records the
// difference across a stage: a stage that compiles (a technique's first run, a new shader permutation)
// pays for it in its time, which is then no warm figure.
std::uint64_t programsCompiledOnThisThread();

// Number of work groups covering `size` items with groups of `group`: ceil(size / group) per axis.
inline glm::ivec3 groupCount(glm::ivec3 size, glm::ivec3 group) {
    return (size + group - 1) / group;
}

}  // namespace viz::gl
