// gl::GpuTimer: stage times on a GPU without waiting for them. gl::StageClock waits for each stage's result
// (glFinish, or the timestamp queries' results), which serialises the CPU and the GPU: right for `report`
// and `bench`, which want each stage's own time, but it costs an interactive window its overlap. GpuTimer
// brackets each stage with two GL_TIMESTAMP queries (they nest: a stage that runs another technique
// inside it times both) and does not wait: a stage's record carries the latest time known for that stage,
// from a frame or a few before, while its own queries wait in a ring to be read when the GPU has
// answered. A stage with no time known yet waits once for its own. The record's clock says so.
//
// Only where GL timer queries measure the work (not llvmpipe: gl/stage_clock.h) do its times mean
// anything; the window uses it there (app/run_scheduler.h), and tests drive its mechanics anywhere.
#pragma once

#include <chrono>
#include <cstddef>
#include <deque>
#include <map>
#include <string>
#include <vector>

#include "debug/timing.h"
#include "gl/timestamp_pair.h"

namespace viz::gl {

class GpuTimer final : public StageTimer {
public:
    // At most `ring` stages' queries wait to be read; one more waits for the oldest first (bounded memory
    // however long the GPU lags).
    explicit GpuTimer(std::size_t ring = 64);

    void begin() override;
    StageTiming end(const std::string& stage) override;
    std::string name() const override { return "GL_TIMESTAMP ring (no wait; times up to a few frames old)"; }

    // Reads every waiting stage whose result the GPU has; returns how many it read. end() calls it.
    std::size_t poll();
    std::size_t waiting() const { return mWaiting.size(); }
    // The latest GPU time known for `stage` (milliseconds), or a negative number.
    double latest(const std::string& stage) const;

private:
    struct Waiting {
        std::string stage;
        TimestampPair queries;
    };
    // Reads the oldest waiting stage (waiting for its result if it is not there yet) and frees its pair.
    void readOldest();

    std::size_t mRing;
    std::vector<TimestampPair> mFree;
    std::vector<std::pair<TimestampPair, std::chrono::steady_clock::time_point>> mOpen;  // begun, not ended (nested)
    std::deque<Waiting> mWaiting;
    std::map<std::string, double> mLatest;
};

}  // namespace viz::gl
