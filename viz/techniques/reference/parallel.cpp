#include "techniques/reference/parallel.h"

#include <unistd.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <thread>

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
    // oneTBB's loop in an arena of the asked-for size: rows are handed out one by one (grain 1), each row
    // to one thread, so the image is the same for any thread count. A row's exception cancels the rest
    // and is rethrown here by parallel_for.
    tbb::task_arena arena(std::min(resolveThreadCount(threads), rows));
    const auto start = std::chrono::steady_clock::now();
    std::atomic<int> done{0};
    std::atomic<long long> lastDrawn{-1000};  // ms since start of the last progress line
    const bool show = progress && progress->enabled();
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, rows, 1), [&](const tbb::blocked_range<int>& range) {
            for (int y = range.begin(); y != range.end(); ++y) {
                row(y);
                const int finished = done.fetch_add(1) + 1;
                if (!show) continue;
                // At most four times a second: the thread that moves lastDrawn on draws the line.
                const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                const long long ms = (long long)(elapsed * 1000.0);
                long long last = lastDrawn.load();
                if (ms - last < 250 || !lastDrawn.compare_exchange_strong(last, ms)) continue;
                progress->update(label, double(finished) / rows, elapsed);
            }
        });
    });
}

}  // namespace viz::reference
