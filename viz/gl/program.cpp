#include "gl/program.h"

#include <algorithm>
#include <glm/gtc/type_ptr.hpp>
#include <string>

#include "gl/gl_error.h"
#include "gl/work_counters.h"

namespace viz::gl {

namespace {

bool endsWith(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() &&
           s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

GLenum stageFromPath(const std::string& path) {
    if (endsWith(path, ".vert"))
        return GL_VERTEX_SHADER;
    if (endsWith(path, ".frag"))
        return GL_FRAGMENT_SHADER;
    if (endsWith(path, ".comp"))
        return GL_COMPUTE_SHADER;
    if (endsWith(path, ".geom"))
        return GL_GEOMETRY_SHADER;
    if (endsWith(path, ".tesc"))
        return GL_TESS_CONTROL_SHADER;
    if (endsWith(path, ".tese"))
        return GL_TESS_EVALUATION_SHADER;
    throw ShaderError(
        path + ":0: error: unknown shader stage (expected .vert .frag .comp .geom .tesc .tese)",
        path, 0);
}

std::string shaderLog(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
    log.resize(std::char_traits<char>::length(log.c_str()));
    return log;
}

std::string programLog(GLuint program) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
    glGetProgramInfoLog(program, static_cast<GLsizei>(log.size()), nullptr, log.data());
    log.resize(std::char_traits<char>::length(log.c_str()));
    return log;
}

// Compiles one stage; on failure throws ShaderError with the log mapped to original files and
// lines.
Handle<ShaderTraits> compileStage(const std::string& path, const ShaderDefines& defines) {
    const GLenum stage = stageFromPath(path);
    const ShaderSource source = loadShaderSource(path, defines);
    Handle<ShaderTraits> shader(glCreateShader(stage));
    const char* text = source.text.c_str();
    const GLint length = static_cast<GLint>(source.text.size());
    glShaderSource(shader.get(), 1, &text, &length);
    glCompileShader(shader.get());
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        std::string file;
        int line = 0;
        std::string message = mapShaderLog(shaderLog(shader.get()), source.files, &file, &line);
        if (file.empty()) {
            file = source.files.front();
            message = file + ":0: error: compile failed: " + message;
        }
        throw ShaderError(message, file, line);
    }
    setLabel(GL_SHADER, shader.get(), source.files.front());
    return shader;
}

}  // namespace

namespace {
thread_local std::uint64_t tProgramsCompiled = 0;
}  // namespace

std::uint64_t programsCompiledOnThisThread() { return tProgramsCompiled; }

Program Program::compile(const ProgramDesc& desc) {
    ++tProgramsCompiled;
    if (desc.stages.empty())
        throw ShaderError("program '" + desc.label + "' has no stages", "", 0);
    std::vector<Handle<ShaderTraits>> shaders;
    ShaderDefines defines = desc.defines;
    if (WorkCounters::enabled()) defines.push_back({"COUNT_WORK", "1"});  // gl/work_counters.h
    for (const std::string& path : desc.stages)
        shaders.push_back(compileStage(path, defines));

    Program p;
    p.mHandle = Handle<ProgramTraits>(glCreateProgram());
    p.mLabel = desc.label;
    if (p.mLabel.empty()) {
        for (const std::string& path : desc.stages)
            p.mLabel += (p.mLabel.empty() ? "" : "+") + path;
    }
    for (const auto& s : shaders)
        glAttachShader(p.id(), s.get());
    glLinkProgram(p.id());
    for (const auto& s : shaders)
        glDetachShader(p.id(), s.get());
    GLint ok = GL_FALSE;
    glGetProgramiv(p.id(), GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        throw ShaderError(desc.stages.front() + ":0: error: program '" + p.mLabel +
                              "' failed to link: " + programLog(p.id()),
                          desc.stages.front(), 0);
    }
    setLabel(GL_PROGRAM, p.id(), p.mLabel);
    return p;
}

void Program::use() const {
    glUseProgram(id());
}

GLint Program::location(const char* name) const {
    return glGetUniformLocation(id(), name);
}

// glProgramUniform* with location -1 is a no-op by the GL spec, which gives "missing is ignored".
void Program::set(const char* name, float v) const {
    glProgramUniform1f(id(), location(name), v);
}
void Program::set(const char* name, int v) const {
    glProgramUniform1i(id(), location(name), v);
}
void Program::set(const char* name, unsigned v) const {
    glProgramUniform1ui(id(), location(name), v);
}
void Program::set(const char* name, glm::vec2 v) const {
    glProgramUniform2fv(id(), location(name), 1, glm::value_ptr(v));
}
void Program::set(const char* name, glm::vec3 v) const {
    glProgramUniform3fv(id(), location(name), 1, glm::value_ptr(v));
}
void Program::set(const char* name, glm::vec4 v) const {
    glProgramUniform4fv(id(), location(name), 1, glm::value_ptr(v));
}
void Program::set(const char* name, glm::ivec2 v) const {
    glProgramUniform2iv(id(), location(name), 1, glm::value_ptr(v));
}
void Program::set(const char* name, glm::ivec3 v) const {
    glProgramUniform3iv(id(), location(name), 1, glm::value_ptr(v));
}
void Program::set(const char* name, glm::ivec4 v) const {
    glProgramUniform4iv(id(), location(name), 1, glm::value_ptr(v));
}
void Program::set(const char* name, const glm::mat3& v) const {
    glProgramUniformMatrix3fv(id(), location(name), 1, GL_FALSE, glm::value_ptr(v));
}
void Program::set(const char* name, const glm::mat4& v) const {
    glProgramUniformMatrix4fv(id(), location(name), 1, GL_FALSE, glm::value_ptr(v));
}

glm::ivec3 Program::workGroupSize() const {
    GLint size[3] = {0, 0, 0};
    glGetProgramiv(id(), GL_COMPUTE_WORK_GROUP_SIZE, size);
    return {size[0], size[1], size[2]};
}

}  // namespace viz::gl
