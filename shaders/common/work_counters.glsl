// Work counters (gl/work_counters.h): with COUNT_WORK defined (every program of a counting run) each
// WORK_COUNT(counter, n) adds n to one of kWorkCounterCount unsigned totals; without it the macro is
// empty and the shader is unchanged. WORK_PIXEL(texel) names the pixel a per-pixel shader invocation
// works for: when the run counts one pixel only (WorkCounters::countPixel), the others add nothing.
// C++ that includes a shader file (tests) sees only the empty macros.
//
// An invocation adds to its own private totals and flushes them to the buffer once, when its main()
// returns: an atomic add per WORK_COUNT (several per ray sample) made a counting run of raymarch 2.4
// times as long as a timed one on llvmpipe, whose atomics serialise the lanes. To flush at the end
// however main() returns, the shader's main() is renamed (the #define below) and called from the main()
// defined here. A fragment shader discards with WORK_DISCARD, which flushes first (a discarded fragment
// has still done its work).

#include "common/host_device.glsl"
#ifdef COUNT_WORK
layout(std430, binding = kBindingWorkCounters) buffer WorkCounterBlock {
    ivec4 gWorkPixel;  // xy: the only pixel counted, or x < 0: every invocation counts
    uint gWork[kWorkCounterCount];
};
bool gWorkCounted = true;
uint gWorkOwn[kWorkCounterCount];  // this invocation's totals, zeroed by main() below
void workCount(int counter, uint n) {
    if (gWorkCounted) gWorkOwn[counter] += n;
}
void workPixel(ivec2 texel) { gWorkCounted = gWorkPixel.x < 0 || texel == gWorkPixel.xy; }
// Called once per invocation: at the end of main() or just before a discard, after which nothing runs.
void workFlush() {
    for (int i = 0; i < kWorkCounterCount; ++i)
        if (gWorkOwn[i] != 0u) atomicAdd(gWork[i], gWorkOwn[i]);
}
void workCountedMain();
void main() {
    for (int i = 0; i < kWorkCounterCount; ++i) gWorkOwn[i] = 0u;
    workCountedMain();
    workFlush();
}
#define main workCountedMain
#define WORK_COUNT(counter, n) workCount(counter, uint(n))
#define WORK_PIXEL(texel) workPixel(ivec2(texel))
#define WORK_DISCARD \
    {                \
        workFlush(); \
        discard;     \
    }
#else
#define WORK_COUNT(counter, n)
#define WORK_PIXEL(texel)
#define WORK_DISCARD discard
#endif
