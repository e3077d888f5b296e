#include "gl/stage_clock.h"

#include "core/error.h"
#include "gl/context_info.h"
#include "gl/program.h"
#include "gl/work_counters.h"

namespace viz::gl {

StageClock::StageClock() : StageClock(methodForRenderer(contextInfo().renderer)) {}

StageClock::StageClock(ClockMethod method) : mMethod(method) {
    if (mMethod == ClockMethod::TimestampQuery) mQueries = TimestampPair::create();
}

void StageClock::begin() {
    VIZ_CHECK(!mRunning, "StageClock::begin called twice without endMilliseconds");
    mRunning = true;
    mCompiledAtBegin = programsCompiledOnThisThread();
    if (WorkCounters::enabled()) {
        WorkCounters::bind();
        mWorkAtBegin = WorkCounters::read();  // waits for the GPU: a counting run's times mean nothing
    }
    mWallStart = std::chrono::steady_clock::now();
    if (mMethod == ClockMethod::TimestampQuery) {
        mQueries.markStart();
    } else {
        // Earlier work must not be billed to this stage.
        glFinish();
        mStart = mWallStart = std::chrono::steady_clock::now();
    }
}

double StageClock::endMilliseconds() {
    VIZ_CHECK(mRunning, "StageClock::endMilliseconds called without begin");
    mRunning = false;
    if (mMethod == ClockMethod::TimestampQuery) {
        mQueries.markEnd();
        return mQueries.milliseconds();  // waits until the results are available
    }
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - mStart)
        .count();
}

StageTiming StageClock::end(const std::string& stage) {
    const double ms = endMilliseconds();
    const double wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - mWallStart).count();
    StageTiming timing{stage, ms, wall};
    timing.programsCompiled = int(programsCompiledOnThisThread() - mCompiledAtBegin);
    if (WorkCounters::enabled() && !mWorkAtBegin.empty()) timing.work = workBetween(mWorkAtBegin, WorkCounters::read());
    mWorkAtBegin.clear();
    return timing;
}

std::string StageClock::method() {
    return methodName(methodForRenderer(contextInfo().renderer));
}

std::string StageClock::methodName(ClockMethod method) {
    return method == ClockMethod::TimestampQuery ? "GL_TIMESTAMP" : "glFinish+steady_clock";
}

ClockMethod StageClock::methodForRenderer(const std::string& renderer) {
    return isSoftwareRenderer(renderer) ? ClockMethod::FinishSteadyClock
                                        : ClockMethod::TimestampQuery;
}

}  // namespace viz::gl
