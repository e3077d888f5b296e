#include "gl/handle.h"

namespace viz::gl {

void setLabel(GLenum identifier, GLuint id, const std::string& label) {
    if (label.empty() || id == 0)
        return;
    glObjectLabel(identifier, id, static_cast<GLsizei>(label.size()), label.c_str());
}

}  // namespace viz::gl
