// The reference's rows run on as many threads as asked, also while an Embree device exists: a device made
// with "threads=1" caps the whole process's oneTBB at one thread, and the reference then ran on one core
// whatever its `threads` setting said (visibility and airlight took as long with 2 threads as with 1).
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <set>
#include <thread>

#include <gtest/gtest.h>

#include "scene/builtin_scenes.h"
#include "techniques/reference/parallel.h"
#include "techniques/reference/ray_tracer.h"

namespace viz::reference {
namespace {

// Calls parallelRows(rows, 2, ...) and returns how many distinct threads were inside a row at once: each
// row waits (at most 10 s in all) until a second thread has entered a row too.
std::size_t threadsInsideRowsAtOnce(int rows) {
    std::mutex m;
    std::condition_variable cv;
    std::set<std::thread::id> inside;
    bool gaveUp = false;
    parallelRows(
        rows, 2,
        [&](int) {
            std::unique_lock lock(m);
            inside.insert(std::this_thread::get_id());
            cv.notify_all();
            if (!cv.wait_for(lock, std::chrono::seconds(10), [&] { return inside.size() >= 2 || gaveUp; }))
                gaveUp = true;
        },
        nullptr, "");
    return inside.size();
}

TEST(ParallelRows, TwoThreadsRunRowsAtOnce) {
    if (std::thread::hardware_concurrency() < 2) GTEST_SKIP() << "one core: no second thread to run a row";
    EXPECT_EQ(threadsInsideRowsAtOnce(16), 2u);
}

TEST(ParallelRows, TwoThreadsRunRowsAtOnceWhileARayTracerExists) {
    if (std::thread::hardware_concurrency() < 2) GTEST_SKIP() << "one core: no second thread to run a row";
    const RayTracer tracer(scene::makeBuiltinScene("grate"));
    EXPECT_EQ(threadsInsideRowsAtOnce(16), 2u);
}

}  // namespace
}  // namespace viz::reference
