#include "probe_command.h"

#include <cstdio>
#include <filesystem>

#include "core/atomic_file.h"
#include "core/error.h"
#include "gl/context_info.h"
#include "gl/throughput_probe.h"
#include "platform/context_egl.h"
#include "report/text_output.h"
#include "run_info.h"

namespace airlight {

using viz::InputError;

namespace {

constexpr const char* kProbeHelp = R"(usage: airlight probe [--size WxH] [--iterations N] [--layers N] [--cell PX] [--runs N] [--out FILE.csv]

Measures what the GL renderer does per second with each kind of work the techniques are made of, one
kind at a time (median of N timed runs after a warm-up, on the clock the measuring commands use):
  compute_alu    N steps of arithmetic per pixel (16 fused multiply-adds a step) in a compute shader
                 (raymarch's march, minmax's and vsv's passes are compute passes)
  fragment_alu   the same arithmetic in a fragment shader over one full-screen triangle
                 (slices' planes, polyvol's volume and the surface pass are fragment passes)
  blend_rgba32f  full-screen layers added into an RGBA32F target, shading left out (slices' planes)
  blend_rgba16f  the same into RGBA16F
  triangles      a grid of small triangles covering the image once (polyvol's volume mesh)
and the ratio of the two arithmetic passes: near 1 on a graphics card and on a CPU rasteriser; far above
1 on a compute accelerator with few graphics units, where every fragment-shaded technique is slower than
its paper's graphics card would make it, and compute-shaded ones are not.

  --size WxH       image size (default 1920x1080; 640x480 on a software renderer)
  --iterations N   arithmetic steps per pixel, 1 to 4096 (default 1024; 256 on a software renderer)
  --layers N       layers per blending pass, 1 to 4096 (default 128, slices' default plane count)
  --cell PX        the triangle grid's cell, 1 to 64 pixels a side (default 2)
  --runs N         timed runs per pass, 1 to 1000 (default 5)
  --out FILE.csv   also write the figures as CSV (pass, ms, min_ms, max_ms, work, unit, rate_per_s,
                   clock, renderer, width, height)
)";

// "21 G fma/s", "1.87 M triangles/s".
std::string rateText(double perSecond, const std::string& unit) {
    const bool giga = perSecond >= 1e9;
    char text[64];
    std::snprintf(text, sizeof text, "%.3g %s %s/s", perSecond * (giga ? 1e-9 : 1e-6), giga ? "G" : "M", unit.c_str());
    return text;
}

}  // namespace

int runProbeCommand(Args& args) {
    if (!args.empty() && isHelpFlag(args.peek())) {
        std::fputs(kProbeHelp, stdout);
        return 0;
    }
    viz::gl::ProbeOptions o;
    bool sizeGiven = false, iterationsGiven = false;
    std::string out;
    while (!args.empty()) {
        const std::string flag = args.take();
        if (flag == "--size") {
            const glm::ivec2 size = parseSize(args.next(flag));
            o.width = size.x, o.height = size.y;
            sizeGiven = true;
        } else if (flag == "--iterations") {
            o.iterations = parseWholeNumber(args.next(flag), flag, 1, 4096);
            iterationsGiven = true;
        } else if (flag == "--layers") o.layers = parseWholeNumber(args.next(flag), flag, 1, 4096);
        else if (flag == "--cell") o.cellPixels = parseWholeNumber(args.next(flag), flag, 1, 64);
        else if (flag == "--runs") o.runs = parseWholeNumber(args.next(flag), flag, 1, 1000);
        else if (flag == "--out") {
            out = args.next(flag);
            if (std::filesystem::path(out).extension() != ".csv") throw InputError("--out must name a .csv file, not '" + out + "'");
            if (std::filesystem::is_directory(out)) throw InputError("--out '" + out + "' is a folder; name a .csv file");
        } else throw InputError("unknown option '" + flag + "' for 'probe' (run 'airlight probe --help')");
    }
    if (o.width > 16384 || o.height > 16384) throw InputError("--size must be at most 16384 pixels a side");

    auto context = viz::HeadlessContext::create(false);
    const std::string renderer = rendererDescription();
    if (viz::gl::isSoftwareRenderer(viz::gl::contextInfo().renderer)) {
        if (!sizeGiven) o.width = 640, o.height = 480;
        if (!iterationsGiven) o.iterations = 256;
    }
    std::printf("renderer: %s\nmachine: %s\n", renderer.c_str(), machineDescription().c_str());
    std::printf("%dx%d, %d arithmetic steps a pixel, %d layers, %d px cells; median of %d runs after a warm-up\n", o.width,
                o.height, o.iterations, o.layers, o.cellPixels, o.runs);
    std::fflush(stdout);
    const viz::gl::ProbeResult result = viz::gl::runThroughputProbe(o);

    std::printf("%-14s %10s %12s  %-22s  %s\n", "pass", "ms", "(min-max)", "rate", "what");
    std::string csv = "pass,ms,min_ms,max_ms,work,unit,rate_per_s,clock,renderer,width,height\n";
    for (const viz::gl::ProbePass& p : result.passes) {
        char range[48];
        std::snprintf(range, sizeof range, "%.3g-%.3g", p.minMilliseconds, p.maxMilliseconds);
        std::printf("%-14s %10.3f %12s  %-22s  %s\n", p.id.c_str(), p.milliseconds, range,
                    rateText(p.ratePerSecond(), p.unit).c_str(), p.what.c_str());
        char figures[160];
        std::snprintf(figures, sizeof figures, "%.6g,%.6g,%.6g,%.6g,", p.milliseconds, p.minMilliseconds,
                      p.maxMilliseconds, p.work);
        char rate[32];
        std::snprintf(rate, sizeof rate, "%.6g", p.ratePerSecond());
        csv += p.id + "," + figures + p.unit + "," + rate + "," + viz::report::csvField(result.clock) + "," +
               viz::report::csvField(renderer) + "," + std::to_string(o.width) + "," + std::to_string(o.height) + "\n";
    }
    const viz::gl::ProbePass* c = result.find("compute_alu");
    const viz::gl::ProbePass* f = result.find("fragment_alu");
    if (c && f && c->milliseconds > 0.0)
        std::printf("fragment_alu / compute_alu = %.2f: the same arithmetic per pixel takes %.2fx as long in a fragment shader "
                    "as in a compute shader (clock: %s)\n",
                    f->milliseconds / c->milliseconds, f->milliseconds / c->milliseconds, result.clock.c_str());
    if (!out.empty()) {
        if (const std::string why = viz::writeFileAtomically(out, csv); !why.empty()) throw InputError(why);
        std::printf("wrote %s\n", out.c_str());
    }
    return 0;
}

}  // namespace airlight
