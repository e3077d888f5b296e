// Counts the fragments that reach the framebuffer between begin() and end() (GL_SAMPLES_PASSED: past the
// depth and stencil tests and not discarded by the shader). The query is created on first use and owned
// (Handle), so it is made once per owner, not per run. count() waits for the result: read it after the
// work it measures, not between draws that could overlap it.
#pragma once

#include <epoxy/gl.h>

#include <cstdint>

#include "gl/handle.h"

namespace viz::gl {

class SamplesPassedQuery {
public:
    void begin() {
        if (!mQuery) {
            GLuint id = 0;
            glCreateQueries(GL_SAMPLES_PASSED, 1, &id);
            mQuery = Handle<QueryTraits>(id);
        }
        glBeginQuery(GL_SAMPLES_PASSED, mQuery.get());
    }
    void end() { glEndQuery(GL_SAMPLES_PASSED); }
    // The fragments counted between the last begin() and end(); waits for the GPU.
    std::uint64_t count() const {
        GLuint64 n = 0;
        glGetQueryObjectui64v(mQuery.get(), GL_QUERY_RESULT, &n);
        return std::uint64_t(n);
    }

private:
    Handle<QueryTraits> mQuery;
};

}  // namespace viz::gl
