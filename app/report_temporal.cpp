#include "report_temporal.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "core/error.h"
#include "core/image_io.h"
#include "plot/plot.h"
#include "report/error_images.h"
#include "report/temporal_error.h"
#include "report/tradeoff.h"
#include "techniques/registry.h"
#include "ui/offscreen.h"
#include "ui/text_renderer.h"
#include "run_info.h"

namespace airlight {


std::string defaultMotionPath(const std::string& sceneName, const viz::scene::Scene& scene) {
    const bool lightMoves = !scene.lights.empty() && scene.lights.front().type != viz::scene::LightType::Area;
    if (sceneName == "grate" || !lightMoves) return "camera-orbit:10deg";
    return "light-sweep:10deg";
}

bool measuredAlongPath(bool quick, bool paperPreset, int indexInSeries) {
    return !quick || (!paperPreset && indexInSeries == 0);
}

void runTemporal(const viz::scene::Scene& scene, const viz::scene::MotionPath& path, int frames, int width,
                 int height, const viz::Settings& referenceSettings, const std::vector<TemporalJob>& jobs,
                 std::vector<viz::report::ReportRow>& rows, const std::filesystem::path& dir, const std::string& stem,
                 float exposure, const std::function<void(const std::string&)>& step) {
    std::vector<viz::scene::Pose> poses;
    for (int i = 0; i < frames; ++i) poses.push_back(viz::scene::poseAt(path, scene, i, frames));
    viz::scene::Scene moving = scene;

    // The reference on every frame: the reference technique's own disk cache keys each frame by the
    // scene's content hash, which covers the camera and the lights, so a second report reads them back.
    std::vector<viz::Image> reference;
    {
        auto t = viz::makeTechnique("reference");
        const viz::Settings settings = viz::completeSettings(*t, referenceSettings);
        for (int i = 0; i < frames; ++i) {
            step("reference frame " + std::to_string(i + 1) + "/" + std::to_string(frames));
            viz::scene::applyPose(poses[std::size_t(i)], moving);
            reference.push_back(t->run(viz::frameInput(&moving, width, height, settings)).airlight);
        }
    }

    std::unique_ptr<viz::Technique> technique;
    for (const TemporalJob& job : jobs) {
        viz::report::ReportRow& row = rows[job.row];
        step(row.technique + " | " + row.setting + " | " + std::to_string(frames) + " frames");
        if (!technique || technique->id() != job.technique) {
            technique.reset();
            technique = viz::makeTechnique(job.technique);
        }
        // Warm-up on frame 0 (shader compiles, uploads), then each frame once, in path order.
        viz::scene::applyPose(poses.front(), moving);
        technique->run(viz::frameInput(&moving, width, height, job.settings));
        viz::report::TemporalAccumulator accumulator;
        std::vector<double> times;
        for (int i = 0; i < frames; ++i) {
            viz::scene::applyPose(poses[std::size_t(i)], moving);
            viz::FrameInput input = viz::frameInput(&moving, width, height, job.settings);
            input.frame = i;
            const viz::FrameOutput out = technique->run(input);
            if (out.airlight.empty()) throw std::runtime_error(job.technique + " produced no L_air image");
            times.push_back(out.timing.totalMilliseconds());
            accumulator.add(out.airlight, reference[std::size_t(i)]);
        }
        const viz::report::TemporalMetrics m = accumulator.finish();
        viz::report::TemporalFigures figures;
        figures.path = path.text;
        figures.frames = frames;
        figures.meanFrameError = m.meanFrameError;
        figures.temporalRms = m.temporalRms;
        figures.worstFlicker = m.worstFlicker;
        figures.msPerFrame = median(times);
        figures.excludedDifferences = m.excludedDifferences;
        figures.flickerImage = stem + "-" + fileStem(row.technique) + "-" + fileStem(row.setting) + "-flicker.png";
        viz::writeImage(viz::report::heatMap(m.flicker, exposure * 10.0f), (dir / figures.flickerImage).string());
        row.temporal = std::move(figures);
    }
    viz::scene::applyPose(poses.front(), moving);
}

void writeTemporalPlot(const viz::ui::FontAtlas& font, const std::vector<viz::report::ReportRow>& rows,
                       const viz::report::ScenePage& page, const std::vector<std::string>& techniques, int width,
                       int height, const std::filesystem::path& file) {
    viz::plot::PlotSpec spec;
    spec.title = page.scene + ": temporal error against time (" + page.motionPath + ", " + std::to_string(page.frames) +
                 " frames, " + std::to_string(width) + "x" + std::to_string(height) + ")";
    spec.xLabel = "time per frame, ms (median over the path)";
    spec.yLabel = "temporal RMS of the error";
    spec.logX = spec.logY = true;
    spec.highlightName = "Pareto front";
    std::vector<viz::report::TradeoffPoint> scenePoints;
    std::vector<glm::dvec2> sceneCoords;
    int colour = 0;
    for (const std::string& technique : techniques) {
        viz::plot::Series all{technique, viz::plot::categoricalColour(colour++), {}, false, true};
        std::vector<viz::report::TradeoffPoint> points;
        for (const auto& r : rows)
            if (r.scene == page.scene && r.technique == technique && r.temporal) {
                all.points.push_back({r.temporal->msPerFrame, r.temporal->temporalRms});
                points.push_back({r.temporal->msPerFrame, r.temporal->temporalRms});
            }
        if (all.points.empty()) continue;
        scenePoints.insert(scenePoints.end(), points.begin(), points.end());
        sceneCoords.insert(sceneCoords.end(), all.points.begin(), all.points.end());
        viz::plot::Series front{"", all.colour, {}, true, false};
        for (int k : viz::report::paretoFront(points)) front.points.push_back(all.points[std::size_t(k)]);
        spec.series.push_back(std::move(all));
        spec.series.push_back(std::move(front));
    }
    for (int k : viz::report::paretoFront(scenePoints)) spec.highlighted.push_back(sceneCoords[std::size_t(k)]);
    viz::ui::DrawList list(font);
    const glm::ivec2 size{760, 480};
    viz::plot::drawPlot(list, {{0.0f, 0.0f}, glm::vec2(size)}, spec);
    viz::writeImage(viz::ui::renderOffscreen(list, size, {1, 1, 1, 1}), file.string());
}

}  // namespace airlight
