#include "techniques/reference/parallel.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace viz::reference {

bool stderrIsTerminal() { return ::isatty(STDERR_FILENO) == 1; }

ProgressBar::ProgressBar(bool enabled) : mEnabled(enabled) {}

void ProgressBar::update(const std::string& label, double fraction, double elapsedSeconds) {
    if (!mEnabled) return;
    fraction = std::clamp(fraction, 0.0, 1.0);
    const int width = 30;
    const int filled = int(fraction * width + 0.5);
    std::string bar(std::size_t(filled), '#');
    bar.resize(std::size_t(width), '.');
    char eta[32] = "?";
    if (fraction > 0.0) std::snprintf(eta, sizeof(eta), "%.1f s", elapsedSeconds * (1.0 - fraction) / fraction);
    // \r returns to the start of the line; \033[K clears what a longer previous line left behind.
    std::fprintf(stderr, "\r%-22s [%s] %5.1f%%  elapsed %.1f s  ETA %s\033[K", label.c_str(), bar.c_str(),
                 100.0 * fraction, elapsedSeconds, eta);
    std::fflush(stderr);
    mDrawn = true;
}

void ProgressBar::finish() {
    if (mEnabled && mDrawn) {
        std::fprintf(stderr, "\n");
        std::fflush(stderr);
    }
    mDrawn = false;
}

int resolveThreadCount(int threads) {
    if (threads > 0) return threads;
    return int(std::max(1u, std::thread::hardware_concurrency()));
}

void parallelRows(int rows, int threads, const std::function<void(int)>& row, ProgressBar* progress,
                  const std::string& label) {
    if (rows <= 0) return;
    const int count = std::min(resolveThreadCount(threads), rows);
    std::atomic<int> next{0};
    std::atomic<int> done{0};
    std::atomic<bool> failed{false};
    std::exception_ptr error;
    std::mutex mutex;
    std::condition_variable finished;

    auto worker = [&] {
        for (;;) {
            const int y = next.fetch_add(1);
            if (y >= rows || failed.load()) break;
            try {
                row(y);
            } catch (...) {
                std::lock_guard<std::mutex> lock(mutex);
                if (!error) error = std::current_exception();
                failed = true;
            }
            if (done.fetch_add(1) + 1 == rows) {
                std::lock_guard<std::mutex> lock(mutex);
                finished.notify_all();
            }
        }
    };

    const auto start = std::chrono::steady_clock::now();
    std::vector<std::thread> pool;
    pool.reserve(std::size_t(count));
    for (int i = 0; i < count; ++i) pool.emplace_back(worker);
    if (progress && progress->enabled()) {
        // The calling thread only redraws the progress line, a few times a second.
        std::unique_lock<std::mutex> lock(mutex);
        while (done.load() < rows && !failed.load()) {
            finished.wait_for(lock, std::chrono::milliseconds(250));
            const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            progress->update(label, double(done.load()) / rows, elapsed);
        }
    }
    for (auto& t : pool) t.join();
    if (error) std::rethrow_exception(error);
}

}  // namespace viz::reference
