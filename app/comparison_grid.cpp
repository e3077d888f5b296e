#include "comparison_grid.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "render_job.h"
#include "silhouette_pixels.h"
#include "techniques/registry.h"

namespace airlight {

void ComparisonGrid::open(const viz::scene::Scene& scene, glm::ivec2 size, const std::vector<std::string>& ids) {
    close();
    mScene = scene;
    mSize = size;
    for (const std::string& id : ids) mTiles.push_back(ComparisonTile{id, "", {}, 0.0, {}});
    const auto reference = viz::makeTechnique("reference");
    mWorker = &mPool.freshWorker(Worker::Comparison, mScene);
    mWorker->submit({"reference", mScene.camera, viz::completeSettings(*reference, {}), mSize.x, mSize.y});
    mWaiting = true;
}

void ComparisonGrid::close() {
    mPlayedFrames = 0;
    mTiles.clear();
    if (mWorker) mPool.dropWorker(Worker::Comparison);
    mWorker = nullptr;
    mWaiting = mDue = false;
    mReference = {};
    mTracedDistance.reset();
    mFirstHits = {};
}

void ComparisonGrid::poll() {
    if (!mWaiting || !mWorker) return;
    std::optional<CpuResult> result = mWorker->take();
    if (!result || (result->error.empty() && result->pass < result->passCount)) return;
    mWaiting = false;
    if (!result->error.empty()) {
        for (ComparisonTile& tile : mTiles) tile.failure = "reference: " + result->error;  // the window shows its first line
        return;
    }
    mReference = std::move(result->output.airlight);
    if (const viz::Image* traced = tracedDistance(result->output)) mTracedDistance = *traced;
    mDue = true;
}

void ComparisonGrid::runTechniques(const RunTechnique& run) {
    mDue = false;
    mPlayedFrames = 0;
    if (mTracedDistance) {
        try {
            mFirstHits = silhouetteMask(*mTracedDistance, mScene);
        } catch (const std::exception&) {
            // No mask: the errors over all pixels stand alone.
        }
        mTracedDistance.reset();
    }
    for (ComparisonTile& tile : mTiles) {
        tile.temporal.reset();
        try {
            const bool reference = tile.technique == "reference";
            viz::FrameOutput out;
            if (!reference) {
                // Timed warm: polyvol's first run at 80x60 takes several times its second.
                (void)run(tile.technique, mScene, mSize, 0);
                out = run(tile.technique, mScene, mSize, 0);
            }
            const viz::Image& airlight = reference ? mReference : out.airlight;
            tile.milliseconds = out.timing.totalMilliseconds();
            tile.error = viz::report::compareImages(airlight, mReference);
            tile.relativeL2Agreeing = mFirstHits.disagreeing > 0
                                          ? viz::report::relativeL2Over(airlight, mReference, mFirstHits)
                                          : tile.error.relativeL2;
            tile.pane.id = tile.technique;
            tile.pane.mode = DisplayMode::HdrColour;
            uploadImage(tile.pane, airlight);
            tile.lastAirlight = airlight;
        } catch (const std::exception& e) {
            tile.failure = e.what();
        }
    }
    mExposure = std::log2(autoExposure(mReference));
}

void ComparisonGrid::playFrame(const viz::scene::Scene& moved, int frame, const RunTechnique& run, bool followCamera,
                               std::shared_ptr<const viz::Image> reference) {
    if (mWaiting || mDue || mTiles.empty()) return;  // the still frame first
    if (mPlayedFrames == 0)
        for (ComparisonTile& tile : mTiles)
            if (tile.technique != "reference" && tile.failure.empty()) tile.temporal.add(tile.lastAirlight);
    ++mPlayedFrames;
    viz::scene::Scene scene = moved;
    if (!followCamera) scene.camera = mScene.camera;
    for (ComparisonTile& tile : mTiles) {
        if (tile.technique == "reference" || !tile.failure.empty()) continue;
        try {
            const viz::FrameOutput out = run(tile.technique, scene, mSize, frame);
            tile.playMilliseconds = out.timing.totalMilliseconds();
            tile.temporal.add(out.airlight, reference);
            tile.lastAirlight = out.airlight;
            uploadImage(tile.pane, out.airlight);
        } catch (const std::exception& e) {
            tile.failure = e.what();
        }
    }
}

void ComparisonGrid::stopPlaying(const RunTechnique& run) {
    if (mPlayedFrames == 0) return;
    runTechniques(run);
}

std::string ComparisonGrid::waitingText() const {
    if (!mWaiting) return "running...";
    const CpuProgress progress = mWorker ? mWorker->progress() : CpuProgress{};
    return "computing the reference... " + passText(progress);
}

viz::plot::PlotSpec ComparisonGrid::errorAgainstTime() const {
    viz::plot::PlotSpec spec;
    spec.xLabel = "run time (ms)";
    spec.yLabel = "relative L2";
    spec.logX = spec.logY = true;
    for (std::size_t i = 0; i < mTiles.size(); ++i) {
        const ComparisonTile& t = mTiles[i];
        if (t.technique == "reference" || !t.failure.empty() || !(t.milliseconds > 0.0) ||
            !(t.error.relativeL2 > 0.0) || !std::isfinite(t.error.relativeL2))
            continue;
        spec.series.push_back({t.technique, viz::plot::categoricalColour(int(i)), {{t.milliseconds, t.error.relativeL2}},
                               false, true});
    }
    return spec;
}

nlohmann::json ComparisonGrid::toJson() const {
    nlohmann::json tiles = nlohmann::json::array();
    for (const ComparisonTile& t : mTiles)
        tiles.push_back({{"technique", t.technique},
                         {"milliseconds", t.milliseconds},
                         {"nan_inf_pixels", t.error.nanPixels + t.error.infPixels},
                         {"error", tileErrorText(t.error)},
                         {"error_agreeing", silhouetteErrorText(t.relativeL2Agreeing, mFirstHits.disagreeing)},
                         {"silhouette_pixels", mFirstHits.disagreeing},
                         {"failure", t.failure},
                         {"played_frames", mPlayedFrames},
                         {"change_pairs", t.temporal.pairs()},
                         {"error_change_pairs", t.temporal.errorPairs()}});
    // Figures only where they are defined (the caption says why one is not).
    for (std::size_t i = 0; i < mTiles.size(); ++i) {
        if (std::isfinite(mTiles[i].error.relativeL2)) tiles[i]["relative_l2"] = mTiles[i].error.relativeL2;
        if (std::isfinite(mTiles[i].relativeL2Agreeing)) tiles[i]["relative_l2_agreeing"] = mTiles[i].relativeL2Agreeing;
        if (std::isfinite(mTiles[i].error.maxAbsolute)) tiles[i]["max_abs"] = mTiles[i].error.maxAbsolute;
        if (std::isfinite(mTiles[i].temporal.score())) tiles[i]["change_rms"] = mTiles[i].temporal.score();
        if (std::isfinite(mTiles[i].temporal.errorScore())) tiles[i]["error_change_rms"] = mTiles[i].temporal.errorScore();
    }
    return tiles;
}

std::string tileTimeText(double milliseconds, int decimals) {
    char text[48];
    std::snprintf(text, sizeof text, "%.*f", decimals, milliseconds);
    if (std::atof(text) < 1000.0) return std::string(text) + " ms";  // as rounded: 999.96 is "1.00 s"
    std::snprintf(text, sizeof text, "%.2f s", milliseconds / 1000.0);
    return text;
}

std::string tileErrorText(const viz::report::ErrorMetrics& error) {
    char text[96];
    if (std::isfinite(error.relativeL2)) std::snprintf(text, sizeof text, "error %.3g", error.relativeL2);
    else if (error.nanPixels + error.infPixels > 0) std::snprintf(text, sizeof text, "error undefined");
    else if (std::isfinite(error.maxAbsolute))
        std::snprintf(text, sizeof text, "reference black: max |a - b| %.2g", error.maxAbsolute);
    else std::snprintf(text, sizeof text, "error undefined");
    return text;
}

std::string silhouetteErrorText(double relativeL2Agreeing, std::size_t silhouettes) {
    if (silhouettes == 0) return "";
    const std::string without = " w/o " + std::to_string(silhouettes) + (silhouettes == 1 ? " silhouette" : " silhouettes");
    if (!std::isfinite(relativeL2Agreeing)) return "undefined" + without;
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", relativeL2Agreeing);
    return text + without;
}

}  // namespace airlight
