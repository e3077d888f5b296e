#include "bench_command.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>

#include "core/error.h"
#include "core/image_io.h"
#include "core/staged_folder.h"
#include "debug/technique.h"
#include "platform/context_egl.h"
#include "plot/plot.h"
#include "report/bench_table.h"
#include "run_info.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_source.h"
#include "techniques/registry.h"
#include "ui/offscreen.h"

namespace airlight {

using viz::InputError;

namespace {

constexpr const char* kBenchHelp = R"(usage: airlight bench [--scenes A,B] [--techniques T1,T2] [--axes size,shadow_map,vpls,triangles]
                      [--size WxH] [--runs N] [--set name=value]... [--quick] --out DIR

Measures how each technique's cost per stage grows as one kind of work grows, everything else fixed at
the defaults: the median of N timed runs after one warm-up run, per stage, with the clock named (GL timer
queries on a GPU; glFinish and a steady clock on a software renderer). Writes DIR/bench.csv (scene,
technique, axis, value, stage, ms, clock, renderer, work, runs, wall_ms: the stage's CPU wall time from its start
until its GPU time was known), DIR/bench.html with a log-log plot per
axis and a fitted exponent k per technique and stage (cost ~ work^k), and the plots as PNG.

  --scenes      built-in scene names or glTF paths, comma-separated (a path with a comma in its name
                stays whole when that file exists), for every axis (default: grate
                for size, shadow_map and triangles; tv-room, the scene with an area light, for vpls)
  --techniques  comma-separated (default: every technique but the CPU reference)
  --axes        which kinds of work to grow (default: all four):
                  size        image size 160x120, 320x240, 640x480, 1280x720, 1920x1080 (work: pixels)
                  shadow_map  256^2 to 4096^2, techniques with a shadow_map setting (work: texels)
                  vpls        1 to 256 virtual point lights, ivsv on scenes with an area light
                  triangles   the scene generator's detail 1x to 100x (grate's bars, forest's trees,
                              terrain's heightfield; work: triangles)
  --sizes LIST  the size axis's points instead (WxH,WxH,...)
  --size WxH    the image size of the other axes (default 640x480; 160x120 with --quick)
  --runs N      timed runs per point (default 5; 3 with --quick)
  --set name=value  a parameter on top of the defaults, for every technique that has it (an axis's own
                value still wins); e.g. --set integrand=svd to time minmax's other integrand
  --quick       fewer, smaller points: sizes 160x120, 240x180, 320x240; shadow maps 256 to 1024;
                4 to 64 VPLs; detail 1 and 10; the other axes at 160x120; 3 runs)
)";

struct Options {
    std::vector<std::string> scenes, techniques, axes;  // scenes empty: each axis's default scene
    int width = 0, height = 0;
    std::vector<glm::ivec2> sizes;  // --sizes: the size axis's points
    int runs = 0;
    bool quick = false;
    std::string out;
    std::vector<std::string> sets;  // --set as given ("name=value")
    // --set per technique: the parameters it has, a named value as it declares it (epipole=paper is 2 in
    // vsv, 1 in ivsv).
    std::map<std::string, viz::Settings> settings;
};

Options parseBenchOptions(Args& args) {
    Options o;
    while (!args.empty()) {
        const std::string flag = args.take();
        if (flag == "--scenes") o.scenes = splitSceneList(args.next(flag), flag);
        else if (flag == "--techniques") o.techniques = splitList(args.next(flag), flag);
        else if (flag == "--axes") o.axes = splitList(args.next(flag), flag);
        else if (flag == "--size") {
            const glm::ivec2 size = parseSize(args.next(flag));
            o.width = size.x, o.height = size.y;
        } else if (flag == "--sizes") {
            for (const std::string& item : splitList(args.next(flag), flag)) o.sizes.push_back(parseSize(item));
        } else if (flag == "--runs") {
            o.runs = parseWholeNumber(args.next(flag), flag, 1, 1000);
        } else if (flag == "--quick") o.quick = true;
        else if (flag == "--out") o.out = args.next(flag);
        else if (flag == "--set") o.sets.push_back(args.next(flag));
        else throw InputError("unknown option '" + flag + "' for 'bench' (run 'airlight bench --help')");
    }
    if (o.out.empty()) throw InputError("bench needs --out DIR (the folder to write bench.csv and bench.html into)");
    if (o.techniques.empty())
        for (const std::string& t : viz::techniqueIds())
            if (t != "reference") o.techniques.push_back(t);
    if (o.axes.empty())
        for (const auto& a : viz::report::benchAxes()) o.axes.push_back(a.id);
    for (const std::string& a : o.axes)
        if (!viz::report::findBenchAxis(a)) {
            std::string known;
            for (const auto& k : viz::report::benchAxes()) known += (known.empty() ? "" : ", ") + k.id;
            throw InputError("--axes: unknown axis '" + a + "' (known: " + known + ")");
        }
    if (!o.width) {
        o.width = o.quick ? 160 : 640;
        o.height = o.quick ? 120 : 480;
    }
    if (!o.runs) o.runs = o.quick ? 3 : 5;
    SettingsByTechnique given = settingsByTechnique(o.sets, o.techniques, "none of the techniques measured has that parameter");
    for (const std::string& id : o.techniques)
        if (const std::string* refused = firstRefusal(given.errors, id)) throw InputError(*refused);  // never measured without it
    o.settings = std::move(given.settings);
    return o;
}

// One point of an axis: what the user would set, and what changes in the run.
struct AxisPoint {
    std::string value;
    int width = 0, height = 0;
    viz::Settings settings;  // on top of the technique's defaults
    double detail = 1.0;     // the scene generator's detail (triangles axis)
};

// The axis's points within what the technique accepts (`limit`: the maximum of its setting, 0 for none).
std::vector<AxisPoint> axisPoints(const std::string& axis, const Options& o, double limit) {
    std::vector<AxisPoint> points;
    if (axis == "size") {
        std::vector<glm::ivec2> sizes = o.quick ? std::vector<glm::ivec2>{{160, 120}, {240, 180}, {320, 240}}
                                                : std::vector<glm::ivec2>{{160, 120}, {320, 240}, {640, 480}, {1280, 720}, {1920, 1080}};
        if (!o.sizes.empty()) sizes = o.sizes;
        for (glm::ivec2 s : sizes) points.push_back({std::to_string(s.x) + "x" + std::to_string(s.y), s.x, s.y, {}, 1.0});
        return points;
    }
    std::vector<int> values;
    if (axis == "shadow_map") values = o.quick ? std::vector<int>{256, 512, 1024} : std::vector<int>{256, 512, 1024, 2048, 4096};
    if (axis == "vpls") values = o.quick ? std::vector<int>{4, 16, 64} : std::vector<int>{1, 4, 16, 64, 256};
    if (axis == "triangles") values = o.quick ? std::vector<int>{1, 10} : std::vector<int>{1, 3, 10, 30, 100};
    for (int v : values) {
        if (limit > 0.0 && v > limit) continue;
        AxisPoint p{std::to_string(v), o.width, o.height, {}, 1.0};
        if (axis == "shadow_map") p.settings["shadow_map"] = v;
        if (axis == "vpls") p.settings["vpls"] = v;
        if (axis == "triangles") p.detail = v;
        points.push_back(p);
    }
    return points;
}

double triangleCount(const viz::scene::Scene& s) {
    double n = 0;
    for (const auto& m : s.meshes) n += double(m.indices.size() / 3);
    return n;
}

// Whether an axis applies to a technique on a scene, and the reason when it does not.
std::string whyNot(const std::string& axis, const viz::Technique& t, const std::string& sceneName,
                   const viz::scene::Scene& scene) {
    if (axis == "shadow_map" && !viz::findParam(t, "shadow_map")) return t.id() + " has no shadow map";
    if (axis == "vpls" && !viz::findParam(t, "vpls")) return t.id() + " has no VPLs";
    if (axis == "vpls" && !viz::scene::hasAreaLight(scene)) return sceneName + " has no area light (VPLs sample area lights)";
    if (axis == "triangles") {
        const auto names = viz::scene::detailedSceneNames();
        if (std::find(names.begin(), names.end(), sceneName) == names.end())
            return sceneName + " has no detail parameter (grate, forest and terrain have)";
    }
    return "";
}

std::string shortExponent(double k) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", k);
    return text;
}

struct Job {
    std::size_t scene;
    std::string technique, axis;
    std::vector<AxisPoint> points;
};

}  // namespace

int runBenchCommand(Args& args, const std::string& commandLine) {
    if (!args.empty() && isHelpFlag(args.peek())) {
        std::fputs(kBenchHelp, stdout);
        return 0;
    }
    const Options o = parseBenchOptions(args);
    // Everything named is checked, and the plan of work made, before any file or context exists.
    std::vector<viz::scene::Scene> scenes;
    // Without --scenes each axis runs on its own scene: grate (a spot light through bars; the triangles
    // axis grows its bars) and, for VPLs, tv-room (the built-in scene with an area light).
    const bool defaultScenes = o.scenes.empty();
    const std::vector<std::string> sceneNames = defaultScenes ? std::vector<std::string>{"grate", "tv-room"} : o.scenes;
    auto defaultSceneOf = [](const std::string& axis) { return axis == "vpls" ? "tv-room" : "grate"; };
    for (const std::string& name : sceneNames) {
        scenes.push_back(viz::scene::loadScene(name));
        viz::scene::stampGeometry(scenes.back());  // the timed runs neither walk nor hash the geometry
    }
    std::vector<Job> jobs;
    std::vector<std::string> skipped;
    int steps = 0;
    for (std::size_t si = 0; si < scenes.size(); ++si)
        for (const std::string& id : o.techniques) {
            const auto technique = viz::makeTechnique(id);
            for (const std::string& axis : o.axes) {
                if (defaultScenes && sceneNames[si] != defaultSceneOf(axis)) continue;
                if (const std::string why = whyNot(axis, *technique, sceneNames[si], scenes[si]); !why.empty()) {
                    skipped.push_back(sceneNames[si] + " " + axis + " " + id + ": " + why);
                    continue;
                }
                const viz::ParamInfo* param = viz::findParam(*technique, axis);  // shadow_map, vpls
                Job job{si, id, axis, axisPoints(axis, o, param ? param->maxValue : 0.0)};
                for (AxisPoint& p : job.points) {
                    for (const auto& [name, value] : o.settings.at(id)) p.settings.try_emplace(name, value);
                    p.settings = viz::measuredSettings(*technique, std::move(p.settings));
                    viz::completeSettings(*technique, p.settings);
                }
                steps += int(job.points.size());
                jobs.push_back(std::move(job));
            }
        }
    if (jobs.empty())
        throw InputError("nothing to measure: no axis of --axes applies to these techniques and scenes (" +
                         (skipped.empty() ? std::string("none given") : skipped.front()) + ")");
    viz::StagedFolder folder(o.out);
    auto context = viz::HeadlessContext::create(false);
    const std::string renderer = rendererDescription();
    const RendererArithmetic arithmetic = measureRendererArithmetic();

    std::vector<viz::report::BenchRow> rows;
    std::vector<std::string> clocks;
    Progress progress(steps);
    int done = 0;
    std::map<std::pair<std::size_t, double>, viz::scene::Scene> detailed;  // (scene, detail) -> generated scene
    for (const Job& job : jobs) {
        auto technique = viz::makeTechnique(job.technique);
        for (const AxisPoint& point : job.points) {
            progress.show(done++, sceneNames[job.scene] + " | " + job.axis + " " + point.value + " | " + job.technique);
            const viz::scene::Scene* scene = &scenes[job.scene];
            if (point.detail != 1.0) {
                auto [it, added] = detailed.try_emplace({job.scene, point.detail});
                if (added) {
                    it->second = viz::scene::makeDetailedScene(sceneNames[job.scene], point.detail);
                    viz::scene::stampGeometry(it->second);
                }
                scene = &it->second;
            }
            const viz::FrameInput in = viz::frameInput(scene, point.width, point.height, viz::completeSettings(*technique, point.settings));
            const TimedRuns timed = timeRuns(*technique, in, o.runs);
            double work = 0.0;
            if (job.axis == "size") work = double(point.width) * point.height;
            if (job.axis == "shadow_map") work = std::pow(point.settings.at("shadow_map"), 2.0);
            if (job.axis == "vpls") work = point.settings.at("vpls");
            if (job.axis == "triangles") work = triangleCount(*scene);
            const std::string& clock = timed.last.timing.clock;
            if (std::find(clocks.begin(), clocks.end(), clock) == clocks.end()) clocks.push_back(clock);
            auto add = [&](const std::string& stage, double ms, double wallMs, const viz::report::RunSpread& spread) {
                rows.push_back({sceneNames[job.scene], job.technique, job.axis, point.value, work, stage, ms, clock,
                                renderer, o.runs, wallMs, spread});
            };
            for (const TimedRuns::Stage& s : timed.stages) add(s.id, s.milliseconds, s.wallMilliseconds, s.spread);
            add("total", timed.totalMilliseconds, timed.wallMilliseconds, timed.totalSpread);
            add("wall", timed.wallMilliseconds, timed.wallMilliseconds, timed.wallSpread);
        }
    }
    progress.show(done, "writing bench.csv, bench.html and the plots");
    progress.finish();

    const std::vector<viz::report::BenchFit> fits = viz::report::fitSeries(rows);
    const viz::ui::FontAtlas font = viz::ui::FontAtlas::bake(viz::ui::FontAtlas::defaultFontPath(), 15.0f);
    std::vector<viz::report::BenchPlot> plots;
    auto plotOf = [&](const Job& job, const std::string& techniqueFilter) {
        const viz::report::BenchAxis& axis = *viz::report::findBenchAxis(job.axis);
        viz::plot::PlotSpec spec;
        const std::string& sceneName = sceneNames[job.scene];
        spec.title = sceneName + ": " + (techniqueFilter.empty() ? "total per technique" : techniqueFilter + " by stage") +
                     " against " + job.axis;
        spec.xLabel = axis.workUnit;
        spec.yLabel = "ms: median, bars min to max";
        spec.logX = spec.logY = true;
        std::vector<std::string> names;  // techniques (totals) or stages
        for (const auto& r : rows) {
            if (r.scene != sceneName || r.axis != job.axis) continue;
            const bool wanted = techniqueFilter.empty() ? r.stage == "total" : r.technique == techniqueFilter;
            const std::string& name = techniqueFilter.empty() ? r.technique : r.stage;
            if (wanted && std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
        }
        for (std::size_t i = 0; i < names.size(); ++i) {
            // The series: a technique's totals, or one stage of the filtered technique.
            const std::string& technique = techniqueFilter.empty() ? names[i] : techniqueFilter;
            const std::string& stage = techniqueFilter.empty() ? std::string("total") : names[i];
            auto inSeries = [&](const auto& x) {
                return x.scene == sceneName && x.axis == job.axis && x.technique == technique && x.stage == stage;
            };
            viz::plot::Series series{names[i], viz::plot::categoricalColour(int(i)), {}, true, true};
            for (const viz::report::BenchFit& f : fits)
                if (inSeries(f))
                    series.name += "  k=" + (std::isfinite(f.fit.exponent) ? shortExponent(f.fit.exponent) : "?");
            for (const auto& r : rows)
                if (inSeries(r)) {
                    series.points.push_back({r.work, r.milliseconds});
                    series.yRanges.push_back({r.spread.minMilliseconds, r.spread.maxMilliseconds});
                }
            spec.series.push_back(std::move(series));
        }
        const std::string file = fileStem(sceneName) + "-" + job.axis + (techniqueFilter.empty() ? "" : "-" + fileStem(techniqueFilter)) + ".png";
        viz::ui::DrawList list(font);
        const glm::ivec2 size = techniqueFilter.empty() ? glm::ivec2(640, 420) : glm::ivec2(480, 340);
        viz::plot::drawPlot(list, {{0.0f, 0.0f}, glm::vec2(size)}, spec);
        viz::writeImage(viz::ui::renderOffscreen(list, size, {1, 1, 1, 1}), folder.path(file));
        plots.push_back({sceneName, job.axis, techniqueFilter, file});
    };
    for (const Job& job : jobs) {
        const bool first = std::none_of(plots.begin(), plots.end(), [&](const viz::report::BenchPlot& p) {
            return p.scene == sceneNames[job.scene] && p.axis == job.axis && p.technique.empty();
        });
        if (first) plotOf(job, "");
        plotOf(job, job.technique);
    }

    viz::report::BenchMeta meta;
    meta.date = utcNow();
    meta.command = commandLine;
    meta.machine = machineDescription();
    meta.renderer = renderer;
    meta.arithmeticNote = arithmetic.line;
    for (const std::string& c : clocks) meta.clock += (meta.clock.empty() ? "" : ", ") + c;
    meta.runs = o.runs;
    meta.quick = o.quick;
    std::string set;
    for (const std::string& text : o.sets) set += " " + text;  // as given: a named value by its name (integrand=svd)
    meta.fixed = "Fixed: each technique's default settings" + (set.empty() ? "" : " with" + set) + "; the axes other than size at " + std::to_string(o.width) +
                 "x" + std::to_string(o.height) + "; the scene at detail 1 except on the triangles axis.";
    std::string recordingsOff;  // Technique::measurementSettings the user did not set
    for (const std::string& id : o.techniques) {
        const auto technique = viz::makeTechnique(id);
        for (const auto& [name, value] : technique->measurementSettings())
            if (!o.settings.at(id).count(name))
                recordingsOff += (recordingsOff.empty() ? "" : ", ") + id + " " + viz::settingText(technique->params(), name, value);
    }
    if (!recordingsOff.empty()) meta.fixed += " The debugger's recordings off: " + recordingsOff + ".";
    if (!skipped.empty()) {
        meta.fixed += " Not measured:";
        for (const std::string& s : skipped) meta.fixed += " " + s + ";";
    }
    viz::report::writeBenchCsv(folder.path("bench.csv"), rows);
    viz::report::writeBenchHtml(folder.path("bench.html"), meta, rows, fits, plots);
    folder.commit();

    for (const viz::report::BenchFit& f : fits)
        if (f.stage == "total")
            std::printf("%-14s %-10s %-9s total ~ work^%s (r2 %.2f, %d points)\n", f.scene.c_str(), f.axis.c_str(),
                        f.technique.c_str(), std::isfinite(f.fit.exponent) ? shortExponent(f.fit.exponent).c_str() : "?",
                        f.fit.r2, f.fit.points);
    std::printf("wrote %s/bench.html (%s)\n", o.out.c_str(), meta.clock.c_str());
    std::vector<viz::report::TimedPoint> totals;
    for (const viz::report::BenchRow& r : rows)
        if (r.stage == "total")
            totals.push_back({r.scene + " " + r.technique + " " + r.axis + " " + r.value, r.milliseconds, r.spread});
    if (const std::string note = viz::report::noisyRunsNote(totals, "points' totals"); !note.empty()) {
        std::fflush(stdout);  // after what the command printed so far
        std::fprintf(stderr, "%s\n", note.c_str());
    }
    return 0;
}

}  // namespace airlight
