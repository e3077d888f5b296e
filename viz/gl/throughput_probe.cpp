#include "gl/throughput_probe.h"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <stdexcept>

#include "gl/framebuffer.h"
#include "gl/program.h"
#include "gl/readback.h"
#include "gl/stage_clock.h"
#include "gl/texture.h"
#include "gl/vertex_array.h"

namespace viz::gl {

namespace {

constexpr float kStep = 1.0f / 1024.0f;  // b: keeps the chains exact (probe/alu.glsl)

struct Timed {
    double median, min, max;
};

// One warm-up run, then `runs` timed runs of `draw` (prepare runs before each, outside the clock).
Timed timeRuns(StageClock& clock, int runs, const std::function<void()>& prepare, const std::function<void()>& draw) {
    prepare();
    draw();
    glFinish();
    std::vector<double> ms;
    for (int r = 0; r < runs; ++r) {
        prepare();
        clock.begin();
        draw();
        ms.push_back(clock.endMilliseconds());
    }
    std::sort(ms.begin(), ms.end());
    const std::size_t n = ms.size();
    const double median = n % 2 ? ms[n / 2] : 0.5 * (ms[n / 2 - 1] + ms[n / 2]);
    return {median, ms.front(), ms.back()};
}

}  // namespace

const ProbePass* ProbeResult::find(const std::string& id) const {
    for (const ProbePass& p : passes)
        if (p.id == id) return &p;
    return nullptr;
}

float probeAluExpected(int x, int y, int channel, int iterations) {
    const int start[4] = {x & 1023, y & 1023, (x + y) & 1023, 0};
    // Four chains from s, s + 1/4, s + 1/2, s + 3/4, each plus iterations / 1024: multiples of 1/1024.
    return (4.0f * float(start[channel]) + 1536.0f + 4.0f * float(iterations)) * kStep;
}

ProbeResult runThroughputProbe(const ProbeOptions& o, bool keepImages) {
    if (o.width < 1 || o.height < 1 || o.width > 16384 || o.height > 16384)
        throw std::invalid_argument("probe size must be 1 to 16384 pixels a side");
    // llvmpipe stops a shader invocation's loops after 65,535 iterations; the values stay exact below 2^14.
    if (o.iterations < 1 || o.iterations > 4096) throw std::invalid_argument("probe iterations must be 1 to 4096");
    if (o.layers < 1 || o.layers > 4096) throw std::invalid_argument("probe layers must be 1 to 4096");
    if (o.cellPixels < 1 || o.cellPixels > 64) throw std::invalid_argument("probe cell must be 1 to 64 pixels");
    if (o.runs < 1 || o.runs > 1000) throw std::invalid_argument("probe runs must be 1 to 1000");

    const Program compute = Program::compile({.stages = {"probe/alu.comp"}, .label = "probe.compute_alu"});
    const Program fragment =
        Program::compile({.stages = {"render/fullscreen.vert", "probe/alu.frag"}, .label = "probe.fragment_alu"});
    for (const Program* p : {&compute, &fragment}) {
        p->set("uIterations", o.iterations);
        p->set("uA", 1.0f);
        p->set("uB", kStep);
    }
    const VertexArray vao = VertexArray::create("probe.vao");
    auto target = [&](GLenum format, const char* label) {
        return Texture::create({.target = GL_TEXTURE_2D, .format = format, .size = {o.width, o.height, 1}, .label = label});
    };
    Texture rgba32f = target(GL_RGBA32F, "probe.rgba32f");
    Texture rgba16f = target(GL_RGBA16F, "probe.rgba16f");
    Framebuffer fb32 = Framebuffer::create("probe.fb32");
    fb32.attachColour(0, rgba32f);
    fb32.checkComplete();
    Framebuffer fb16 = Framebuffer::create("probe.fb16");
    fb16.attachColour(0, rgba16f);
    fb16.checkComplete();

    ProbeResult result;
    StageClock clock;
    result.clock = clock.name();
    const double pixels = double(o.width) * double(o.height);
    auto keep = [&](const Texture& t) {
        if (keepImages) result.images.push_back(readTexture(t));
    };
    auto add = [&](const char* id, const char* what, const Timed& t, double work, const char* unit) {
        result.passes.push_back({id, what, t.median, t.min, t.max, work, unit});
    };
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glViewport(0, 0, o.width, o.height);
    vao.bind();
    const double fmas = pixels * o.iterations * 16.0;
    auto nothing = [] {};

    // 1. The arithmetic as a compute pass: one invocation a pixel, 8x8 groups.
    compute.use();
    rgba32f.bindImage(0, GL_WRITE_ONLY);
    const glm::ivec3 groups = groupCount({o.width, o.height, 1}, compute.workGroupSize());
    add("compute_alu", "arithmetic per pixel, compute shader",
        timeRuns(clock, o.runs, nothing, [&] { glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1); }), fmas, "fma");
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
    keep(rgba32f);

    // 2. The same arithmetic as a fragment pass over the same target.
    glDisable(GL_BLEND);
    fb32.bind();
    fragment.use();
    add("fragment_alu", "arithmetic per pixel, fragment shader (one full-screen triangle)",
        timeRuns(clock, o.runs, nothing, [&] { glDrawArrays(GL_TRIANGLES, 0, 3); }), fmas, "fma");
    keep(rgba32f);
    if (o.arithmeticOnly) {
        Framebuffer::bindDefault();
        return result;
    }

    // 3, 4. Full-screen layers added into a float target, as slices' planes are: the blending units' cost.
    // The colour 1/256 is exact in both formats and so is the sum of up to 4096 layers in RGBA32F.
    const Program layer = Program::compile({.stages = {"render/fullscreen.vert", "probe/flat.frag"}, .label = "probe.layer"});
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
    layer.use();
    layer.set("uColour", glm::vec4(1.0f / 256.0f));
    for (const auto& [fb, tex, id] : {std::tuple{&fb32, &rgba32f, "blend_rgba32f"}, std::tuple{&fb16, &rgba16f, "blend_rgba16f"}}) {
        fb->bind();
        const std::string what = std::to_string(o.layers) + " full-screen layers added into " +
                                 (tex == &rgba32f ? "RGBA32F" : "RGBA16F") + " (slices' planes, shading left out)";
        const Timed t = timeRuns(clock, o.runs, [&] { tex->clear(glm::vec4(0.0f)); },
                                 [&] { glDrawArraysInstanced(GL_TRIANGLES, 0, 3, o.layers); });
        result.passes.push_back({id, what, t.median, t.min, t.max, pixels * o.layers, "pixels"});
        keep(*tex);
    }

    // 5. Many small triangles over the screen, each pixel covered once (polyvol's volume mesh, shading
    // left out): the rasteriser's triangle rate.
    const int cellsX = (o.width + o.cellPixels - 1) / o.cellPixels, cellsY = (o.height + o.cellPixels - 1) / o.cellPixels;
    const double triangles = 2.0 * cellsX * cellsY;
    const Program grid = Program::compile({.stages = {"probe/grid.vert", "probe/flat.frag"}, .label = "probe.grid"});
    fb32.bind();
    grid.use();
    grid.set("uCells", glm::ivec2(cellsX, cellsY));
    grid.set("uColour", glm::vec4(1.0f));
    const std::string what = std::to_string(cellsX) + "x" + std::to_string(cellsY) + " cells of " +
                             std::to_string(o.cellPixels) + " px, two triangles each (polyvol's volume mesh, shading left out)";
    const Timed t = timeRuns(clock, o.runs, [&] { rgba32f.clear(glm::vec4(0.0f)); },
                             [&] { glDrawArrays(GL_TRIANGLES, 0, GLsizei(triangles * 3)); });
    result.passes.push_back({"triangles", what, t.median, t.min, t.max, triangles, "triangles"});
    keep(rgba32f);
    glDisable(GL_BLEND);
    Framebuffer::bindDefault();
    return result;
}

ArithmeticRatio measureArithmeticRatio() {
    ProbeOptions o{.width = 512, .height = 256, .iterations = 64, .runs = 3, .arithmeticOnly = true};
    constexpr double kEnoughMilliseconds = 0.5;
    for (;;) {
        const ProbeResult r = runThroughputProbe(o);
        const double compute = r.find("compute_alu")->milliseconds, fragment = r.find("fragment_alu")->milliseconds;
        if (compute >= kEnoughMilliseconds || o.iterations >= 4096 || !(compute > 0.0)) {
            const double ratio = compute > 0.0 ? fragment / compute : 0.0;
            return {ratio, compute, fragment, o.iterations};
        }
        // Aim for twice the threshold, at least 4x the steps a try: at most four tries from 64 to 4096.
        o.iterations = std::min(4096, std::max(o.iterations * 4, int(o.iterations * 2.0 * kEnoughMilliseconds / compute)));
    }
}

std::string describeArithmeticRatio(const ArithmeticRatio& r) {
    char head[160];
    std::snprintf(head, sizeof head, "the same arithmetic takes %.3gx as long in a fragment shader as in a compute shader here",
                  r.fragmentOverCompute);
    if (!r.handicapsFragments()) return head;
    return std::string(head) +
           ": the techniques' fragment-shaded passes (every surface pass, slices' planes, polyvol's volume) pay that "
           "against the compute passes (raymarch's march, minmax, vsv and ivsv), a handicap a graphics card does not have "
           "(airlight probe)";
}

}  // namespace viz::gl
