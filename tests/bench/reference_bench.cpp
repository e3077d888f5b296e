// Benchmark (not a test): `reference` on a scene (default grate) at 160x120, cache off, median of N runs.
// Usage: reference_bench [scene] [width height] [threads] [runs]
//        reference_bench --convergence scene width height threads runs n1,n2,... [outdir]
// The second form renders with area_samples = each n, prints the median time of each, and the relative
// L2 (||x - x_last|| / ||x_last|| over every channel) and max abs difference of L_air and of the final
// image of each against the last n; with outdir, also writes outdir/airlight_<n>.exr and final_<n>.exr.
//        reference_bench --compare test.exr reference.exr
// The third form prints the same figures for two images (e.g. another technique against the reference).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/image_io.h"
#include "scene/scene_source.h"
#include "techniques/reference/reference.h"

namespace {

struct Run {
    int samples = 0;
    double seconds = 0.0;
    viz::Image airlight, final;
};

struct Difference {
    double relativeL2 = 0.0, maxAbs = 0.0;
    int x = 0, y = 0;
};

Difference difference(const viz::Image& a, const viz::Image& b) {
    Difference d;
    double num = 0.0, den = 0.0;
    for (int y = 0; y < b.height; ++y) {
        for (int x = 0; x < b.width; ++x) {
            for (int c = 0; c < b.channels; ++c) {
                const double e = double(a.at(x, y, c)) - double(b.at(x, y, c));
                num += e * e;
                den += double(b.at(x, y, c)) * double(b.at(x, y, c));
                if (std::abs(e) > d.maxAbs) {
                    d.maxAbs = std::abs(e);
                    d.x = x;
                    d.y = y;
                }
            }
        }
    }
    d.relativeL2 = den > 0.0 ? std::sqrt(num / den) : 0.0;
    return d;
}

double medianRun(viz::Technique& tech, viz::FrameInput& in, int runs, viz::FrameOutput& last) {
    std::vector<double> totals;
    for (int r = 0; r < runs; ++r) {
        last = tech.run(in);
        std::printf("run %d:", r + 1);
        for (const auto& s : last.timing.stages) std::printf("  %s %.0f ms", s.stage.c_str(), s.milliseconds);
        std::printf("  total %.0f ms\n", last.timing.totalMilliseconds());
        std::fflush(stdout);
        totals.push_back(last.timing.totalMilliseconds());
    }
    std::sort(totals.begin(), totals.end());
    return totals[totals.size() / 2] / 1000.0;
}

int compare(int argc, char** argv) {
    if (argc < 4) throw viz::InputError("usage: reference_bench --compare test.exr reference.exr");
    const viz::Image test = viz::readImage(argv[2]), ref = viz::readImage(argv[3]);
    if (test.width != ref.width || test.height != ref.height || test.channels != ref.channels)
        throw viz::InputError("the two images differ in size or channels");
    const Difference d = difference(test, ref);
    std::printf("relative L2 %.4e, max abs %.4e at (%d,%d)\n", d.relativeL2, d.maxAbs, d.x, d.y);
    return 0;
}

int convergence(int argc, char** argv) {
    if (argc < 8) throw viz::InputError("usage: reference_bench --convergence scene width height threads runs n1,n2,...");
    const viz::scene::Scene scene = viz::scene::loadScene(argv[2]);
    const int width = std::atoi(argv[3]), height = std::atoi(argv[4]);
    const double threads = std::atof(argv[5]);
    const int runs = std::max(1, std::atoi(argv[6]));
    std::vector<int> samples;
    std::stringstream list(argv[7]);
    for (std::string item; std::getline(list, item, ',');) samples.push_back(std::atoi(item.c_str()));
    if (samples.empty()) throw viz::InputError("no area_samples given");
    auto tech = viz::makeReferenceTechnique();
    std::vector<Run> results;
    for (int n : samples) {
        viz::FrameInput in;
        in.scene = &scene;
        in.width = width;
        in.height = height;
        viz::setRunSettings(in, viz::completeSettings(*tech, {{"cache", 0}, {"threads", threads}, {"area_samples", double(n)}}));
        viz::FrameOutput out;
        std::printf("area_samples %d\n", n);
        Run run;
        run.samples = n;
        run.seconds = medianRun(*tech, in, runs, out);
        run.airlight = out.airlight;
        run.final = out.final;
        if (argc > 8) {
            viz::writeImage(run.airlight, std::string(argv[8]) + "/airlight_" + std::to_string(n) + ".exr");
            viz::writeImage(run.final, std::string(argv[8]) + "/final_" + std::to_string(n) + ".exr");
        }
        results.push_back(std::move(run));
    }
    const Run& best = results.back();
    std::printf("\n%s at %dx%d, threads %g, median of %d; differences to area_samples %d\n", argv[2], width, height,
                threads, runs, best.samples);
    std::printf("| area_samples | time (s) | L_air rel. L2 | L_air max abs (pixel) | final rel. L2 | final max abs (pixel) |\n");
    std::printf("|---|---|---|---|---|---|\n");
    for (const Run& r : results) {
        const Difference a = difference(r.airlight, best.airlight), f = difference(r.final, best.final);
        std::printf("| %d | %.2f | %.2e | %.2e (%d,%d) | %.2e | %.2e (%d,%d) |\n", r.samples, r.seconds, a.relativeL2,
                    a.maxAbs, a.x, a.y, f.relativeL2, f.maxAbs, f.x, f.y);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        if (argc > 1 && std::string(argv[1]) == "--convergence") return convergence(argc, argv);
        if (argc > 1 && std::string(argv[1]) == "--compare") return compare(argc, argv);
        const std::string name = argc > 1 ? argv[1] : "grate";
        const int width = argc > 3 ? std::atoi(argv[2]) : 160;
        const int height = argc > 3 ? std::atoi(argv[3]) : 120;
        const double threads = argc > 4 ? std::atof(argv[4]) : 2.0;
        const int runs = argc > 5 ? std::max(1, std::atoi(argv[5])) : 3;
        const viz::scene::Scene scene = viz::scene::loadScene(name);
        auto tech = viz::makeReferenceTechnique();
        viz::FrameInput in;
        in.scene = &scene;
        in.width = width;
        in.height = height;
        viz::setRunSettings(in, viz::completeSettings(*tech, {{"cache", 0}, {"threads", threads}}));
        viz::FrameOutput out;
        const double median = medianRun(*tech, in, runs, out);
        std::printf("reference on %s at %dx%d, threads %g: median of %d = %.2f s\n", name.c_str(), width, height,
                    threads, runs, median);
        return 0;
    } catch (const viz::InputError& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 2;
    }
}
