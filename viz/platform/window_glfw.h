// A GLFW window with an OpenGL 4.5 core context, current on the creating thread; GL is loaded
// through libepoxy. The interactive app uses it; tests use HeadlessContext instead.
#pragma once

#include <glm/glm.hpp>
#include <memory>
#include <string>

struct GLFWwindow;

namespace viz {

// Why no window can be opened, in one line: "no display" when neither DISPLAY nor WAYLAND_DISPLAY is
// set, "cannot connect to display ':N'" with GLFW's reason when one is set but glfwInit fails (a stale
// DISPLAY, an X server that has gone); empty when a window can be tried.
std::string displayProblem();
// displayProblem() is empty.
bool displayAvailable();

class Window {
public:
    // Throws GlUnavailable with one line when no window or no 4.5 core context can be created.
    static std::unique_ptr<Window> create(int width, int height, const std::string& title,
                                          bool debug);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    GLFWwindow* handle() { return mWindow; }
    glm::ivec2 framebufferSize() const;
    bool shouldClose() const;
    void swapBuffers();
    void pollEvents();
    void setTitle(const std::string& title);

private:
    explicit Window(GLFWwindow* window) : mWindow(window) {}
    GLFWwindow* mWindow = nullptr;
};

}  // namespace viz
