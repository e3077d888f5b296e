#include "gl/stage_clock.h"

#include "core/error.h"
#include "gl/context_info.h"
#include "gl/work_counters.h"

namespace viz::gl {

StageClock::StageClock() : StageClock(methodForRenderer(contextInfo().renderer)) {}

StageClock::StageClock(ClockMethod method) : mMethod(method) {
    if (mMethod == ClockMethod::TimestampQuery) {
        GLuint ids[2] = {0, 0};
        glCreateQueries(GL_TIMESTAMP, 2, ids);
        mStartQuery = Handle<QueryTraits>(ids[0]);
        mEndQuery = Handle<QueryTraits>(ids[1]);
    }
}

void StageClock::begin() {
    VIZ_CHECK(!mRunning, "StageClock::begin called twice without endMilliseconds");
    mRunning = true;
    if (WorkCounters::enabled()) {
        WorkCounters::bind();
        mWorkAtBegin = WorkCounters::read();  // waits for the GPU: a counting run's times mean nothing
    }
    mWallStart = std::chrono::steady_clock::now();
    if (mMethod == ClockMethod::TimestampQuery) {
        glQueryCounter(mStartQuery.get(), GL_TIMESTAMP);
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
        glQueryCounter(mEndQuery.get(), GL_TIMESTAMP);
        GLuint64 start = 0, end = 0;
        // GL_QUERY_RESULT waits until the result is available.
        glGetQueryObjectui64v(mStartQuery.get(), GL_QUERY_RESULT, &start);
        glGetQueryObjectui64v(mEndQuery.get(), GL_QUERY_RESULT, &end);
        return end > start ? static_cast<double>(end - start) * 1e-6 : 0.0;
    }
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - mStart)
        .count();
}

StageTiming StageClock::end(const std::string& stage) {
    const double ms = endMilliseconds();
    const double wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - mWallStart).count();
    StageTiming timing{stage, ms, wall};
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
