// GLFW window check. It needs a display: scripts/test.sh runs the suite under xvfb-run when there is
// none, and sets VIZ_REQUIRE_DISPLAY=1 so that a missing display fails instead of skipping.
#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "gl/context_info.h"
#include "gl/debug_output.h"
#include "gl/gl_error.h"
#include "platform/window_glfw.h"

namespace viz {
namespace {

TEST(GlWindow, OpensWithOpenGl45CoreAndPresents) {
    if (!displayAvailable()) {
        const char* require = std::getenv("VIZ_REQUIRE_DISPLAY");
        if (require != nullptr && std::string(require) == "1") FAIL() << "VIZ_REQUIRE_DISPLAY=1 but no display";
        GTEST_SKIP() << "no DISPLAY/WAYLAND_DISPLAY (try xvfb-run -a)";
    }
    std::unique_ptr<Window> window;
    try {
        window = Window::create(160, 120, "airlight window test", /*debug=*/true);
    } catch (const GlUnavailable& e) {
        FAIL() << e.what();
    }
    gl::installDebugOutput();
    gl::resetDebugErrorCount();
    const gl::ContextInfo info = gl::contextInfo();
    EXPECT_GE(info.major * 10 + info.minor, 45) << info.version;
    EXPECT_TRUE(info.core);
    EXPECT_EQ(window->framebufferSize(), glm::ivec2(160, 120));
    EXPECT_FALSE(window->shouldClose());

    // Clear the back buffer and read it before presenting: the default framebuffer works.
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, 160, 120);
    glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    float pixel[4] = {};
    glReadBuffer(GL_BACK);
    glReadPixels(80, 60, 1, 1, GL_RGBA, GL_FLOAT, pixel);
    EXPECT_NEAR(pixel[0], 0.25f, 1.0f / 255.0f);
    EXPECT_NEAR(pixel[1], 0.5f, 1.0f / 255.0f);
    EXPECT_NEAR(pixel[2], 0.75f, 1.0f / 255.0f);
    window->setTitle("airlight window test: presented");
    window->swapBuffers();
    window->pollEvents();
    std::printf("window: %s, %s\n", info.renderer.c_str(), info.version.c_str());
    EXPECT_EQ(gl::debugErrorCount(), 0);
}

}  // namespace
}  // namespace viz
