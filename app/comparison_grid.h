// The window's comparison grid (G): every technique's L_air for one view (scene, camera, size) beside the
// reference's, each with the time of a warm run and its error against the reference, and the error
// against time as a plot. The reference renders on a worker thread (from its on-disk cache when it has
// the frame) while the window stays responsive; once it is in, the window runs the GPU techniques on its
// own thread (they need its GL context). The grid is a snapshot: it does not follow later changes, except
// while the window's animation plays (P): then every GPU technique renders each played frame side by side
// (the lights moving as in the window, and the camera too along a --path that moves it; FrameInput::frame
// advancing), each tile with its run time and the running change of its L_air (temporal_monitor.h). The
// reference tile keeps the still frame; along a --path the window renders the reference on the loop's
// frames (path_reference.h), and each tile also scores the change of its error against them, the
// flicker `report --temporal` ranks by. When play stops the tiles show the still frame again.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "cpu_worker.h"
#include "pane_image.h"
#include "run_pool.h"
#include "temporal_monitor.h"
#include "plot/plot.h"
#include "report/error_metrics.h"
#include "report/first_hits.h"
#include "scene/scene.h"

namespace airlight {

struct ComparisonTile {
    std::string technique, failure;
    PaneImage pane;  // empty until the technique has run
    double milliseconds = 0.0;
    viz::report::ErrorMetrics error;
    // Its relative L2 over the pixels whose first hit agrees (ComparisonGrid::silhouettePixels); the same
    // as error.relativeL2 where the view has no silhouette pixel.
    double relativeL2Agreeing = viz::report::kUndefined;
    TemporalMonitor temporal{};  // while playing: the change of its L_air from frame to frame
    viz::Image lastAirlight{};   // what its pane shows (the first played frame is compared with it)
    double playMilliseconds = 0.0;  // the last played frame's run time
};

// A tile's error as its caption says it: the relative L2 error, or why there is none (a NaN or Inf
// pixel; a reference that is black where the technique is not, then the largest absolute difference).
std::string tileErrorText(const viz::report::ErrorMetrics& error);
// A tile's run time as its caption says it: "281.7 ms" (with `decimals` digits) under a second, "2.41 s"
// from a second on, so that a slow technique's caption is no longer than a fast one's.
std::string tileTimeText(double milliseconds, int decimals = 1);
// Where the view has `silhouettes` pixels (report/first_hits.h), the error without them ("0.0235 w/o 4
// silhouettes", short enough for a small tile); empty where it has none.
std::string silhouetteErrorText(double relativeL2Agreeing, std::size_t silhouettes);

class ComparisonGrid {
public:
    // The reference renders on the pool's Worker::Comparison thread, a new one for every open.
    explicit ComparisonGrid(RunPool& pool) : mPool(pool) {}

    // Runs technique `id` once on `scene` at `size` with the window's settings for it (throws on failure).
    // `frame`: FrameInput::frame (0 for the still frame).
    using RunTechnique = std::function<viz::FrameOutput(const std::string& id, const viz::scene::Scene& scene,
                                                        glm::ivec2 size, int frame)>;

    // Starts the reference for `scene` (its camera is the view compared) at `size`; one tile per id.
    void open(const viz::scene::Scene& scene, glm::ivec2 size, const std::vector<std::string>& ids);
    void close();
    bool isOpen() const { return !mTiles.empty(); }
    // Automation waits while the reference renders or the techniques are still to run.
    bool pending() const { return mWaiting || mDue; }
    // The reference is in: call runTechniques (at the start of a frame, after one that said so).
    bool due() const { return mDue; }

    // Takes the reference's full-size pass when the worker has it.
    void poll();
    // Runs every technique but the reference twice and keeps the second run (the first compiles shaders
    // and allocates), its time and its error against the reference, over all pixels and over those whose
    // first hit agrees (the silhouette pixels are found by the first call after the reference is in: it
    // needs the GL context; stopPlaying's call reuses them).
    void runTechniques(const RunTechnique& run);
    // Playing (the reference is in): every technique but the reference once on `moved` (the window's
    // moving lights; its camera with `followCamera`, else the snapshot's) as frame `frame`; its tile shows
    // it with its time and running change, and the change of its error where `reference` (the reference on
    // this frame at the grid's size and camera) is known. stopPlaying() shows the still frame again
    // (runTechniques on the snapshot).
    void playFrame(const viz::scene::Scene& moved, int frame, const RunTechnique& run, bool followCamera = false,
                   std::shared_ptr<const viz::Image> reference = nullptr);
    bool playing() const { return mPlayedFrames > 0; }
    int playedFrames() const { return mPlayedFrames; }
    void stopPlaying(const RunTechnique& run);
    // The snapshot's scene (its camera is the one compared) and the tiles' image size.
    const viz::scene::Scene& scene() const { return mScene; }
    glm::ivec2 size() const { return mSize; }

    std::vector<ComparisonTile>& tiles() { return mTiles; }
    const std::vector<ComparisonTile>& tiles() const { return mTiles; }
    float exposure() const { return mExposure; }  // EV, from the reference's image, shared by every tile
    // The snapshot's silhouette pixels, where the rasterised and the traced first hit differ (0 until the
    // techniques have run, or where the reference published no distance).
    std::size_t silhouettePixels() const { return mFirstHits.disagreeing; }
    // What a tile without an image says ("computing the reference... pass 2/4").
    std::string waitingText() const;
    // Each technique as a point: run time against relative L2, both on log axes.
    viz::plot::PlotSpec errorAgainstTime() const;
    // The tiles' figures for the screenshot sidecar.
    nlohmann::json toJson() const;

private:
    RunPool& mPool;
    std::vector<ComparisonTile> mTiles;
    CpuWorker* mWorker = nullptr;  // the reference's, the pool's while the grid is open
    bool mWaiting = false, mDue = false;
    viz::Image mReference;
    std::optional<viz::Image> mTracedDistance;  // the reference's reference.distance, until the mask is made
    viz::report::FirstHitMask mFirstHits;       // once per snapshot, by the first runTechniques
    viz::scene::Scene mScene;
    glm::ivec2 mSize{0};
    float mExposure = 0.0f;
    int mPlayedFrames = 0;
};

}  // namespace airlight
