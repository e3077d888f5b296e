// Work counters: what a GPU run costs in units that do not depend on the GPU or its driver (shadow-map
// lookups and texels, ray samples, closed-form segments and their quadrature nodes, tree nodes,
// fragments, voxels), the figure that carries over from llvmpipe to any GPU. A counting run compiles
// every program with COUNT_WORK, whose shaders add to the counters (shaders/common/work_counters.glsl); an
// ordinary run compiles them out and is unchanged. The counters live in one SSBO per context; StageClock reads them at the start and end of
// every stage, so each stage's record carries the work it did (debug/timing.h, StageTiming::work).
// Counts are 32-bit and wrap: a stage's count is exact below 2^32.
#pragma once

#include <optional>

#include <glm/vec2.hpp>

#include "debug/timing.h"

namespace viz::gl {

class WorkCounters {
public:
    // While enabled, Program::compile adds COUNT_WORK to every program: programs compiled before keep
    // counting nothing (make a fresh technique instance after enabling). Only for the GL context of
    // the thread that enables it.
    static void setEnabled(bool enabled);
    static bool enabled();
    // Count only the invocations that name this pixel with WORK_PIXEL (per-pixel shaders: column, GL
    // row 0 at the bottom), or every invocation (nullopt, the default).
    static void countPixel(std::optional<glm::ivec2> pixel);

    // The current totals (waits for the GPU); zeros when counting is off.
    static WorkCounts read();
    // Binds the counter buffer (creating it on first use) at its binding point; StageClock calls it.
    static void bind();
    // Frees the buffer (before the context goes).
    static void release();

    static const char* name(int counter);  // "shadow_lookups", ...
};

// What a stage did between two reads (wrap-around safe).
WorkCounts workBetween(const WorkCounts& before, const WorkCounts& after);

}  // namespace viz::gl
