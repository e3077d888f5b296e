#include "gl/gpu_timer.h"

#include "core/error.h"

namespace viz::gl {

GpuTimer::GpuTimer(std::size_t ring) : mRing(ring < 1 ? 1 : ring) {}

void GpuTimer::begin() {
    TimestampPair p;
    if (mFree.empty()) {
        p = TimestampPair::create();
    } else {
        p = std::move(mFree.back());
        mFree.pop_back();
    }
    p.markStart();
    mOpen.emplace_back(std::move(p), std::chrono::steady_clock::now());
}

void GpuTimer::readOldest() {
    Waiting& w = mWaiting.front();
    mLatest[w.stage] = w.queries.milliseconds();
    mFree.push_back(std::move(w.queries));
    mWaiting.pop_front();
}

std::size_t GpuTimer::poll() {
    std::size_t n = 0;
    // In order: the GPU answers queries in the order it ran them, so the first not ready ends the scan.
    for (; !mWaiting.empty() && mWaiting.front().queries.ready(); ++n) readOldest();
    return n;
}

StageTiming GpuTimer::end(const std::string& stage) {
    VIZ_CHECK(!mOpen.empty(), "GpuTimer::end called without begin");
    auto [pair, started] = std::move(mOpen.back());
    mOpen.pop_back();
    pair.markEnd();
    const double wall =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
    mWaiting.push_back({stage, std::move(pair)});
    poll();
    // Nothing known for this stage yet: wait for its own result, the last queued (and so for all of them).
    if (!mLatest.contains(stage))
        while (!mWaiting.empty()) readOldest();
    while (mWaiting.size() > mRing) readOldest();  // the GPU lags far behind: wait for the oldest
    return {stage, mLatest.at(stage), wall};
}

double GpuTimer::latest(const std::string& stage) const {
    const auto it = mLatest.find(stage);
    return it == mLatest.end() ? -1.0 : it->second;
}

}  // namespace viz::gl
