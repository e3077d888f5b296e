#include "gl/debug_output.h"

#include <epoxy/gl.h>

#include <atomic>
#include <cstdio>
#include <cstring>

namespace viz::gl {

namespace {

std::atomic<int> gErrorCount{0};

const char* typeName(GLenum type) {
    switch (type) {
        case GL_DEBUG_TYPE_ERROR:
            return "error";
        case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR:
            return "deprecated";
        case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR:
            return "undefined behavior";
        case GL_DEBUG_TYPE_PORTABILITY:
            return "portability";
        case GL_DEBUG_TYPE_PERFORMANCE:
            return "performance";
        default:
            return "other";
    }
}

void GLAPIENTRY onMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                          const GLchar* message, const void* /*user*/) {
    // Compile errors reach the caller as ShaderError with mapped file:line; the raw driver text
    // (with encoded line numbers) would only confuse, and an expected compile failure is not an API
    // error.
    if (source == GL_DEBUG_SOURCE_SHADER_COMPILER)
        return;
    if (type == GL_DEBUG_TYPE_ERROR)
        ++gErrorCount;
    // Notifications (object created, buffer placed in memory, ...) are noise for our purposes.
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION)
        return;
    if (type == GL_DEBUG_TYPE_PUSH_GROUP || type == GL_DEBUG_TYPE_POP_GROUP)
        return;
    std::fprintf(stderr, "[gl %s %u] %.*s\n", typeName(type), id,
                 length < 0 ? static_cast<int>(std::strlen(message)) : static_cast<int>(length),
                 message);
}

}  // namespace

void installDebugOutput() {
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onMessage, nullptr);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

int debugErrorCount() {
    return gErrorCount.load();
}

void resetDebugErrorCount() {
    gErrorCount = 0;
}

}  // namespace viz::gl
