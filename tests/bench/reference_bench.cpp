// Benchmark (not a test): `reference` on a scene (default grate) at 160x120, cache off, median of N runs.
// Usage: reference_bench [scene] [width height] [threads] [runs]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/error.h"
#include "scene/scene_source.h"
#include "techniques/reference/reference.h"

int main(int argc, char** argv) {
    try {
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
        in.settings = viz::completeSettings(*tech, {{"cache", 0}, {"threads", threads}});
        std::vector<double> totals;
        for (int r = 0; r < runs; ++r) {
            const viz::FrameOutput out = tech->run(in);
            std::printf("run %d:", r + 1);
            for (const auto& s : out.timing.stages) std::printf("  %s %.0f ms", s.stage.c_str(), s.milliseconds);
            std::printf("  total %.0f ms\n", out.timing.totalMilliseconds());
            totals.push_back(out.timing.totalMilliseconds());
        }
        std::sort(totals.begin(), totals.end());
        std::printf("reference on %s at %dx%d, threads %g: median of %d = %.2f s\n", name.c_str(), width, height,
                    threads, runs, totals[totals.size() / 2] / 1000.0);
        return 0;
    } catch (const viz::InputError& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 2;
    }
}
