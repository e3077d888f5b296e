// Work counters: what a GPU run costs in units that do not depend on the GPU or its driver (shadow-map
// lookups and texels, ray samples, closed-form segments and their quadrature nodes, tree nodes,
// fragments, voxels, primitives drawn), the figure that carries over from llvmpipe to any GPU. A counting
// run compiles every program with COUNT_WORK, whose shaders add to the counters
// (shaders/common/work_counters.glsl); an ordinary run compiles them out and is unchanged. The counters
// live in one SSBO per context. One more, kWorkPrimitives, is the GL's own: the primitives (triangles,
// lines, points) its draws assembled, before clipping and culling, from a GL_PRIMITIVES_GENERATED query
// kept running through a counting run and restarted at every read. StageClock reads them all at the start
// and end of every stage, so each stage's record carries the work it did (debug/timing.h,
// StageTiming::work). Counts are 32-bit and wrap: a stage's count is exact below 2^32.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "debug/timing.h"

// The shader counters' indices, shared with the shaders (as render/host_device.h does).
#include "../../shaders/common/host_device.glsl"

namespace viz::gl {

// After the shader counters in WorkCounts: the primitives the GL assembled (GL_PRIMITIVES_GENERATED).
inline constexpr int kWorkPrimitives = render::hd::kWorkCounterCount;
inline constexpr int kWorkCounts = kWorkPrimitives + 1;  // WorkCounts' size in a counting run

class WorkCounters {
public:
    // While enabled, Program::compile adds COUNT_WORK to every program: programs compiled before keep
    // counting nothing (make a fresh technique instance after enabling). Only for the GL context of
    // the thread that enables it, which must be current when it is disabled again (the primitives'
    // query ends then).
    static void setEnabled(bool enabled);
    static bool enabled();
    // Count only the invocations that name this pixel with WORK_PIXEL (per-pixel shaders: column, GL
    // row 0 at the bottom), or every invocation (nullopt, the default).
    static void countPixel(std::optional<glm::ivec2> pixel);

    // The current totals, kWorkCounts of them (waits for the GPU); empty when counting is off.
    static WorkCounts read();
    // Binds the counter buffer (creating it on first use) at its binding point; StageClock calls it.
    static void bind();
    // Frees the buffer (before the context goes).
    static void release();

    static const char* name(int counter);  // "shadow_lookups", ..., "primitives"
};

// What a stage did between two reads (wrap-around safe).
WorkCounts workBetween(const WorkCounts& before, const WorkCounts& after);

}  // namespace viz::gl
