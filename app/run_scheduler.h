// Running a technique for one consumer of its images (the window's main views), re-running only what
// changed. A run is identified by a RunKey: the scene's content (camera included), the size, the
// complete settings and the stepping cursor. Against the key of the instance's previous run, resumePoint
// finds the first stage whose inputs changed (the parameters it declares in StageInfo::params, the scene,
// the size, or the cursor leaving a stage it had cut short); the technique skips the stages before it and
// republishes what they published (debug/stage_reuse.h). A cursor that moved only inside one stage
// re-runs that stage alone, told that only the sub-step changed.
//
// Each RunScheduler owns its technique instance: textures it publishes are the scheduler's own, so another
// consumer's run (a difference view, the comparison grid) never replaces them behind its back.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "debug/technique.h"
#include "scene/scene.h"

namespace airlight {

// Where the stepping cursor stands: stage index (-1: the complete frame) and sub-step (1-based as
// Technique::substepValues lists them; 0: the stage whole).
struct StepCursor {
    int stage = -1;
    int substep = 0;
    bool operator==(const StepCursor&) const = default;
};

struct RunKey {
    std::string scene;  // viz::scene::sceneContentHash: geometry, materials, lights, medium, camera
    int width = 0, height = 0;
    viz::Settings settings;  // complete
    StepCursor cursor;
    std::vector<std::string> views;  // the on-demand intermediates asked for (FrameInput::views), sorted
    int frame = 0;  // FrameInput::frame: a technique whose settings read it (Technique::readsFrame) restarts
};

struct ResumePoint {
    int stage = 0;             // the first stage to compute
    bool substepOnly = false;  // that stage differs from the previous run in the cursor's sub-step only
};

// Where a run with key `next` may start after the same instance's run with key `previous` computed
// stages 0 .. previousLastStage (FrameOutput::lastStageRun; -1: it failed). Stage k's output stands when
// the scene, the size and every parameter of stages 0 .. k are unchanged and the previous run finished
// stage k whole (not stopped at an earlier sub-step of it), and asks for the same on-demand views of it
// (StageInfo::onDemand). The run always computes the cursor's stage.
ResumePoint resumePoint(const viz::Technique& technique, const RunKey& previous, int previousLastStage,
                        const RunKey& next);

class RunScheduler {
public:
    explicit RunScheduler(std::unique_ptr<viz::Technique> technique) : mTechnique(std::move(technique)) {}
    viz::Technique& technique() { return *mTechnique; }
    const viz::Technique& technique() const { return *mTechnique; }

    // Runs the technique on `scene` (its camera included) at `width` x `height` with complete `settings`,
    // stopping at `cursor`, resuming after the previous run where resumePoint allows. `views`: the
    // intermediates the caller shows; those the stages draw on demand are asked for.
    viz::FrameOutput run(const viz::scene::Scene& scene, int width, int height, const viz::Settings& settings,
                         StepCursor cursor, const std::vector<std::string>& views = {}, int frame = 0);
    // The on-demand intermediates among `shown` (sorted, once each): what a run asked to show them draws.
    std::vector<std::string> onDemandAmong(const std::vector<std::string>& shown) const;
    // The on-demand views the last run drew.
    const std::vector<std::string>& lastViews() const { return mLastViews; }
    // Where the last run started (for the status line and the tests).
    ResumePoint lastResume() const { return mResume; }
    // The next run starts from stage 0 (its textures were touched by someone else, a GL reset, ...).
    void invalidate() { mPrevious.reset(); }
    // The clock a GPU technique's stages are timed by (FrameInput::timer; null: the technique's own).
    void setTimer(viz::StageTimer* timer) { mTimer = timer; }

private:
    std::unique_ptr<viz::Technique> mTechnique;
    viz::StageTimer* mTimer = nullptr;
    std::optional<RunKey> mPrevious;
    int mPreviousLastStage = -1;
    ResumePoint mResume;
    std::vector<std::string> mLastViews;
};

}  // namespace airlight
