// Benchmark of minmax (not run by CTest: DISABLED_; run with --gtest_also_run_disabled_tests
// --gtest_filter=MinmaxBench.*): time per stage and error against the reference for shadow maps 1024^2 to
// 4096^2 on colonnade, forest and terrain, and brute-force raymarch at equal error for the speed ratio.
// Environment: MINMAX_BENCH_SIZE=WxH (default 160x120), MINMAX_BENCH_MAPS=1024,2048,4096,
// MINMAX_BENCH_SCENES=colonnade,forest,terrain.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "technique_test_util.h"
#include "scene/builtin_scenes.h"

namespace {

class MinmaxBench : public viz::testing::TechniqueTest {};

double stageMs(const viz::FrameOutput& out, const std::string& id) {
    for (const auto& s : out.timing.stages)
        if (s.stage == id) return s.milliseconds;
    return 0.0;
}

}  // namespace

TEST_F(MinmaxBench, DISABLED_StagesErrorAndRaymarchAtEqualError) {
    int w = 160, h = 120;
    if (const char* s = std::getenv("MINMAX_BENCH_SIZE")) std::sscanf(s, "%dx%d", &w, &h);
    std::vector<int> maps{1024, 2048, 4096};
    if (const char* s = std::getenv("MINMAX_BENCH_MAPS")) {
        maps.clear();
        std::stringstream ss(s);
        std::string item;
        while (std::getline(ss, item, ',')) maps.push_back(std::atoi(item.c_str()));
    }
    std::vector<std::string> scenes{"colonnade", "forest", "terrain"};
    if (const char* s = std::getenv("MINMAX_BENCH_SCENES")) {
        scenes.clear();
        std::stringstream ss(s);
        std::string item;
        while (std::getline(ss, item, ',')) scenes.push_back(item);
    }
    std::printf("%-10s %5s %-8s | %8s %8s %8s %8s | %7s | %6s %9s %7s | %6s\n", "scene", "map", "integr.",
                "shadow", "rectify", "mipmap", "traverse", "err", "rm N", "rm march", "rm err", "speed");
    for (const std::string& sceneName : scenes) {
        const char* name = sceneName.c_str();
        const viz::scene::Scene scene = viz::scene::makeBuiltinScene(sceneName);
        const viz::FrameOutput reference = render(scene, "reference", {}, w, h);
        for (int map : maps) {
            for (int integrand : {0, 1}) {
                // Warm-up run (shader compilation), then the timed one.
                render(scene, "minmax", {{"shadow_map", map}, {"integrand", integrand}}, w, h);
                const viz::FrameOutput out = render(scene, "minmax", {{"shadow_map", map}, {"integrand", integrand}}, w, h);
                const double err = viz::testing::relativeL2(out.airlight, reference.airlight);
                const double scatter = stageMs(out, "minmax.rectify") + stageMs(out, "minmax.mipmap") +
                                       stageMs(out, "minmax.traverse");
                // Smallest power-of-two N whose raymarch error is at most minmax's.
                int n = 8;
                double rmErr = 1e9, rmMs = 0.0;
                for (; n <= 16384; n *= 2) {
                    render(scene, "raymarch", {{"samples", n}, {"shadow_map", map}}, w, h);
                    const viz::FrameOutput rm = render(scene, "raymarch", {{"samples", n}, {"shadow_map", map}}, w, h);
                    rmErr = viz::testing::relativeL2(rm.airlight, reference.airlight);
                    rmMs = stageMs(rm, "raymarch.march");
                    if (rmErr <= err) break;
                }
                std::printf("%-10s %5d %-8s | %8.1f %8.1f %8.1f %8.1f | %7.4f | %6d %9.1f %7.4f | %5.1fx%s\n", name, map,
                            integrand ? "svd" : "analytic", stageMs(out, "minmax.shadow_maps"),
                            stageMs(out, "minmax.rectify"), stageMs(out, "minmax.mipmap"),
                            stageMs(out, "minmax.traverse"), err, n, rmMs, rmErr, rmMs / scatter,
                            rmErr <= err ? "" : " (raymarch never reached it)");
                std::fflush(stdout);
            }
        }
    }
}
