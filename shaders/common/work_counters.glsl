// Work counters (gl/work_counters.h): with COUNT_WORK defined (every program of a counting run) each
// WORK_COUNT(counter, n) adds n to one of kWorkCounterCount unsigned totals; without it the macro is
// empty and the shader is unchanged. WORK_PIXEL(texel) names the pixel a per-pixel shader invocation
// works for: when the run counts one pixel only (WorkCounters::countPixel), the others add nothing.
// C++ that includes a shader file (tests) sees only the empty macros.

#include "common/host_device.glsl"
#ifdef COUNT_WORK
layout(std430, binding = kBindingWorkCounters) buffer WorkCounterBlock {
    ivec4 gWorkPixel;  // xy: the only pixel counted, or x < 0: every invocation counts
    uint gWork[kWorkCounterCount];
};
bool gWorkCounted = true;
void workCount(int counter, uint n) {
    if (gWorkCounted && n != 0u) atomicAdd(gWork[counter], n);
}
void workPixel(ivec2 texel) { gWorkCounted = gWorkPixel.x < 0 || texel == gWorkPixel.xy; }
#define WORK_COUNT(counter, n) workCount(counter, uint(n))
#define WORK_PIXEL(texel) workPixel(ivec2(texel))
#else
#define WORK_COUNT(counter, n)
#define WORK_PIXEL(texel)
#endif
