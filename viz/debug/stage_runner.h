// One run of a technique's declared stages. The runner does what every stage repeats: it times the stage
// with the run's clock and records the time, carries over a stage whose outputs the instance kept
// (StageInfo::keepsOutputs, when the caller resumes after it: debug/stage_reuse.h), notes how far the run
// got, and answers whether the run stops there (FrameInput::stopAfterStage). A technique's run() is then
// a list of stages:
//
//     StageRunner stages(mStages, input, out, mReuse, clock);  // clock: a StageTimer
//     if (!stages.run(kRectifyIndex, [&] { rectify(); }, [&] { publishRectified(out); })) return out;
//
// `work` is timed; `publish` (read-backs and intermediates built on the CPU for the debugger) is not.
// Stage indices come from the declared order (stageIndexOf), never from a hand-kept enum.
#pragma once

#include <array>
#include <string_view>
#include <vector>

#include "debug/stage_reuse.h"
#include "debug/technique.h"
#include "debug/timing.h"

namespace viz {

// The index of stage `id` in a technique's declared order. Used in constant expressions, so an id missing
// from the order fails to compile; checkStageOrder() ties the order to the declared StageInfo list.
template <std::size_t N>
constexpr int stageIndexOf(const std::array<std::string_view, N>& order, std::string_view id) {
    for (std::size_t i = 0; i < N; ++i)
        if (order[i] == id) return int(i);
    throw "stage id not in the technique's stage order";
}

// Throws (a programmer error) unless `stages` lists exactly the ids of `order`, in that order.
void checkStageOrder(const std::vector<StageInfo>& stages, const std::string_view* order, std::size_t count);
template <std::size_t N>
void checkStageOrder(const std::vector<StageInfo>& stages, const std::array<std::string_view, N>& order) {
    checkStageOrder(stages, order.data(), N);
}

class StageRunner {
public:
    // Begins the run: `reuse` learns where it starts (out.firstStageRun), out.timing which clock. The
    // stages are timed by `timer`, or by the caller's input.timer where it gives one.
    StageRunner(const std::vector<StageInfo>& stages, const FrameInput& input, FrameOutput& out, StageReuse& reuse,
                StageTimer& timer);

    // Runs stage `stage` (or carries it over), then returns whether the run goes on past it.
    template <class Work, class Publish>
    bool run(int stage, Work&& work, Publish&& publish) {
        if (carries(stage)) {
            mReuse.carry(stage, mOut);
        } else {
            mTimer.begin();
            work();
            mOut.timing.stages.push_back(mTimer.end(mStages[std::size_t(stage)].id));
            publish();
            if (mStages[std::size_t(stage)].keepsOutputs) mReuse.ran(stage, mOut);
        }
        mOut.lastStageRun = stage;
        return stage != mStop;
    }
    template <class Work>
    bool run(int stage, Work&& work) {
        return run(stage, std::forward<Work>(work), [] {});
    }

    // Whether this run carries stage `stage` over instead of running it.
    bool carries(int stage) const {
        return mStages[std::size_t(stage)].keepsOutputs && mReuse.carries(stage);
    }
    // Whether stage `stage` redoes only what the cursor's sub-step changes (FrameInput::substepOnly).
    bool substepOnly(int stage) const { return mReuse.substepOnly(stage); }
    // The stage the run stops after (the last one when the caller asked for none).
    int stop() const { return mStop; }
    // Whether the run gets as far as stage `stage`.
    bool reaches(int stage) const { return stage <= mStop; }

private:
    const std::vector<StageInfo>& mStages;
    FrameOutput& mOut;
    StageReuse& mReuse;
    StageTimer& mTimer;
    int mStop = 0;
};

}  // namespace viz
