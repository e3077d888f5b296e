// Ending a worker thread that shares its state through a shared_ptr (CpuWorker, PathReference).
#pragma once

#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <thread>

namespace airlight {

// Sets `quit` under `mutex` and wakes the thread. A thread that is idle (`busy` false) is joined; one busy
// with a run, which cannot be interrupted, is detached to finish it on the shared state, so that closing
// the window does not wait for it (`what` names the run on stderr).
inline void endWorker(std::thread& thread, std::mutex& mutex, std::condition_variable& wake, bool& quit,
                      const bool& busy, const char* what) {
    bool running = false;
    {
        std::lock_guard lock(mutex);
        quit = true;
        running = busy;
    }
    wake.notify_all();
    if (running) {
        std::fprintf(stderr, "airlight: leaving %s to finish in the background\n", what);
        thread.detach();
    } else {
        thread.join();
    }
}

}  // namespace airlight
