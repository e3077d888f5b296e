#include "gl/stage_clock.h"

#include "core/error.h"
#include "gl/context_info.h"

namespace viz::gl {

StageClock::StageClock() : StageClock(methodForRenderer(contextInfo().renderer)) {}

StageClock::StageClock(ClockMethod method) : mMethod(method) {
    if (mMethod == ClockMethod::TimeElapsedQuery) {
        GLuint id = 0;
        glCreateQueries(GL_TIME_ELAPSED, 1, &id);
        mQuery = Handle<QueryTraits>(id);
    }
}

void StageClock::begin() {
    VIZ_CHECK(!mRunning, "StageClock::begin called twice without endMilliseconds");
    mRunning = true;
    mWallStart = std::chrono::steady_clock::now();
    if (mMethod == ClockMethod::TimeElapsedQuery) {
        glBeginQuery(GL_TIME_ELAPSED, mQuery.get());
    } else {
        // Earlier work must not be billed to this stage.
        glFinish();
        mStart = mWallStart = std::chrono::steady_clock::now();
    }
}

double StageClock::endMilliseconds() {
    VIZ_CHECK(mRunning, "StageClock::endMilliseconds called without begin");
    mRunning = false;
    if (mMethod == ClockMethod::TimeElapsedQuery) {
        glEndQuery(GL_TIME_ELAPSED);
        GLuint64 nanoseconds = 0;
        // GL_QUERY_RESULT waits until the result is available.
        glGetQueryObjectui64v(mQuery.get(), GL_QUERY_RESULT, &nanoseconds);
        return static_cast<double>(nanoseconds) * 1e-6;
    }
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - mStart)
        .count();
}

StageTiming StageClock::end(const std::string& stage) {
    const double ms = endMilliseconds();
    const double wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - mWallStart).count();
    return {stage, ms, wall};
}

std::string StageClock::method() {
    return methodName(methodForRenderer(contextInfo().renderer));
}

std::string StageClock::methodName(ClockMethod method) {
    return method == ClockMethod::TimeElapsedQuery ? "GL_TIME_ELAPSED" : "glFinish+steady_clock";
}

ClockMethod StageClock::methodForRenderer(const std::string& renderer) {
    return isSoftwareRenderer(renderer) ? ClockMethod::FinishSteadyClock
                                        : ClockMethod::TimeElapsedQuery;
}

}  // namespace viz::gl
