#include "process_stats.h"

#include <malloc.h>
#include <cstddef>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "gl/handle.h"

// Under AddressSanitizer malloc is the sanitizer's own allocator, which glibc's mallinfo2 does not see
// (it reports 0): ask the sanitizer for the bytes it has handed out instead.
#if defined(__SANITIZE_ADDRESS__)
#define AIRLIGHT_ASAN_HEAP 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define AIRLIGHT_ASAN_HEAP 1
#endif
#endif
#ifdef AIRLIGHT_ASAN_HEAP
// The sanitizer runtime's public allocator API (sanitizer/allocator_interface.h, which GCC does not
// install).
extern "C" std::size_t __sanitizer_get_current_allocated_bytes();
#endif

namespace airlight {

ProcessStats currentProcessStats() {
    ProcessStats s;
    std::ifstream statm("/proc/self/statm");
    long pages = 0, resident = 0;
    if (statm >> pages >> resident) s.residentKb = resident * (::sysconf(_SC_PAGESIZE) / 1024);
    std::error_code ec;
    long files = 0;
    for (std::filesystem::directory_iterator it("/proc/self/fd", ec), end; !ec && it != end; it.increment(ec)) ++files;
    if (!ec) s.openFiles = files - 1;  // less the descriptor the listing itself holds
    s.glObjects = viz::gl::liveHandleCount();
#ifdef AIRLIGHT_ASAN_HEAP
    s.heapKb = long(__sanitizer_get_current_allocated_bytes() / 1024);
#else
    const struct mallinfo2 m = ::mallinfo2();
    s.heapKb = long((m.uordblks + m.hblkhd) / 1024);
#endif
    return s;
}

std::string statsJsonLine(const ProcessStats& s, long frame, long glErrors) {
    return "{\"frame\": " + std::to_string(frame) + ", \"rss_kb\": " + std::to_string(s.residentKb) +
           ", \"heap_kb\": " + std::to_string(s.heapKb) + ", \"fds\": " + std::to_string(s.openFiles) + ", \"gl_objects\": " + std::to_string(s.glObjects) +
           ", \"gl_errors\": " + std::to_string(glErrors) + "}";
}

}  // namespace airlight
