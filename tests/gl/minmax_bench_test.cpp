// Benchmark of minmax (not run by CTest: DISABLED_; run with --gtest_also_run_disabled_tests
// --gtest_filter=MinmaxBench.*): time per stage and error against the reference for shadow maps 1024^2 to
// 4096^2 on colonnade, forest and terrain, and brute-force raymarch at equal error for the speed ratio.
// Environment: MINMAX_BENCH_SIZE=WxH (default 160x120), MINMAX_BENCH_MAPS=1024,2048,4096,
// MINMAX_BENCH_SCENES=colonnade,forest,terrain. MinmaxBench.DISABLED_PointLightEpipolarVsMarch (below) times
// point lights.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "minmax_point_scene.h"
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

// Point lights: the epipolar path (analytic, and svd at the default rank 4) against the per-pixel march it
// replaced (point_lights=march, its default 512 samples) and raymarch (the smallest power-of-two N from 64
// whose error is at most minmax's, at most 4096), on the point-light grate with the light on screen, off
// screen and behind the camera, and the built-in grate's spot (the same view as "off"; point_lights has no
// effect there). Median of 5 timed runs after a warm-up; "scatter" = the stages that compute L_air
// (minmax: rectify + mipmap + traverse; raymarch: march); "total" = every stage. Environment:
// MINMAX_BENCH_SIZES=160x120,640x480, MINMAX_BENCH_RAYMARCH_N, MINMAX_BENCH_CASES=on,off,behind,spot.
TEST_F(MinmaxBench, DISABLED_PointLightEpipolarVsMarch) {
    std::vector<std::pair<int, int>> sizes{{160, 120}, {640, 480}};
    if (const char* s = std::getenv("MINMAX_BENCH_SIZES")) {
        sizes.clear();
        std::stringstream ss(s);
        std::string item;
        while (std::getline(ss, item, ',')) {
            int w = 0, h = 0;
            if (std::sscanf(item.c_str(), "%dx%d", &w, &h) == 2) sizes.push_back({w, h});
        }
    }
    struct Timed {
        double scatter = 0.0, total = 0.0, err = 0.0;
        std::string stages;  // median ms per stage
    };
    auto timed = [&](const viz::scene::Scene& scene, const std::string& technique, const viz::Settings& settings,
                     const std::vector<std::string>& scatterStages, int w, int h, const viz::Image& reference) {
        render(scene, technique, settings, w, h);  // warm-up: shader compilation, allocations
        std::vector<double> scatter, total;
        std::vector<std::vector<double>> perStage;
        std::vector<std::string> names;
        viz::Image last;
        for (int run = 0; run < 5; ++run) {
            const viz::FrameOutput out = render(scene, technique, settings, w, h);
            double sc = 0.0, tot = 0.0;
            perStage.resize(out.timing.stages.size());
            names.resize(out.timing.stages.size());
            for (std::size_t k = 0; k < out.timing.stages.size(); ++k) {
                const auto& st = out.timing.stages[k];
                perStage[k].push_back(st.milliseconds);
                names[k] = st.stage;
                tot += st.milliseconds;
                if (std::find(scatterStages.begin(), scatterStages.end(), st.stage) != scatterStages.end())
                    sc += st.milliseconds;
            }
            scatter.push_back(sc);
            total.push_back(tot);
            last = out.airlight;
        }
        std::sort(scatter.begin(), scatter.end());
        std::sort(total.begin(), total.end());
        std::string stages;
        for (std::size_t k = 0; k < perStage.size(); ++k) {
            std::sort(perStage[k].begin(), perStage[k].end());
            char item[96];
            std::snprintf(item, sizeof item, " %s %.1f", names[k].c_str(), perStage[k][perStage[k].size() / 2]);
            stages += item;
        }
        return Timed{scatter[2], total[2], viz::testing::relativeL2(last, reference), stages};
    };
    const std::vector<std::string> minmaxStages{"minmax.rectify", "minmax.mipmap", "minmax.traverse"};
    std::printf("%-8s %-9s | %-26s | %-26s | %-26s | %-32s\n", "light", "size",
                "minmax epipolar scatter/total err", "minmax svd rank 4 scatter/total err",
                "minmax march scatter/total err", "raymarch N scatter/total err");
    for (const auto& [w, h] : sizes) {
        // "spot": the built-in grate (its spot, the "off" view) for the cost of the spot's epipolar path.
        std::vector<std::string> cases{"on", "off", "behind", "spot"};
        if (const char* list = std::getenv("MINMAX_BENCH_CASES")) {
            cases.clear();
            std::stringstream ss(list);
            std::string item;
            while (std::getline(ss, item, ',')) cases.push_back(item);
        }
        for (const std::string& camera : cases) {
            const viz::scene::Scene scene =
                camera == "spot" ? viz::scene::makeBuiltinScene("grate") : viz::testing::pointGrate(camera);
            const viz::FrameOutput reference = render(scene, "reference", {}, w, h);
            const viz::Settings map = {{"shadow_map", 1024}};
            const Timed epi = timed(scene, "minmax", map, minmaxStages, w, h, reference.airlight);
            viz::Settings march = map;
            march["point_lights"] = 1.0;
            const Timed old = timed(scene, "minmax", march, minmaxStages, w, h, reference.airlight);
            viz::Settings svdSettings = map;
            svdSettings["integrand"] = 1.0;
            const Timed svd = timed(scene, "minmax", svdSettings, minmaxStages, w, h, reference.airlight);
            Timed rm;
            int n = 64, nMax = 4096;
            // MINMAX_BENCH_RAYMARCH_N=N times raymarch at N only (large images: the search is slow).
            if (const char* fixed = std::getenv("MINMAX_BENCH_RAYMARCH_N")) n = nMax = std::atoi(fixed);
            for (; n <= nMax; n *= 2) {
                rm = timed(scene, "raymarch", {{"samples", n}, {"shadow_map", 1024}}, {"raymarch.march"}, w, h,
                           reference.airlight);
                if (rm.err <= epi.err) break;
            }
            std::printf("%-8s %4dx%-4d | %8.1f %8.1f %7.4f | %8.1f %8.1f %7.4f | %8.1f %8.1f %7.4f | "
                        "%5d %8.1f %8.1f %7.4f\n",
                        camera.c_str(), w, h, epi.scatter, epi.total, epi.err, svd.scatter, svd.total, svd.err,
                        old.scatter, old.total, old.err, std::min(n, nMax), rm.scatter, rm.total, rm.err);
            std::printf("    stages, epipolar:%s\n    stages, march:%s\n", epi.stages.c_str(), old.stages.c_str());
            std::fflush(stdout);
        }
    }
}
