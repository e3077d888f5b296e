// HeadlessContext: an OpenGL 4.5 core context without a window, through EGL. Uses Mesa's
// surfaceless platform (EGL_MESA_platform_surfaceless), or the EGL device platform
// (EGL_EXT_platform_device, NVIDIA) when surfaceless is missing. Used by tests and the --headless
// CLI.
#pragma once

#include <memory>
#include <string>

namespace viz {

class HeadlessContext {
public:
    // Creates the context, makes it current on the calling thread and checks for 4.5 core. debug:
    // request a debug context (needed for glDebugMessageCallback output). Throws GlUnavailable with
    // one line.
    static std::unique_ptr<HeadlessContext> create(bool debug);
    ~HeadlessContext();

    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;
    HeadlessContext(HeadlessContext&& other) noexcept;
    HeadlessContext& operator=(HeadlessContext&& other) noexcept;

    // Makes this context current on the calling thread (create() already did for its thread).
    void makeCurrent() const;
    std::string renderer() const;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
    std::string platform() const;  // "surfaceless" or "device"

private:
    HeadlessContext() = default;
    void destroy();

    void* mDisplay = nullptr;  // EGLDisplay
    void* mContext = nullptr;  // EGLContext
    std::string mPlatform;
    std::string mRenderer;
};

}  // namespace viz
