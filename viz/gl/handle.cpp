#include "gl/handle.h"

#include <atomic>

namespace viz::gl {
namespace {
std::atomic<long> gLive{0};
}

long liveHandleCount() { return gLive.load(); }
void countHandle(int delta) { gLive.fetch_add(delta); }

void setLabel(GLenum identifier, GLuint id, const std::string& label) {
    if (label.empty() || id == 0)
        return;
    glObjectLabel(identifier, id, static_cast<GLsizei>(label.size()), label.c_str());
}

}  // namespace viz::gl
