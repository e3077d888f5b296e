#include "core/error.h"

#include <cstdio>
#include <cstdlib>

namespace viz {

void checkFailed(const char* expr, const char* file, int line, const std::string& msg) {
    std::fprintf(stderr, "%s:%d: check failed: %s: %s\n", file, line, expr, msg.c_str());
    std::abort();
}

}  // namespace viz
