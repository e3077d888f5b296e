// Benchmark (disabled by default; never a pass/fail test): the two StageClock methods on one
// workload, a 512x512 fullscreen fragment loop of 256 steps. On llvmpipe GPU timer queries report a
// fraction of the wall time, which is why StageClock uses glFinish+steady_clock there. Run with
//   viz_gl_tests --gtest_also_run_disabled_tests --gtest_filter='*ClockBench*'
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "gl/gl.h"
#include "gl/gl_test_fixture.h"

namespace viz::gl {
namespace {

using ClockBench = GlTest;

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

TEST_F(ClockBench, DISABLED_FinishSteadyClockVersusTimeElapsed) {
    const int size = 512, steps = 256, runs = 5;
    Texture target =
        Texture::create({.format = GL_RGBA32F, .size = {size, size, 1}, .label = "bench.target"});
    Framebuffer fb = Framebuffer::create("bench.fb");
    fb.attachColour(0, target);
    fb.checkComplete();
    VertexArray vao = VertexArray::create("bench.vao");
    Program p = Program::compile(
        {.stages = {"test/fullscreen.vert", "test/loop.frag"}, .label = "bench.loop"});
    p.set("uSteps", steps);
    fb.bind();
    glViewport(0, 0, size, size);
    vao.bind();
    p.use();
    auto draw = [] { glDrawArrays(GL_TRIANGLES, 0, 3); };
    draw();  // warm-up: shader JIT and first-touch allocation
    glFinish();

    std::vector<double> wall, query, queryInsideWall;
    StageClock finishClock(ClockMethod::FinishSteadyClock);
    StageClock queryClock(ClockMethod::TimestampQuery);
    for (int i = 0; i < runs; ++i) {
        finishClock.begin();
        draw();
        wall.push_back(finishClock.endMilliseconds());

        queryClock.begin();
        draw();
        query.push_back(queryClock.endMilliseconds());

        // The same draw measured by both at once: the query nested inside the glFinish bracket.
        finishClock.begin();
        queryClock.begin();
        draw();
        queryInsideWall.push_back(queryClock.endMilliseconds());
        wall.push_back(finishClock.endMilliseconds());
    }
    Framebuffer::bindDefault();
    const double wallMs = median(wall), queryMs = median(query), nestedMs = median(queryInsideWall);
    std::printf("renderer: %s\n", context()->renderer().c_str());
    std::printf("StageClock::method(): %s\n", StageClock::method().c_str());
    std::printf("workload: %dx%d fullscreen fragment loop, %d steps, median of %d runs\n", size,
                size, steps, runs);
    std::printf("glFinish+steady_clock: %.2f ms\n", wallMs);
    std::printf("GL_TIMESTAMP pair:     %.2f ms (nested in the glFinish bracket: %.2f ms)\n",
                queryMs, nestedMs);
    RecordProperty("finish_steady_ms", std::to_string(wallMs));
    RecordProperty("time_elapsed_ms", std::to_string(queryMs));
}

}  // namespace
}  // namespace viz::gl
