#include "platform/window_glfw.h"

#include <cstdlib>
#include <string>

#include <epoxy/gl.h>
// GL comes from epoxy; GLFW must not include a GL header of its own.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "gl/gl_error.h"
#include "gl/work_counters.h"

namespace viz {

namespace {

// GLFW reports errors through a callback; keep the last one so a failure can be explained in one
// line.
std::string gLastGlfwError;

void onGlfwError(int /*code*/, const char* description) {
    gLastGlfwError = description ? description : "";
}

bool initGlfw() {
    glfwSetErrorCallback(onGlfwError);
    return glfwInit() == GLFW_TRUE;
}

}  // namespace

std::string displayProblem() {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    const bool hasX11 = x11 != nullptr && x11[0] != '\0';
    const bool hasWayland = wayland != nullptr && wayland[0] != '\0';
    if (!hasX11 && !hasWayland) return "no display";
    gLastGlfwError.clear();
    if (initGlfw()) return "";
    const std::string name = hasX11 ? std::string(x11) : std::string(wayland);
    return "cannot connect to display '" + name + "'" +
           (gLastGlfwError.empty() ? std::string() : " (GLFW: " + gLastGlfwError + ")");
}

bool displayAvailable() { return displayProblem().empty(); }

std::unique_ptr<Window> Window::create(int width, int height, const std::string& title,
                                       bool debug) {
    if (!initGlfw())
        throw GlUnavailable("cannot open a window: " + gLastGlfwError);
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, debug ? GLFW_TRUE : GLFW_FALSE);
    gLastGlfwError.clear();
    GLFWwindow* window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (window == nullptr) {
        throw GlUnavailable(
            "OpenGL 4.5 core is not available (GLFW: " +
            (gLastGlfwError.empty() ? std::string("window creation failed") : gLastGlfwError) +
            ")");
    }
    std::unique_ptr<Window> result(new Window(window));
    glfwMakeContextCurrent(window);
    gl::requireGl45();
    return result;
}

Window::~Window() {
    if (mWindow != nullptr) {
        if (glfwGetCurrentContext() == mWindow) gl::WorkCounters::release();
        glfwDestroyWindow(mWindow);
    }
}

glm::ivec2 Window::framebufferSize() const {
    glm::ivec2 size{0};
    glfwGetFramebufferSize(mWindow, &size.x, &size.y);
    return size;
}

bool Window::shouldClose() const {
    return glfwWindowShouldClose(mWindow) == GLFW_TRUE;
}

void Window::swapBuffers() {
    glfwSwapBuffers(mWindow);
}

void Window::pollEvents() {
    glfwPollEvents();
}

void Window::setTitle(const std::string& title) {
    glfwSetWindowTitle(mWindow, title.c_str());
}

}  // namespace viz
