// One insertion sort for the shaders' short break-point lists (common/airlight.glsl's 12 panel breaks,
// polyvol/segment.glsl's at most 8 cone crossings). GLSL has no generic array parameter, so it is a macro
// over the caller's array: SORT_ASCENDING(values, count) sorts values[0 .. count - 1] in place. Compares
// and copies only, so the result does not depend on how the compiler schedules it.
#ifndef COMMON_SORT_GLSL
#define COMMON_SORT_GLSL

#define SORT_ASCENDING(values, count)                   \
    for (int sortI_ = 1; sortI_ < (count); ++sortI_) {  \
        float sortV_ = values[sortI_];                  \
        int sortJ_ = sortI_ - 1;                        \
        while (sortJ_ >= 0 && values[sortJ_] > sortV_) { \
            values[sortJ_ + 1] = values[sortJ_];        \
            --sortJ_;                                   \
        }                                               \
        values[sortJ_ + 1] = sortV_;                    \
    }

#endif
