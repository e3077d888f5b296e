#include "debug/stage_reuse.h"

#include <algorithm>

namespace viz {

int StageReuse::begin(const FrameInput& input, FrameOutput& out) {
    int first = std::max(0, input.resumeAtStage);
    for (int k = 0; k < first; ++k)
        if (k >= int(mRecords.size()) || !mRecords[std::size_t(k)].complete) {
            first = k;
            break;
        }
    mFirst = first;
    mSubstepOnly = input.substepOnly && first == input.resumeAtStage;
    if (int(mRecords.size()) > first) mRecords.resize(std::size_t(first));
    mIntermediates = out.intermediates.size();
    mNotes = out.notes.size();
    out.firstStageRun = first;
    return first;
}

void StageReuse::carry(int stage, FrameOutput& out) {
    const Record& r = mRecords.at(std::size_t(stage));
    out.intermediates.insert(out.intermediates.end(), r.intermediates.begin(), r.intermediates.end());
    out.notes.insert(out.notes.end(), r.notes.begin(), r.notes.end());
    mIntermediates = out.intermediates.size();
    mNotes = out.notes.size();
}

void StageReuse::ran(int stage, const FrameOutput& out) {
    if (int(mRecords.size()) <= stage) mRecords.resize(std::size_t(stage) + 1);
    Record& r = mRecords[std::size_t(stage)];
    r.intermediates.assign(out.intermediates.begin() + std::ptrdiff_t(mIntermediates), out.intermediates.end());
    r.notes.assign(out.notes.begin() + std::ptrdiff_t(mNotes), out.notes.end());
    r.complete = true;
    mIntermediates = out.intermediates.size();
    mNotes = out.notes.size();
    // A later stage's record was computed from this stage's previous output.
    mRecords.resize(std::size_t(stage) + 1);
}

}  // namespace viz
