#include "platform/context_egl.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>
#include <string>
#include <utility>

#include "gl/context_info.h"
#include "gl/debug_output.h"
#include "gl/gl_error.h"
#include "gl/work_counters.h"

namespace viz {

namespace {

// eglTerminate affects every context on a display, and displays from eglGetPlatformDisplay are
// shared per platform/device; count the live contexts per display and terminate with the last one.
std::mutex gDisplayMutex;
std::map<EGLDisplay, int> gDisplayUsers;

bool hasExtension(const char* list, const char* name) {
    if (list == nullptr)
        return false;
    const size_t n = std::strlen(name);
    for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n) {
        const bool startOk = p == list || p[-1] == ' ';
        const bool endOk = p[n] == ' ' || p[n] == '\0';
        if (startOk && endOk)
            return true;
    }
    return false;
}

std::string eglErrorName(EGLint code) {
    switch (code) {
        case EGL_BAD_MATCH:
            return "EGL_BAD_MATCH";
        case EGL_BAD_ATTRIBUTE:
            return "EGL_BAD_ATTRIBUTE";
        case EGL_BAD_CONFIG:
            return "EGL_BAD_CONFIG";
        case EGL_BAD_ALLOC:
            return "EGL_BAD_ALLOC";
        case EGL_BAD_DISPLAY:
            return "EGL_BAD_DISPLAY";
        case EGL_NOT_INITIALIZED:
            return "EGL_NOT_INITIALIZED";
        default: {
            char hex[16];
            std::snprintf(hex, sizeof hex, "0x%04X", static_cast<unsigned>(code));
            return hex;
        }
    }
}

[[noreturn]] void unavailable(const std::string& why) {
    throw GlUnavailable("OpenGL 4.5 core is not available (EGL: " + why + ")");
}

// Surfaceless first (Mesa, no window system or device node required); then the first EGL device.
std::pair<EGLDisplay, std::string> openDisplay() {
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (client == nullptr)
        unavailable("no client extensions (EGL 1.5 or EGL_EXT_client_extensions missing)");
    if (hasExtension(client, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay d =
            eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (d != EGL_NO_DISPLAY)
            return {d, "surfaceless"};
    }
    if (hasExtension(client, "EGL_EXT_platform_device") &&
        hasExtension(client, "EGL_EXT_device_enumeration")) {
        EGLDeviceEXT devices[8];
        EGLint count = 0;
        if (eglQueryDevicesEXT(8, devices, &count) && count > 0) {
            EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[0], nullptr);
            if (d != EGL_NO_DISPLAY)
                return {d, "device"};
        }
        unavailable("no surfaceless platform and no EGL device");
    }
    unavailable("no surfaceless platform");
}

}  // namespace

std::unique_ptr<HeadlessContext> HeadlessContext::create(bool debug) {
    // AIRLIGHT_GL_DEBUG=1 asks any headless run (render, bench, report, ...) for a debug context whose
    // messages go to stderr: the way to see a driver's complaints on a machine without a window.
    const char* debugEnv = std::getenv("AIRLIGHT_GL_DEBUG");
    const bool debugFromEnv = debugEnv != nullptr && debugEnv[0] != '\0' && std::string(debugEnv) != "0";
    debug = debug || debugFromEnv;
    auto [display, platform] = openDisplay();
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor))
        unavailable("eglInitialize failed on the " + platform + " platform");
    {
        std::lock_guard lock(gDisplayMutex);
        ++gDisplayUsers[display];
    }
    std::unique_ptr<HeadlessContext> ctx(new HeadlessContext());
    ctx->mDisplay = display;
    ctx->mPlatform = platform;

    if (!eglBindAPI(EGL_OPENGL_API))
        unavailable("desktop OpenGL API not supported");
    const char* ext = eglQueryString(display, EGL_EXTENSIONS);
    if (!hasExtension(ext, "EGL_KHR_surfaceless_context"))
        unavailable("EGL_KHR_surfaceless_context missing");

    // We never draw to an EGL surface, so any OpenGL-capable config will do; without one, fall back
    // to EGL_KHR_no_config_context.
    const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint numConfigs = 0;
    if (!eglChooseConfig(display, configAttribs, &config, 1, &numConfigs) || numConfigs == 0) {
        if (!hasExtension(ext, "EGL_KHR_no_config_context"))
            unavailable("no OpenGL config");
        config = EGL_NO_CONFIG_KHR;
    }

    const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                     4,
                                     EGL_CONTEXT_MINOR_VERSION,
                                     5,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                     EGL_CONTEXT_OPENGL_DEBUG,
                                     debug ? EGL_TRUE : EGL_FALSE,
                                     EGL_NONE};
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttribs);
    if (context == EGL_NO_CONTEXT) {
        unavailable("eglCreateContext for 4.5 core failed with " + eglErrorName(eglGetError()));
    }
    ctx->mContext = context;
    ctx->makeCurrent();
    gl::requireGl45();
    if (debugFromEnv) gl::installDebugOutput();
    ctx->mRenderer = gl::contextInfo().renderer;
    return ctx;
}

HeadlessContext::~HeadlessContext() {
    destroy();
}

HeadlessContext::HeadlessContext(HeadlessContext&& other) noexcept
    : mDisplay(std::exchange(other.mDisplay, nullptr))
    , mContext(std::exchange(other.mContext, nullptr))
    , mPlatform(std::move(other.mPlatform))
    , mRenderer(std::move(other.mRenderer)) {}

HeadlessContext& HeadlessContext::operator=(HeadlessContext&& other) noexcept {
    if (this != &other) {
        destroy();
        mDisplay = std::exchange(other.mDisplay, nullptr);
        mContext = std::exchange(other.mContext, nullptr);
        mPlatform = std::move(other.mPlatform);
        mRenderer = std::move(other.mRenderer);
    }
    return *this;
}

void HeadlessContext::destroy() {
    if (mDisplay == nullptr)
        return;
    EGLDisplay display = static_cast<EGLDisplay>(mDisplay);
    if (mContext != nullptr) {
        if (eglGetCurrentContext() == static_cast<EGLContext>(mContext)) {
            gl::WorkCounters::release();
            eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        }
        eglDestroyContext(display, static_cast<EGLContext>(mContext));
    }
    std::lock_guard lock(gDisplayMutex);
    if (--gDisplayUsers[display] == 0) {
        gDisplayUsers.erase(display);
        eglTerminate(display);
    }
    mDisplay = nullptr;
    mContext = nullptr;
}

void HeadlessContext::makeCurrent() const {
    if (!eglMakeCurrent(static_cast<EGLDisplay>(mDisplay), EGL_NO_SURFACE, EGL_NO_SURFACE,
                        static_cast<EGLContext>(mContext))) {
        unavailable("eglMakeCurrent without a surface failed");
    }
}

std::string HeadlessContext::renderer() const {
    return mRenderer;
}

std::string HeadlessContext::platform() const {
    return mPlatform;
}

}  // namespace viz
