#include "run_scheduler.h"

#include <algorithm>
#include <set>

#include "scene/scene_source.h"

namespace airlight {

namespace {

// The cursor's stage as an index (-1: the last stage) and its sub-step, 0 when it runs the stage whole.
StepCursor normalised(const viz::Technique& t, const RunKey& key) {
    const int n = int(t.stages().size());
    StepCursor c = key.cursor;
    if (c.stage < 0 || c.stage >= n) c.stage = n - 1;
    const int count = int(t.substepValues(c.stage, key.settings).size());
    if (c.substep <= 0 || c.substep >= count) c.substep = 0;
    return c;
}

}  // namespace

ResumePoint resumePoint(const viz::Technique& t, const RunKey& previous, int previousLastStage, const RunKey& next) {
    const auto& stages = t.stages();
    const int n = int(stages.size());
    if (n == 0 || previous.scene != next.scene || previous.width != next.width || previous.height != next.height)
        return {};
    // Noise that changes from frame to frame (raymarch jitter_time=per-frame, ivsv subsets=per-frame).
    if (previous.frame != next.frame && t.readsFrame(next.settings)) return {};
    const StepCursor was = normalised(t, previous), now = normalised(t, next);

    // The first stage reading a parameter that changed; a changed parameter no stage declares: stage 0.
    if (previous.settings.size() != next.settings.size()) return {};
    int changed = n;
    std::set<std::string> declared;
    for (const auto& st : stages) declared.insert(st.params.begin(), st.params.end());
    // A stage with an on-demand view asked for by one run and not the other computes again.
    for (int k = 0; k < n; ++k)
        for (const std::string& id : stages[std::size_t(k)].onDemand) {
            const bool before = std::binary_search(previous.views.begin(), previous.views.end(), id);
            if (before != std::binary_search(next.views.begin(), next.views.end(), id)) changed = std::min(changed, k);
        }
    for (const auto& [name, value] : next.settings) {
        const auto it = previous.settings.find(name);
        if (it != previous.settings.end() && it->second == value) continue;
        if (!declared.count(name)) return {};
        for (int k = 0; k < changed; ++k) {
            const auto& p = stages[std::size_t(k)].params;
            if (std::find(p.begin(), p.end(), name) != p.end()) changed = k;
        }
    }
    // Stages the previous run finished whole: up to its cursor's stage (that one only without a sub-step)
    // and no further than it got. The cursor's stage always runs: it is where the run stops.
    const int whole = std::min(was.substep == 0 ? was.stage : was.stage - 1, previousLastStage);
    ResumePoint r;
    r.stage = std::max(0, std::min({changed, whole + 1, now.stage}));
    // Only the sub-step moved inside the stage the previous run stopped in, every input of it the same.
    r.substepOnly = r.stage == now.stage && changed > now.stage && was.stage == now.stage &&
                    was.substep != now.substep && previousLastStage >= now.stage;
    return r;
}

std::vector<std::string> RunScheduler::onDemandAmong(const std::vector<std::string>& shown) const {
    return viz::onDemandAmong(*mTechnique, shown);
}

viz::FrameOutput RunScheduler::run(const viz::scene::Scene& scene, int width, int height, const viz::Settings& settings,
                                  StepCursor cursor, const std::vector<std::string>& views, int frame) {
    RunKey key{viz::scene::sceneContentHash(scene), width, height, settings, cursor, onDemandAmong(views), frame};
    mResume = mPrevious ? resumePoint(*mTechnique, *mPrevious, mPreviousLastStage, key) : ResumePoint{};
    viz::FrameInput input;
    input.scene = &scene;
    input.width = width;
    input.height = height;
    viz::setRunSettings(input, settings);
    const int n = int(mTechnique->stages().size());
    input.stopAfterStage = cursor.stage >= 0 && cursor.stage < n - 1 ? cursor.stage : -1;
    // A sub-step of the last stage: stop there explicitly so that the technique applies it.
    if (cursor.stage == n - 1 && cursor.substep > 0) input.stopAfterStage = cursor.stage;
    input.substep = cursor.substep;
    input.resumeAtStage = mResume.stage;
    input.substepOnly = mResume.substepOnly;
    input.views = key.views;
    input.frame = frame;
    input.timer = mTechnique->needsGl() ? mTimer : nullptr;  // GL only: the reference runs on a worker
    mLastViews = key.views;
    mPrevious.reset();  // a run that throws leaves nothing to resume from
    viz::FrameOutput out = mTechnique->run(input);
    mPrevious = std::move(key);
    mPreviousLastStage = out.lastStageRun;
    return out;
}

}  // namespace airlight
