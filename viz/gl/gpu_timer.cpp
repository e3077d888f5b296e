#include "gl/gpu_timer.h"

#include "core/error.h"

namespace viz::gl {

GpuTimer::GpuTimer(std::size_t ring) : mRing(ring < 1 ? 1 : ring) {}

GpuTimer::Pair GpuTimer::takePair() {
    if (!mFree.empty()) {
        Pair p = std::move(mFree.back());
        mFree.pop_back();
        return p;
    }
    GLuint ids[2] = {0, 0};
    glCreateQueries(GL_TIMESTAMP, 2, ids);
    return {Handle<QueryTraits>(ids[0]), Handle<QueryTraits>(ids[1])};
}

void GpuTimer::begin() {
    Pair p = takePair();
    glQueryCounter(p.start.get(), GL_TIMESTAMP);
    mOpen.emplace_back(std::move(p), std::chrono::steady_clock::now());
}

void GpuTimer::read(Waiting& w) {
    GLuint64 start = 0, end = 0;
    glGetQueryObjectui64v(w.queries.start.get(), GL_QUERY_RESULT, &start);
    glGetQueryObjectui64v(w.queries.end.get(), GL_QUERY_RESULT, &end);
    mLatest[w.stage] = end > start ? double(end - start) * 1e-6 : 0.0;
    mFree.push_back(std::move(w.queries));
}

std::size_t GpuTimer::poll() {
    std::size_t n = 0;
    // In order: the GPU answers queries in the order it ran them, so the first not ready ends the scan.
    while (!mWaiting.empty()) {
        GLint ready = 0;
        glGetQueryObjectiv(mWaiting.front().queries.end.get(), GL_QUERY_RESULT_AVAILABLE, &ready);
        if (!ready) break;
        read(mWaiting.front());
        mWaiting.pop_front();
        ++n;
    }
    return n;
}

StageTiming GpuTimer::end(const std::string& stage) {
    VIZ_CHECK(!mOpen.empty(), "GpuTimer::end called without begin");
    auto [pair, started] = std::move(mOpen.back());
    mOpen.pop_back();
    glQueryCounter(pair.end.get(), GL_TIMESTAMP);
    const double wall =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
    mWaiting.push_back({stage, std::move(pair)});
    poll();
    if (mLatest.find(stage) == mLatest.end()) {
        // Nothing known for this stage yet: wait for its own result (and everything queued before it).
        while (!mWaiting.empty()) {
            const bool mine = mWaiting.size() == 1;
            read(mWaiting.front());
            mWaiting.pop_front();
            if (mine) break;
        }
    }
    while (mWaiting.size() > mRing) {  // the GPU lags far behind: wait for the oldest
        read(mWaiting.front());
        mWaiting.pop_front();
    }
    return {stage, mLatest.at(stage), wall};
}

double GpuTimer::latest(const std::string& stage) const {
    const auto it = mLatest.find(stage);
    return it == mLatest.end() ? -1.0 : it->second;
}

}  // namespace viz::gl
