// What a long-running window holds, for the soak test: resident memory, open file descriptors and GL
// objects owned by our RAII wrappers (gl/handle.h). Linux: read from /proc/self.
#pragma once

#include <string>

namespace airlight {

struct ProcessStats {
    long residentKb = -1;       // -1: unknown
    long heapKb = -1;           // bytes malloc has handed out and not had back (mallinfo2), in KiB
    long openFiles = -1;
    long glObjects = 0;
};

ProcessStats currentProcessStats();

// One JSON object on one line: {"frame": F, "rss_kb": ..., "heap_kb": ..., "fds": ..., "gl_objects": ...,
// "gl_errors": E}.
std::string statsJsonLine(const ProcessStats& s, long frame, long glErrors);

}  // namespace airlight
