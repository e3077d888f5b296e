// The band across the bottom of the frame view while a run is under way: the GL technique's "rendering..."
// line, or the CPU worker's pass, its size, its time and, when the previous pass gives an estimate, how far
// along it is.
#pragma once

#include <string>

#include "cpu_worker.h"

namespace airlight {

struct ProgressBand {
    std::string text;
    float fraction = -1.0f;  // in [0, 0.99] when estimated; negative: no bar
};

// `lastRunSeconds` is quoted only when there is an earlier output.
std::string renderingText(bool haveOutput, double lastRunSeconds);

// From the worker's progress (busy). Pass 0: the request waits for the worker to take it. The estimate
// is the previous pass's time per pixel times this pass's pixels; once the pass has run past 1.5 times
// it (the previous pass came from the cache, say), it is dropped rather than shown as a full bar.
ProgressBand cpuProgressBand(const CpuProgress& progress);

}  // namespace airlight
