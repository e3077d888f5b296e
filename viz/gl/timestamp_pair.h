// gl::TimestampPair: two GL_TIMESTAMP queries around GPU work, the time between them read back. Unlike a
// GL_TIME_ELAPSED query, pairs nest (a stage that runs another technique inside it times both). Used by
// gl::StageClock, which waits for the result, and gl::GpuTimer, which reads it once it is there.
#pragma once

#include <epoxy/gl.h>

#include "gl/handle.h"

namespace viz::gl {

struct TimestampPair {
    Handle<QueryTraits> start, end;

    static TimestampPair create() {
        GLuint ids[2] = {0, 0};
        glCreateQueries(GL_TIMESTAMP, 2, ids);
        return {Handle<QueryTraits>(ids[0]), Handle<QueryTraits>(ids[1])};
    }
    void markStart() const { glQueryCounter(start.get(), GL_TIMESTAMP); }
    void markEnd() const { glQueryCounter(end.get(), GL_TIMESTAMP); }
    // Whether the GPU has answered both (the end is answered last).
    bool ready() const {
        GLint available = 0;
        glGetQueryObjectiv(end.get(), GL_QUERY_RESULT_AVAILABLE, &available);
        return available != 0;
    }
    // Milliseconds between the two marks; waits for the results when they are not there yet.
    double milliseconds() const {
        GLuint64 t0 = 0, t1 = 0;
        glGetQueryObjectui64v(start.get(), GL_QUERY_RESULT, &t0);
        glGetQueryObjectui64v(end.get(), GL_QUERY_RESULT, &t1);
        return t1 > t0 ? double(t1 - t0) * 1e-6 : 0.0;
    }
};

}  // namespace viz::gl
