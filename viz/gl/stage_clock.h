// gl::StageClock: wall time of one GPU stage. On Mesa llvmpipe/softpipe GL timer queries do not
// measure the rasterization work (it runs in worker threads the query does not see), so the stage
// is bracketed by glFinish and std::chrono::steady_clock ("glFinish+steady_clock"); on other
// drivers GPU timestamp queries are used ("GL_TIMESTAMP"). The method is chosen when the clock
// is created (needs a current context) from the renderer string.
// The GPU method reads two GL_TIMESTAMP queries (glQueryCounter) around the stage rather than a
// GL_TIME_ELAPSED query: only one GL_TIME_ELAPSED query may be active at a time, and a stage that runs
// another technique inside it (ivsv's gather runs vsv for the point, spot and directional lights) then
// made GL_INVALID_OPERATION and lost its inner times on an NVIDIA driver; timestamps nest.
#pragma once

#include <epoxy/gl.h>

#include <chrono>
#include <cstdint>
#include <string>

#include "debug/timing.h"
#include "gl/timestamp_pair.h"

namespace viz::gl {

enum class ClockMethod { FinishSteadyClock, TimestampQuery };

class StageClock final : public StageTimer {
public:
    StageClock();                             // method chosen from the current renderer
    explicit StageClock(ClockMethod method);  // forced (benchmarks compare the two)

    void begin() override;
    // Ends the stage and returns its duration in milliseconds. Waits for the GPU (glFinish, or the
    // query result).
    double endMilliseconds();
    // endMilliseconds() as a record of `stage`, with the CPU wall time from begin() until the result was
    // known (debug/timing.h), and in a counting run the work the stage did (gl/work_counters.h).
    StageTiming end(const std::string& stage) override;
    std::string name() const override { return methodName(mMethod); }

    ClockMethod clockMethod() const { return mMethod; }
    // "glFinish+steady_clock" or "GL_TIMESTAMP" for the current context.
    static std::string method();
    static std::string methodName(ClockMethod method);
    static ClockMethod methodForRenderer(const std::string& renderer);

private:
    ClockMethod mMethod;
    TimestampPair mQueries;  // TimestampQuery only
    std::chrono::steady_clock::time_point mStart, mWallStart;
    bool mRunning = false;
    WorkCounts mWorkAtBegin;  // counting runs (gl/work_counters.h): the totals when the stage began
    std::uint64_t mCompiledAtBegin = 0;  // gl::programsCompiledOnThisThread() when the stage began
};

}  // namespace viz::gl
