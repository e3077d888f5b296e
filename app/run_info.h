// What the measuring commands (report, bench) share: the statement of the run (date, machine), a median,
// comma lists, file-name stems and the progress line on the terminal.
#pragma once

#include <string>
#include <vector>

#include "debug/technique.h"
#include "report/run_spread.h"

namespace airlight {

// "A,B,C" -> {"A", "B", "C"}; an empty entry is an InputError naming `flag`.
std::vector<std::string> splitList(const std::string& text, const std::string& flag);
// splitList for scene lists: pieces that together name an existing file ("my,hall.gltf") stay one entry,
// so a glTF path with a comma in it can be named.
std::vector<std::string> splitSceneList(const std::string& text, const std::string& flag);
double median(std::vector<double> v);  // 0 for no values
std::string utcNow();                  // "2026-11-26T16:41:38Z"
std::string machineDescription();      // "host, CPU model, N threads"
// "RENDERER, OpenGL VERSION" of the current GL context.
std::string rendererDescription();
// The renderer's fragment against compute arithmetic (gl::measureArithmeticRatio), measured before any
// technique runs, with its line for the page (gl::describeArithmeticRatio); where it handicaps the
// fragment-shaded passes the line is printed on stderr as a note too.
struct RendererArithmetic {
    double fragmentOverCompute = 0.0;
    std::string line;
};
RendererArithmetic measureRendererArithmetic();
// File-name friendly: letters, digits, '-' and '_' kept, anything else becomes '_'.
std::string fileStem(const std::string& text);

// A technique timed as the measuring commands time it: one warm-up run (shader compiles, uploads,
// caches), then `runs` timed runs; medians per stage (in the order the stages first ran) and of the totals,
// each with the fastest and slowest run beside it.
struct TimedRuns {
    viz::FrameOutput last;  // the last run's output
    struct Stage {
        std::string id;
        double milliseconds = 0.0;      // median by the record's clock
        double wallMilliseconds = 0.0;  // median CPU wall time (viz::StageTiming::wallMilliseconds)
        viz::report::RunSpread spread;  // of the record's clock
    };
    std::vector<Stage> stages;
    double totalMilliseconds = 0.0;  // median of the per-run sums of stage times
    double wallMilliseconds = 0.0;   // median steady-clock time of the whole run()
    viz::report::RunSpread totalSpread, wallSpread;
};
TimedRuns timeRuns(viz::Technique& technique, const viz::FrameInput& input, int runs);

// One line on the terminal, redrawn in place when stderr is a terminal (a line per step otherwise).
class Progress {
public:
    explicit Progress(int total);
    void show(int done, const std::string& what);
    void finish();

private:
    int mTotal;
    bool mTty;
};

}  // namespace airlight
