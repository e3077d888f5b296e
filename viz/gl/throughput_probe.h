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

// The value probe/alu.glsl gives pixel (x, y) (GL window coordinates) with a = 1, b = 1/1024: exact.
float probeAluExpected(int x, int y, int channel, int iterations);

}  // namespace viz::gl
