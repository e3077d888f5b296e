// Row-parallel loops for the reference (oneTBB), with an optional terminal progress line. Each row is
// computed by exactly one thread and writes only its own pixels, so results do not depend on the thread
// count.
#pragma once

#include <functional>
#include <string>

namespace viz::reference {

// One line on stderr updated in place ("label  42%  elapsed 3.1 s  ETA 4.2 s"), shown only when
// stderr is a terminal. finish() ends the line.
class ProgressBar {
public:
    explicit ProgressBar(bool enabled);
    bool enabled() const { return mEnabled; }
    void update(const std::string& label, double fraction, double elapsedSeconds);
    void finish();

private:
    bool mEnabled = false;
    bool mDrawn = false;
};

// Whether stderr is a terminal (progress lines would otherwise litter logs).
bool stderrIsTerminal();

// threads <= 0: std::thread::hardware_concurrency(). Calls row(y) for y in [0, rows) on that many
// threads; an exception thrown by a row stops the others and is rethrown here.
void parallelRows(int rows, int threads, const std::function<void(int)>& row, ProgressBar* progress,
                  const std::string& label);

int resolveThreadCount(int threads);

}  // namespace viz::reference
