// What the GL implementation does that our shaders must respect. llvmpipe (Mesa's CPU driver, the one
// CI runs) stops all loops of one invocation after 65,535 iterations in total, silently; techniques
// split long loops over dispatches (raymarch) or bound them. This test pins the figure down, so a Mesa
// that changes it is noticed.
#include <gtest/gtest.h>

#include <string>

#include "gl/buffer.h"
#include "gl/gl_test_fixture.h"
#include "gl/program.h"

namespace viz::gl {
namespace {

class PlatformLimits : public GlTest {};

unsigned iterationsRun(Program& program, Buffer& out, int count, int nested) {
    program.use();
    program.set("uCount", count);
    program.set("uNested", nested);
    out.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    unsigned result = 0;
    glGetNamedBufferSubData(out.id(), 0, sizeof result, &result);
    return result;
}

TEST_F(PlatformLimits, LlvmpipeCapsLoopIterationsPerInvocation) {
    Program program = Program::compile({.stages = {"test/loop_count.comp"}, .label = "test.loop_count"});
    Buffer out = Buffer::create({.bytes = 16, .flags = GL_DYNAMIC_STORAGE_BIT, .label = "test.loop_count"});
    EXPECT_EQ(iterationsRun(program, out, 60000, 0), 60000u);  // below the cap: every iteration runs
    const std::string renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const unsigned beyond = iterationsRun(program, out, 100000, 0);
    if (renderer.find("llvmpipe") != std::string::npos) {
        EXPECT_EQ(beyond, 65535u) << renderer;
        // Nested loops share the count: 6,553 outer iterations of 10 stop short of 65,535 inner ones.
        EXPECT_LT(iterationsRun(program, out, 100000, 10), 65535u);
    } else {
        EXPECT_EQ(beyond, 100000u) << renderer;
    }
}

}  // namespace
}  // namespace viz::gl
