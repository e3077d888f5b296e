// What the current GL context is: version, profile, debug flag and renderer strings.
#pragma once

#include <string>

namespace viz::gl {

struct ContextInfo {
    int major = 0;
    int minor = 0;
    bool core = false;   // GL_CONTEXT_CORE_PROFILE_BIT set in GL_CONTEXT_PROFILE_MASK
    bool debug = false;  // GL_CONTEXT_FLAG_DEBUG_BIT set in GL_CONTEXT_FLAGS
    std::string vendor, renderer, version;
};

// Needs a current context.
ContextInfo contextInfo();

// True for Mesa's CPU rasterizers (llvmpipe, softpipe), where GL timer queries do not measure the
// work.
bool isSoftwareRenderer(const std::string& renderer);

}  // namespace viz::gl
