#include "gl/context_info.h"

#include <epoxy/gl.h>

#include "gl/gl_error.h"

namespace viz::gl {

namespace {

std::string glString(GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return s ? std::string(s) : std::string();
}

}  // namespace

ContextInfo contextInfo() {
    ContextInfo info;
    info.vendor = glString(GL_VENDOR);
    info.renderer = glString(GL_RENDERER);
    info.version = glString(GL_VERSION);
    // GL_MAJOR_VERSION exists since 3.0; epoxy parses the version string, which also works before
    // that.
    const int v = epoxy_gl_version();
    info.major = v / 10;
    info.minor = v % 10;
    if (v >= 32) {
        GLint mask = 0;
        glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
        info.core = (mask & GL_CONTEXT_CORE_PROFILE_BIT) != 0;
    }
    if (v >= 30) {
        GLint flags = 0;
        glGetIntegerv(GL_CONTEXT_FLAGS, &flags);
        info.debug = (flags & GL_CONTEXT_FLAG_DEBUG_BIT) != 0;
    }
    return info;
}

bool isSoftwareRenderer(const std::string& renderer) {
    return renderer.find("llvmpipe") != std::string::npos ||
           renderer.find("softpipe") != std::string::npos;
}

void requireGl45() {
    const ContextInfo info = contextInfo();
    if (info.major * 10 + info.minor < 45 || !info.core) {
        throw GlUnavailable("OpenGL 4.5 core is required; this context offers " +
                            std::to_string(info.major) + "." + std::to_string(info.minor) +
                            (info.core ? " core" : "") + " (" + info.renderer + ")");
    }
}

}  // namespace viz::gl
