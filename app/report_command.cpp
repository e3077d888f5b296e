#include "report_command.h"
#include "report_temporal.h"
#include "run_info.h"
#include "silhouette_pixels.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <thread>

#include "core/error.h"
#include "core/image_io.h"
#include "debug/technique.h"
#include "gl/gl.h"
#include "gl/work_counters.h"
#include "platform/context_egl.h"
#include "plot/plot.h"
#include "report/error_images.h"
#include "report/error_metrics.h"
#include "report/first_hits.h"
#include "report/report_table.h"
#include "scene/stiff_scenes.h"
#include "report/stiff_suite.h"
#include "report/temporal_report.h"
#include "report/text_output.h"
#include "report/tradeoff.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_source.h"
#include "techniques/registry.h"
#include "ui/offscreen.h"

namespace airlight {

using viz::InputError;

namespace {

constexpr const char* kReportHelp = R"(usage: airlight report [--scenes A,B,..] [--techniques T1,T2,..] [--size WxH] --out DIR [--quick] [--runs N]
                       [--temporal [--frames N] [--path P]]

Sweeps each technique's quality knobs on each scene, times every setting (median of N runs after one
warm-up; N = 5 by default) and compares its L_air with the reference (cached on disk). Writes into DIR:
results.csv, results.json, one error-against-time plot per scene (PNG), each technique's image and error
heat map, and index.html (static, no scripts). The headline is each technique's speed-up over
brute-force raymarch at equal error. On a scene with an area light the sweeps of the techniques that
sample it as virtual point lights add more of them (area_samples 8, 12 and 16; 8 and 16 with --quick,
where polyvol adds none and ivsv adds vpls=256), each count also with the technique's other knob for
the VPLs' rays (raymarch samples=16, minmax vpl_samples=16, slices planes=256).

  --scenes      built-in scene names or glTF paths, comma-separated (default: every built-in scene); a
                path with a comma in its name stays whole when that file exists
  --techniques  techniques to compare, comma-separated (default: every one but the reference;
                raymarch is always added: it is the baseline of the speed-up)
  --size        image size (default 160x120)
  --quick       a shorter sweep per technique (all built-in scenes in a few minutes at 160x120)
  --runs        timed runs per setting (default 5)
  --temporal    also render each setting on every frame of a motion path per scene, with the reference
                on the same frames (cached), and score the frame-to-frame change of the error: per scene a
                temporal table (mean per-frame error, temporal RMS, worst flicker, ms per frame), a flicker
                heat map per setting, a plot of temporal RMS against time, and the techniques ranked by
                stability. Every sweep setting and paper preset but the added area_samples; with --quick
                each technique's cheapest setting
  --frames N    frames per path, 2 to 240 (default 12; 6 with --quick); needs --temporal
  --path P      the motion path for every scene (as for animate: camera-orbit:A, camera-dolly:D,
                light-orbit:A, light-sweep:A or a keyframe .json); default per scene: light-sweep:10deg, or
                camera-orbit:10deg on grate and where the first light is an area light; needs --temporal

airlight report --suite stiff --out DIR [--techniques T1,T2,..]
  runs the stiff and extreme cases (extreme media, intensities and scales, rays through the light,
  epipole cases, cameras inside things, degenerate geometry, huge depth ranges, extreme phase
  functions) at a small size against the reference, and writes DIR/stiff.csv and DIR/stiff.html.
  A cell passes when every pixel is finite and non-negative and the error is within the bound the
  technique declares for the case's class. Exit code 3 when any cell fails.
)";

std::string settingsText(const std::vector<viz::ParamInfo>& params, const viz::Settings& s) {
    std::string text;
    for (const auto& [name, value] : s) text += (text.empty() ? "" : " ") + viz::settingText(params, name, value);
    return text;
}

// --quick renders the reference with 4 x 4 emitter cells per area light instead of 8 x 8: 2.3e-3 relative
// L2 from 32 x 32 on tv-room (viz/techniques/reference/README.md), far below the errors a quick sweep
// separates, at about 2.5 times less time. Only scenes with an area light are affected.
constexpr double kQuickReferenceAreaSamples = 4.0;

struct Options {
    std::vector<std::string> scenes, techniques;
    int width = 160, height = 120;
    std::string out;
    bool quick = false;
    int runs = 5;
    std::string suite;  // "" or "stiff"
    bool temporal = false;
    int frames = 0;     // 0: kTemporalFrames, or kQuickTemporalFrames with --quick
    std::string path;   // "" : defaultMotionPath per scene
};

Options parseReportOptions(Args& args) {
    Options o;
    while (!args.empty()) {
        const std::string flag = args.take();
        if (flag == "--scenes") o.scenes = splitSceneList(args.next(flag), flag);
        else if (flag == "--techniques") o.techniques = splitList(args.next(flag), flag);
        else if (flag == "--size") {
            const glm::ivec2 size = parseSize(args.next(flag));
            o.width = size.x, o.height = size.y;
        } else if (flag == "--out") o.out = args.next(flag);
        else if (flag == "--quick") o.quick = true;
        else if (flag == "--suite") {
            o.suite = args.next(flag);
            if (o.suite != "stiff") throw InputError("--suite '" + o.suite + "' is not known (known: stiff)");
        }
        else if (flag == "--runs") o.runs = parseWholeNumber(args.next(flag), flag, 1, 1000);
        else if (flag == "--temporal") o.temporal = true;
        else if (flag == "--frames") o.frames = parseWholeNumber(args.next(flag), flag, 2, kMaxTemporalFrames);
        else if (flag == "--path") o.path = args.next(flag);
        else throw InputError("unknown option '" + flag + "' for 'report' (run 'airlight report --help')");
    }
    if (o.out.empty()) throw InputError("report needs --out DIR (the folder to write the report into)");
    if (o.temporal && !o.suite.empty())
        throw InputError("--temporal does not apply to --suite " + o.suite + " (its cases are single frames)");
    if (!o.temporal && o.frames) throw InputError("--frames needs --temporal (it sets the frames of the motion path)");
    if (!o.temporal && !o.path.empty()) throw InputError("--path needs --temporal (it sets the motion path)");
    if (o.temporal && !o.frames) o.frames = o.quick ? kQuickTemporalFrames : kTemporalFrames;
    if (o.scenes.empty()) o.scenes = viz::scene::builtinSceneNames();
    if (o.techniques.empty())
        for (const std::string& t : viz::techniqueIds())
            if (t != "reference") o.techniques.push_back(t);
    for (const std::string& t : o.techniques)
        if (t == "reference")
            throw InputError("--techniques: 'reference' is what the report measures against; list the others");
    if (o.suite.empty() && std::find(o.techniques.begin(), o.techniques.end(), "raymarch") == o.techniques.end())
        o.techniques.insert(o.techniques.begin(), "raymarch");
    return o;
}

viz::report::ReportMeta describeRun(const Options& o, const std::string& commandLine) {
    viz::report::ReportMeta meta;
    meta.date = utcNow();
    meta.command = commandLine;
    meta.machine = machineDescription();
    meta.renderer = rendererDescription();
    meta.width = o.width, meta.height = o.height, meta.runs = o.runs, meta.quick = o.quick;
    if (o.quick) meta.referenceSettings = "area_samples=" + std::to_string(int(kQuickReferenceAreaSamples));
    meta.temporal = o.temporal;
    return meta;
}

std::filesystem::path createOutputFolder(const std::string& out) {
    std::error_code ec;
    std::filesystem::create_directories(out, ec);
    if (!std::filesystem::is_directory(out)) throw InputError("cannot create the report folder '" + out + "'");
    return out;
}

// The stiff suite: every case, the reference once per case, then each technique.
int runStiffSuite(const Options& o, const std::string& commandLine) {
    std::vector<std::unique_ptr<viz::Technique>> made;  // an unknown id fails here, before any folder exists
    for (const std::string& id : o.techniques) made.push_back(viz::makeTechnique(id));
    const auto& cases = viz::scene::stiffCases();
    const std::filesystem::path dir = createOutputFolder(o.out);
    auto context = viz::HeadlessContext::create(false);
    // Declared after the context, so the techniques' GL objects are deleted while it is current (the
    // other order aborted at exit in libepoxy, exit 134, after the files were written).
    const std::vector<std::unique_ptr<viz::Technique>> techniques = std::move(made);
    const viz::report::ReportMeta meta = describeRun(o, commandLine);

    std::vector<viz::report::StiffOutcome> outcomes;
    Progress progress(int(cases.size() * (techniques.size() + 1)));
    int done = 0;
    for (const viz::scene::StiffCase& c : cases) {
        progress.show(done++, c.id + " | reference");
        const viz::scene::Scene scene = viz::scene::buildStiffScene(c);
        auto reference = viz::makeTechnique("reference");
        viz::FrameInput in = viz::frameInput(&scene, c.width, c.height, viz::completeSettings(*reference, {}));
        const viz::Image referenceImage = reference->run(in).airlight;
        for (auto& technique : techniques) {
            progress.show(done++, c.id + " | " + technique->id());
            outcomes.push_back(viz::report::runStiffCase(*technique, c, scene, referenceImage));
        }
    }
    progress.show(done, "writing stiff.csv and stiff.html");
    progress.finish();
    viz::report::writeStiffFiles(dir.string(), meta, outcomes);
    int failures = 0;
    for (const auto& outcome : outcomes)
        if (!outcome.passed) {
            ++failures;
            std::printf("FAIL %-26s %-10s %s\n", outcome.caseId.c_str(), outcome.technique.c_str(),
                        outcome.verdict.c_str());
        }
    std::printf("%d of %zu cells pass; wrote %s\n", int(outcomes.size()) - failures, outcomes.size(),
                (dir / "stiff.html").string().c_str());
    return failures ? 3 : 0;
}

// The technique at its cheapest sweep setting, timed as planned and with force_features=1.
viz::report::PlanSaving measurePlanSaving(const std::string& id, const viz::scene::Scene& scene,
                                          const std::string& sceneName, const Options& o) {
    // Two instances, one per side: each keeps its own compiled programs and targets, so the runs can
    // alternate without recompiling (one instance would time its compiler on every switch).
    auto plannedTechnique = viz::makeTechnique(id), forcedTechnique = viz::makeTechnique(id);
    viz::report::PlanSaving saving{sceneName, id, 0.0, 0.0, {}};
    // The cheapest setting of the technique's sweep (its quick sweep with --quick), so that the check
    // costs what one row of the sweep costs; force_features on top of it for the forced runs.
    viz::Settings base = viz::measuredSettings(*plannedTechnique, plannedTechnique->qualitySweep(o.quick).front().settings);
    const viz::Settings planned = viz::completeSettings(*plannedTechnique, base);
    base["force_features"] = 1.0;
    const viz::Settings forced = viz::completeSettings(*forcedTechnique, base);
    const viz::Plan a = plannedTechnique->plan(scene, planned), b = forcedTechnique->plan(scene, forced);
    for (std::size_t i = 0; i < a.stages.size() && i < b.stages.size(); ++i)
        if (!a.stages[i].runs && b.stages[i].runs) saving.skipped.push_back("stage " + a.stages[i].stage);
    for (std::size_t i = 0; i < a.features.size() && i < b.features.size(); ++i)
        if (!a.features[i].enabled && b.features[i].enabled) saving.skipped.push_back(a.features[i].feature);
    viz::FrameInput in = viz::frameInput(&scene, o.width, o.height, planned);
    viz::FrameInput inForced = viz::frameInput(&scene, o.width, o.height, forced);
    // A warm-up of each, then the runs in pairs, alternated (planned first in even pairs, forced first in
    // odd ones): a slow spell of the machine falls on both sides instead of on whichever block it met.
    // At least 7 of each (the cheapest setting is cheap), so that the ranges the page compares are not
    // two or three samples.
    const int runs = std::max(o.runs, 7);
    std::vector<double> plannedTimes, forcedTimes;
    plannedTechnique->run(in);
    forcedTechnique->run(inForced);
    for (int r = 0; r < runs; ++r)
        for (int side = 0; side < 2; ++side) {
            if ((side == 0) == (r % 2 == 0))
                plannedTimes.push_back(plannedTechnique->run(in).timing.totalMilliseconds());
            else
                forcedTimes.push_back(forcedTechnique->run(inForced).timing.totalMilliseconds());
        }
    saving.plannedMilliseconds = median(plannedTimes);
    saving.forcedMilliseconds = median(forcedTimes);
    saving.plannedRuns = plannedTimes;
    saving.forcedRuns = forcedTimes;
    return saving;
}

// A counting run's work summed over its stages, named by counter.
std::vector<std::pair<std::string, std::uint64_t>> namedWork(const viz::FrameOutput& out) {
    const viz::WorkCounts total = out.timing.totalWork();
    std::vector<std::pair<std::string, std::uint64_t>> named;
    for (std::size_t c = 0; c < total.size(); ++c) named.push_back({viz::gl::WorkCounters::name(int(c)), total[c]});
    return named;
}

struct SweepPoint {
    std::string technique;
    viz::QualitySetting setting;
    std::string series;  // the report's series: the technique, or "T (paper)" for its paper preset
    bool alongPath = false;    // with --temporal, also measured along the motion path
    std::string stabiliser{};  // a stabilising option's pair (always measured along the path)
    bool stabiliserOn = false;
};

// A scene's sweep, technique by technique: the technique's quality sweep, with more VPLs where the scene
// has an area light (Technique::areaLightSweep: these join the technique's front but are not measured
// along the path, which would cost their square of VPLs on every frame), then its paper preset as a
// series of its own; with --temporal, each technique's stabilising options on that scene as pairs of
// points (the option off, then on). Each point's settings hold the technique's measurementSettings
// beneath its own. Every setting is checked here, before any work starts.
std::vector<SweepPoint> sceneSweep(const std::vector<std::string>& techniques, const viz::scene::Scene& scene,
                                   bool quick, bool temporal) {
    std::vector<SweepPoint> out;
    for (const std::string& id : techniques) {
        const auto technique = viz::makeTechnique(id);
        std::vector<viz::QualitySetting> points = technique->qualitySweep(quick);
        const std::size_t own = points.size();
        if (viz::scene::hasAreaLight(scene))
            for (viz::QualitySetting& q : technique->areaLightSweep(quick)) points.push_back(std::move(q));
        for (std::size_t k = 0; k < points.size(); ++k) {
            points[k].settings = viz::measuredSettings(*technique, std::move(points[k].settings));
            viz::completeSettings(*technique, points[k].settings);  // throws if a declared sweep is invalid
            out.push_back({id, std::move(points[k]), id, k < own && measuredAlongPath(quick, false, int(k))});
        }
        // The paper's configuration beside ours: its own series, one point.
        if (!technique->paperSettings().empty()) {
            const viz::Settings paper = viz::measuredSettings(*technique, technique->paperSettings());
            viz::completeSettings(*technique, paper);
            out.push_back({id, {"paper preset", paper}, id + " (paper)", measuredAlongPath(quick, true, 0)});
        }
    }
    if (!temporal) return out;
    for (const std::string& id : techniques) {
        const auto technique = viz::makeTechnique(id);
        for (viz::StabilisingOption& option : technique->stabilisingOptions(scene)) {
            for (bool on : {false, true}) {
                const viz::Settings given = viz::measuredSettings(*technique, on ? option.on : option.off);
                (void)viz::completeSettings(*technique, given);  // throws if a declared option is invalid
                out.push_back({id, {settingsText(technique->params(), given), given}, id, true, option.name, on});
            }
        }
    }
    return out;
}

}  // namespace

int runReportCommand(Args& args, const std::string& commandLine) {
    if (!args.empty() && isHelpFlag(args.peek())) {
        std::fputs(kReportHelp, stdout);
        return 0;
    }
    const Options o = parseReportOptions(args);
    if (o.suite == "stiff") return runStiffSuite(o, commandLine);

    // Everything the user named is checked before any work starts.
    std::vector<viz::scene::Scene> scenes;
    for (const std::string& name : o.scenes) {
        scenes.push_back(viz::scene::loadScene(name));
        viz::scene::stampGeometry(scenes.back());  // the timed runs neither walk nor hash the geometry
    }
    // --temporal: every scene's path and poses, so that a path that cannot move a scene fails here.
    std::vector<viz::scene::MotionPath> paths;
    if (o.temporal) {
        for (std::size_t si = 0; si < scenes.size(); ++si) {
            paths.push_back(viz::scene::parseMotionPath(o.path.empty() ? defaultMotionPath(o.scenes[si], scenes[si]) : o.path));
            for (int i = 0; i < o.frames; ++i) (void)viz::scene::poseAt(paths.back(), scenes[si], i, o.frames);
        }
    }
    std::vector<std::vector<SweepPoint>> sweeps;  // per scene: with --temporal, the stabilising options too
    std::size_t progressSteps = 0;
    for (const viz::scene::Scene& scene : scenes) {
        sweeps.push_back(sceneSweep(o.techniques, scene, o.quick, o.temporal));
        progressSteps += 2 * sweeps.back().size() + 1 + o.techniques.size();
        if (o.temporal) {
            progressSteps += std::size_t(o.frames);
            for (const SweepPoint& p : sweeps.back()) progressSteps += p.alongPath;
        }
    }
    const std::filesystem::path dir = createOutputFolder(o.out);
    auto context = viz::HeadlessContext::create(false);
    viz::report::ReportMeta meta = describeRun(o, commandLine);
    // Before any technique runs: what this renderer's fragment passes pay against its compute passes.
    const RendererArithmetic arithmetic = measureRendererArithmetic();
    meta.fragmentOverCompute = arithmetic.fragmentOverCompute;
    meta.arithmeticNote = arithmetic.line;

    const viz::ui::FontAtlas font = viz::ui::FontAtlas::bake(viz::ui::FontAtlas::defaultFontPath(), 15.0f);
    std::vector<viz::report::ReportRow> rows;
    std::vector<viz::report::ScenePage> pages;
    std::vector<viz::report::PlanSaving> savings;
    Progress progress{int(progressSteps)};
    // What --temporal adds: the stabilising options' points and every run along the paths (seconds).
    const auto reportStart = std::chrono::steady_clock::now();
    double temporalSeconds = 0.0;
    auto secondsSince = [](std::chrono::steady_clock::time_point t) {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    };
    int done = 0;
    for (std::size_t si = 0; si < scenes.size(); ++si) {
        const viz::scene::Scene& scene = scenes[si];
        const std::string& sceneName = o.scenes[si];
        const std::string stem = fileStem(scene.name.empty() ? sceneName : scene.name);
        progress.show(done, sceneName + " | reference");
        viz::Image reference;
        viz::report::FirstHitMask firstHits;  // where the rasteriser and the traced rays see one surface
        {
            auto t = viz::makeTechnique("reference");
            const viz::Settings settings =
                o.quick ? viz::Settings{{"area_samples", kQuickReferenceAreaSamples}} : viz::Settings{};
            viz::FrameInput in = viz::frameInput(&scene, o.width, o.height, viz::completeSettings(*t, settings));
            viz::FrameOutput out = t->run(in);
            const viz::Image* traced = tracedDistance(out);
            if (!traced) throw std::runtime_error("the reference published no reference.distance");
            firstHits = silhouetteMask(*traced, scene);
            reference = std::move(out.airlight);
        }
        ++done;
        const float exposure = viz::report::exposureFor(reference);
        viz::report::ScenePage page;
        page.scene = sceneName;
        page.plot = stem + "-plot.png";
        page.referenceImage = stem + "-reference.png";
        viz::writeImage(reference, (dir / page.referenceImage).string(), exposure);

        std::vector<TemporalJob> temporalJobs;
        // Keep the most accurate image of each technique for the page.
        std::map<std::string, std::pair<std::size_t, viz::Image>> bestImage;
        std::unique_ptr<viz::Technique> technique;
        const std::size_t firstRow = rows.size();
        const std::vector<SweepPoint>& sweepHere = sweeps[si];
        for (const SweepPoint& point : sweepHere) {
            const auto pointStart = std::chrono::steady_clock::now();
            progress.show(done, sceneName + " | " + point.technique + " | " + point.setting.label);
            if (!technique || technique->id() != point.technique) {
                technique.reset();
                technique = viz::makeTechnique(point.technique);
            }
            viz::FrameInput in = viz::frameInput(&scene, o.width, o.height, viz::completeSettings(*technique, point.setting.settings));
            const TimedRuns timed = timeRuns(*technique, in, o.runs);
            const viz::FrameOutput& output = timed.last;
            viz::report::ReportRow row;
            row.scene = sceneName;
            row.technique = point.series;
            row.setting = point.setting.label;
            row.settings = settingsText(technique->params(), point.setting.settings);
            row.stabiliser = point.stabiliser;
            row.stabiliserOn = point.stabiliserOn;
            row.width = o.width, row.height = o.height, row.runs = o.runs;
            row.clock = output.timing.clock;
            for (const TimedRuns::Stage& s : timed.stages) row.stages.push_back({s.id, s.milliseconds});
            row.totalMilliseconds = timed.totalMilliseconds;
            row.wallMilliseconds = timed.wallMilliseconds;
            row.totalSpread = timed.totalSpread;
            if (output.airlight.empty()) throw std::runtime_error(point.technique + " produced no L_air image");
            row.error = viz::report::compareImages(output.airlight, reference);
            row.firstHitDisagreements = firstHits.disagreeing;
            row.relativeL2Agreeing = viz::report::relativeL2Over(output.airlight, reference, firstHits);
            // The page shows each technique's most accurate image (a finite error beats an undefined one).
            const auto it = bestImage.find(point.series);
            const double e = row.error.relativeL2;
            if (it == bestImage.end() || (std::isfinite(e) && !(rows[it->second.first].error.relativeL2 <= e)))
                bestImage[point.series] = {rows.size(), output.airlight};
            if (o.temporal && point.alongPath)
                temporalJobs.push_back({rows.size(), point.technique, in.settings});
            rows.push_back(std::move(row));
            ++done;
            if (!point.stabiliser.empty()) temporalSeconds += secondsSince(pointStart);
        }
        technique.reset();
        // The work of every setting (gl/work_counters.h): one counting run each, in an instance per
        // technique made while counting is on, so that every program it compiles counts.
        viz::gl::WorkCounters::setEnabled(true);
        for (std::size_t k = 0; k < sweepHere.size(); ++k) {
            const SweepPoint& point = sweepHere[k];
            const auto pointStart = std::chrono::steady_clock::now();
            progress.show(done, sceneName + " | " + point.technique + " | work of " + point.setting.label);
            if (!technique || technique->id() != point.technique) {
                technique.reset();
                technique = viz::makeTechnique(point.technique);
            }
            viz::FrameInput in = viz::frameInput(&scene, o.width, o.height, viz::completeSettings(*technique, point.setting.settings));
            rows[firstRow + k].work = namedWork(technique->run(in));
            ++done;
            if (!point.stabiliser.empty()) temporalSeconds += secondsSince(pointStart);
        }
        technique.reset();
        viz::gl::WorkCounters::setEnabled(false);
        for (const std::string& id : o.techniques) {
            progress.show(done++, sceneName + " | " + id + " | plan savings");
            if (viz::findParam(*viz::makeTechnique(id), "force_features"))
                savings.push_back(measurePlanSaving(id, scene, sceneName, o));
        }
        for (auto& [id, best] : bestImage) {
            viz::report::ReportRow& row = rows[best.first];
            row.image = stem + "-" + fileStem(id) + ".png";
            row.errorImage = stem + "-" + fileStem(id) + "-error.png";
            viz::writeImage(best.second, (dir / row.image).string(), exposure);
            viz::writeImage(viz::report::errorHeatMap(best.second, reference, exposure * 10.0f),
                            (dir / row.errorImage).string());
        }
        if (o.temporal) {
            page.motionPath = paths[si].text;
            page.frames = o.frames;
            page.temporalPlot = stem + "-temporal-plot.png";
            const viz::Settings referenceSettings =
                o.quick ? viz::Settings{{"area_samples", kQuickReferenceAreaSamples}} : viz::Settings{};
            const auto temporalStart = std::chrono::steady_clock::now();
            runTemporal(scene, paths[si], o.frames, o.width, o.height, referenceSettings, temporalJobs, rows, dir, stem,
                        exposure, [&](const std::string& what) { progress.show(done++, sceneName + " | temporal | " + what); });
            temporalSeconds += secondsSince(temporalStart);
        }
        pages.push_back(page);
    }
    progress.show(done, "writing the report");
    progress.finish();
    viz::report::annotateTradeoffs(rows);

    // Plots: error against time per scene, one series per technique (its own Pareto front joined by a
    // line), the scene's overall Pareto front ringed.
    for (const viz::report::ScenePage& page : pages) {
        viz::plot::PlotSpec spec;
        spec.title = page.scene + ": error against time (" + std::to_string(o.width) + "x" + std::to_string(o.height) + ")";
        spec.xLabel = "time per frame, ms (sum of stages; bars: fastest to slowest run)";
        spec.yLabel = "relative L2 error of L_air";
        spec.logX = spec.logY = true;
        spec.highlightName = "Pareto front";
        int colour = 0;
        std::vector<std::string> plotted;  // every series of the scene: the techniques and their paper presets
        for (const auto& r : rows)
            if (r.scene == page.scene && std::find(plotted.begin(), plotted.end(), r.technique) == plotted.end())
                plotted.push_back(r.technique);
        for (const std::string& technique : plotted) {
            viz::plot::Series all{technique, viz::plot::categoricalColour(colour), {}, false, true};
            std::vector<viz::report::TradeoffPoint> points;
            for (const auto& r : rows)
                if (r.scene == page.scene && r.technique == technique) {
                    all.points.push_back({r.totalMilliseconds, r.error.relativeL2});
                    all.xRanges.push_back({r.totalSpread.minMilliseconds, r.totalSpread.maxMilliseconds});
                    points.push_back({r.totalMilliseconds, r.error.relativeL2});
                }
            viz::plot::Series front{"", all.colour, {}, true, false};
            for (int k : viz::report::paretoFront(points)) front.points.push_back(all.points[std::size_t(k)]);
            spec.series.push_back(std::move(all));
            spec.series.push_back(std::move(front));
            ++colour;
        }
        for (const auto& r : rows)
            if (r.scene == page.scene && r.pareto) spec.highlighted.push_back({r.totalMilliseconds, r.error.relativeL2});
        viz::ui::DrawList list(font);
        const glm::ivec2 size{760, 480};
        viz::plot::drawPlot(list, {{0.0f, 0.0f}, glm::vec2(size)}, spec);
        viz::writeImage(viz::ui::renderOffscreen(list, size, {1, 1, 1, 1}), (dir / page.plot).string());
        if (!page.temporalPlot.empty()) {
            std::vector<std::string> series;  // the paper presets too: with --quick they are half the points
            for (const auto& r : rows)
                if (r.scene == page.scene && r.temporal && std::find(series.begin(), series.end(), r.technique) == series.end())
                    series.push_back(r.technique);
            writeTemporalPlot(font, rows, page, series, o.width, o.height, dir / page.temporalPlot);
        }
    }
    viz::report::writeCsv((dir / "results.csv").string(), rows);
    viz::report::writeJson((dir / "results.json").string(), meta, rows, savings);
    viz::report::writeHtml((dir / "index.html").string(), meta, rows, pages, savings);

    // Every series (a technique, or its paper preset) against raymarch at each error target.
    std::vector<std::string> series;
    for (const auto& r : rows)
        if (std::find(series.begin(), series.end(), r.technique) == series.end()) series.push_back(r.technique);
    if (std::find(o.techniques.begin(), o.techniques.end(), "raymarch") != o.techniques.end())
        for (const viz::report::ScenePage& page : pages)
            for (const std::string& t : series)
                for (double target : viz::report::errorTargets())
                    if (t != "raymarch") {
                        const std::string time =
                            viz::report::targetSpeedupPhrase(viz::report::targetSpeedup(rows, page.scene, t, target));
                        const std::string work = viz::report::targetSpeedupPhrase(
                            viz::report::targetSpeedup(rows, page.scene, t, target, "raymarch", viz::report::Measure::Work),
                            "raymarch", viz::report::Measure::Work);
                        // A target one side never reaches reads the same in time and in work: once.
                        std::printf("%-14s %-16s at %4.3g %% error: %s%s\n", page.scene.c_str(), t.c_str(), 100.0 * target,
                                    time.c_str(), work == time ? "" : ("; " + work).c_str());
                        // With silhouette pixels (report/first_hits.h), the same without them where it differs.
                        const std::string agreeing = viz::report::targetSpeedupPhrase(viz::report::targetSpeedup(
                            rows, page.scene, t, target, "raymarch", viz::report::Measure::Time,
                            viz::report::ErrorOver::AgreeingPixels));
                        if (agreeing != time) std::printf("%33s over the pixels whose first hit agrees: %s\n", "", agreeing.c_str());
                    }
    if (o.temporal)
        for (const viz::report::ScenePage& page : pages) {
            std::vector<viz::report::TechniqueRank> ranks = viz::report::rankTechniques(rows, page.scene);
            std::stable_sort(ranks.begin(), ranks.end(), [](const auto& a, const auto& b) {
                return (a.stabilityRank ? a.stabilityRank : 1 << 20) < (b.stabilityRank ? b.stabilityRank : 1 << 20);
            });
            std::printf("%-14s most stable along %s:", page.scene.c_str(), page.motionPath.c_str());
            for (const auto& t : ranks)
                if (t.stabilityRank) std::printf(" %d. %s %.3g", t.stabilityRank, t.technique.c_str(), t.mostStable);
            std::printf("\n");
            for (const viz::report::StabiliserPair& p : viz::report::stabiliserPairs(rows, page.scene))
                std::printf("%-14s %s\n", page.scene.c_str(), viz::report::stabiliserLine(p).c_str());
        }
    if (o.temporal)
        std::printf("--temporal took %.0f s of the report's %.0f s (the stabilising options' settings and every frame "
                    "along the paths, reference frames included)\n",
                    temporalSeconds, secondsSince(reportStart));
    std::vector<viz::report::TimedPoint> times;
    for (const viz::report::ReportRow& r : rows)
        times.push_back({r.scene + " " + r.technique + " " + r.setting, r.totalMilliseconds, r.totalSpread});
    if (const std::string note = viz::report::noisyRunsNote(times, "settings"); !note.empty()) {
        std::fflush(stdout);  // after what the command printed so far
        std::fprintf(stderr, "%s\n", note.c_str());
    }
    std::printf("wrote %s\n", (dir / "index.html").string().c_str());
    return 0;
}

}  // namespace airlight
