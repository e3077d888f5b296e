// gl::runThroughputProbe: what the current GL renderer does per millisecond with the kinds of work the
// techniques are made of, each kind alone: the same arithmetic per pixel as a compute pass and as a
// fragment pass, full-screen layers blended additively into float targets (slices' planes), and many
// small triangles (polyvol's volume mesh). A renderer whose fragment passes run the same arithmetic many
// times slower than its compute passes (a compute accelerator with few graphics units) favours the
// techniques built on compute passes (raymarch's march, minmax, vsv), whatever the papers measured on
// graphics cards; `airlight probe` prints it beside the renderer's name.
#pragma once

#include <string>
#include <vector>

#include "core/image.h"

namespace viz::gl {

struct ProbeOptions {
    int width = 1920, height = 1080;
    int iterations = 1024;  // arithmetic steps per pixel (16 fused multiply-adds a step)
    int layers = 128;       // full-screen layers per blending pass (slices' default plane count)
    int cellPixels = 2;     // the triangle grid's cell, pixels a side (two triangles a cell)
    int runs = 5;           // timed runs per pass, after one warm-up run
    bool arithmeticOnly = false;  // the two arithmetic passes alone
};

struct ProbePass {
    std::string id;       // compute_alu, fragment_alu, blend_rgba32f, blend_rgba16f, triangles
    std::string what;     // one line for people
    double milliseconds;  // median of the timed runs
    double minMilliseconds, maxMilliseconds;
    double work;          // in `unit`
    std::string unit;     // "fma", "pixels", "triangles"
    // work per second, in thousands of millions (1e9) of the unit
    double ratePerSecond() const { return milliseconds > 0.0 ? work / (milliseconds * 1e-3) : 0.0; }
};

struct ProbeResult {
    std::vector<ProbePass> passes;
    std::string clock;  // gl::StageClock's method
    // Each pass's target after its last run (filled only when asked: the tests check them against the
    // closed forms): the arithmetic passes' value per pixel, the blended sum, the triangles' coverage.
    std::vector<Image> images;
    const ProbePass* find(const std::string& id) const;
};

// Needs a current GL 4.5 context. Throws std::invalid_argument for options out of range.
ProbeResult runThroughputProbe(const ProbeOptions& options, bool keepImages = false);

// How many times as long the same arithmetic takes in a fragment shader as in a compute shader on the
// current renderer, measured quickly enough for the start of a report or a bench: 512x256 pixels, 64
// steps a pixel, the steps raised (to at most 4096) until the compute pass takes 0.5 ms, so that a GPU's
// fixed cost per pass does not set the ratio. Needs a current GL 4.5 context; leaves blending off and
// the default framebuffer bound.
struct ArithmeticRatio {
    double fragmentOverCompute = 0.0;
    double computeMilliseconds = 0.0, fragmentMilliseconds = 0.0;
    int iterations = 0;
    // Far enough above 1 that the fragment-shaded passes lose against the compute passes on this renderer.
    bool handicapsFragments() const { return fragmentOverCompute > 2.0; }
};
ArithmeticRatio measureArithmeticRatio();

// One line for people: the ratio, and where it handicaps them what it means for the techniques' fragment-shaded passes.
std::string describeArithmeticRatio(const ArithmeticRatio& ratio);

// The value probe/alu.glsl gives pixel (x, y) (GL window coordinates) with a = 1, b = 1/1024: exact.
float probeAluExpected(int x, int y, int channel, int iterations);

}  // namespace viz::gl
