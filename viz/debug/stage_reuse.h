// Stage-level reuse inside one technique instance. A run told to resume at stage k
// (FrameInput::resumeAtStage) skips stages 0 .. k-1 and republishes what they published the last time
// they ran: their GL textures are still the instance's own and still hold those results, because only
// the stage that computes a texture writes it. The stage runner (debug/stage_runner.h) records each stage
// that declares StageInfo::keepsOutputs as it runs (ran) and, for one it skips, carries the record over
// (carry). The caller (app/run_scheduler.h) vouches that the
// skipped stages' inputs did not change; this class makes sure they ran completely last time.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "debug/technique.h"

namespace viz {

class StageReuse {
public:
    // At the start of run(): the first stage this run computes, input.resumeAtStage lowered to the first
    // stage with no complete record (a failed or shorter previous run). Records from it on are dropped:
    // they belong to outputs this run replaces. Sets out.firstStageRun.
    int begin(const FrameInput& input, FrameOutput& out);
    // Whether this run skips stage `stage` (then carry() it instead of running it).
    bool carries(int stage) const { return stage < mFirst; }
    // Whether this run redoes only what the cursor's sub-step changes in `stage` (FrameInput::substepOnly,
    // when every stage before it is carried).
    bool substepOnly(int stage) const { return mSubstepOnly && stage == mFirst; }
    // Republishes the intermediates and notes that stage `stage` published when it last ran.
    void carry(int stage, FrameOutput& out);
    // After stage `stage` ran: what it published is what `out` gained since the previous stage.
    void ran(int stage, const FrameOutput& out);

private:
    struct Record {
        bool complete = false;
        std::vector<Intermediate> intermediates;
        std::vector<std::string> notes;
    };
    std::vector<Record> mRecords;
    int mFirst = 0;
    bool mSubstepOnly = false;
    std::size_t mIntermediates = 0, mNotes = 0;  // out's sizes after the last recorded stage
};

}  // namespace viz
