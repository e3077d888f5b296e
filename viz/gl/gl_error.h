// Errors of the GL layer. GlUnavailable: the machine cannot give us an OpenGL 4.5 core context (an
// InputError, so the CLI prints one line and exits with code 2). ShaderError: a shader failed to
// compile or link; the message starts with "file:line:" of the original source line.
#pragma once

#include <stdexcept>
#include <string>

#include "core/error.h"

namespace viz {

class GlUnavailable : public InputError {
public:
    explicit GlUnavailable(const std::string& message) : InputError(message) {}
};

}  // namespace viz

namespace viz::gl {

class ShaderError : public std::runtime_error {
public:
    // file: the shader path as shown to people ("shaders/common/airlight.glsl"); line: 1-based line
    // in that file, 0 when the driver's log could not be mapped to one.
    ShaderError(const std::string& message, std::string file, int line)
        : std::runtime_error(message), mFile(std::move(file)), mLine(line) {}
    const std::string& file() const { return mFile; }
    int line() const { return mLine; }

private:
    std::string mFile;
    int mLine = 0;
};

// Throws GlUnavailable("OpenGL 4.5 core is required; this context offers X.Y (renderer)") when the
// current context is older than 4.5 or is not a core profile. Needs a current context.
void requireGl45();

}  // namespace viz::gl
