// Runs a test compute shader of tests/data/math over a list of cases: the GLSL side of the tests that
// check shader math against an independent double computation (airlight_glsl_test.cpp,
// vpl_cell_test.cpp). Needs a current GL context (gl::GlTest).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl/buffer.h"
#include "gl/program.h"

namespace viz::testing {

// Runs tests/data/math/FILE over `count` cases (its inputs at binding 0, uCount, 64 per work group) and
// returns one Output per case (binding 1).
template <typename Output>
std::vector<Output> runCaseShader(const char* file, const std::vector<glm::vec4>& inputs, int count) {
    gl::Buffer inBuffer = gl::Buffer::create(
        {.bytes = inputs.size() * sizeof(glm::vec4), .data = inputs.data(), .label = "test.case_inputs"});
    gl::Buffer outBuffer =
        gl::Buffer::create({.bytes = std::size_t(count) * sizeof(Output), .label = "test.case_outputs"});
    const std::string shader = std::string(VIZ_TEST_DATA_DIR) + "/math/" + file;
    gl::Program program = gl::Program::compile({.stages = {shader}, .label = file});
    program.use();
    program.set("uCount", count);
    inBuffer.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
    outBuffer.bindBase(GL_SHADER_STORAGE_BUFFER, 1);
    glDispatchCompute(GLuint((count + 63) / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    return outBuffer.download<Output>();
}

}  // namespace viz::testing
