#include "gl/work_counters.h"

#include <epoxy/gl.h>

#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "gl/buffer.h"
#include "gl/handle.h"

namespace viz::gl {

namespace {

using render::hd::kBindingWorkCounters;
using render::hd::kWorkCounterCount;

struct State {
    bool enabled = false;
    glm::ivec4 pixel{-1, -1, 0, 0};
    std::unique_ptr<Buffer> buffer;
    Handle<QueryTraits> primitivesQuery;
    bool primitivesRunning = false;
    std::uint64_t primitives = 0;  // assembled since counting began, up to the last restart
};

// Never destroyed: a buffer still held at exit would be deleted after its context is gone. Contexts call
// release() before they go (platform/context_egl.cpp, window_glfw.cpp).
State& state() {
    static State* s = new State;
    return *s;
}

constexpr std::size_t kHeaderBytes = sizeof(glm::ivec4);
constexpr std::size_t kBufferBytes = kHeaderBytes + sizeof(std::uint32_t) * std::size_t(kWorkCounterCount);

Buffer& buffer() {
    State& s = state();
    if (!s.buffer) {
        s.buffer = std::make_unique<Buffer>(
            Buffer::create({.bytes = kBufferBytes, .flags = GL_DYNAMIC_STORAGE_BIT, .label = "work_counters"}));
        s.buffer->clearZero();
        s.buffer->upload(0, kHeaderBytes, &s.pixel);
    }
    return *s.buffer;
}

// Ends the primitives' query, if it runs, and adds what it counted.
void stopPrimitives() {
    State& s = state();
    if (!s.primitivesRunning) return;
    glEndQuery(GL_PRIMITIVES_GENERATED);
    GLuint64 n = 0;
    glGetQueryObjectui64v(s.primitivesQuery.get(), GL_QUERY_RESULT, &n);  // waits for the result
    s.primitives += n;
    s.primitivesRunning = false;
}

// The primitives assembled so far; the query restarts, so that the next read counts from here. One query
// runs at a time, however the stage clocks nest (ivsv's gather runs vsv's stages inside it).
std::uint64_t primitivesSoFar() {
    State& s = state();
    stopPrimitives();
    if (!s.primitivesQuery) {
        GLuint id = 0;
        glCreateQueries(GL_PRIMITIVES_GENERATED, 1, &id);
        s.primitivesQuery = Handle<QueryTraits>(id);
    }
    glBeginQuery(GL_PRIMITIVES_GENERATED, s.primitivesQuery.get());
    s.primitivesRunning = true;
    return s.primitives;
}

}  // namespace

void WorkCounters::setEnabled(bool enabled) {
    if (!enabled) stopPrimitives();
    state().enabled = enabled;
}

bool WorkCounters::enabled() { return state().enabled; }

void WorkCounters::countPixel(std::optional<glm::ivec2> pixel) {
    State& s = state();
    s.pixel = pixel ? glm::ivec4(*pixel, 0, 0) : glm::ivec4(-1, -1, 0, 0);
    if (s.buffer) s.buffer->upload(0, kHeaderBytes, &s.pixel);
}

void WorkCounters::bind() {
    if (!enabled()) return;
    buffer().bindBase(GL_SHADER_STORAGE_BUFFER, GLuint(kBindingWorkCounters));
}

WorkCounts WorkCounters::read() {
    if (!enabled()) return {};
    // Make the shaders' atomic adds visible to the read.
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    std::vector<std::uint32_t> raw(static_cast<std::size_t>(kWorkCounterCount));
    buffer().download(kHeaderBytes, raw.size() * sizeof(std::uint32_t), raw.data());
    WorkCounts counts(raw.begin(), raw.end());
    counts.push_back(primitivesSoFar());
    return counts;
}

void WorkCounters::release() {
    stopPrimitives();
    state().primitivesQuery = {};
    state().buffer.reset();
}

const char* WorkCounters::name(int counter) {
    static const char* kNames[] = {"shadow_lookups", "shadow_texels",  "ray_samples",    "closed_form_segments",
                                   "tree_nodes",     "fragments",      "voxels_written", "voxels_read",
                                   "quadrature_nodes", "primitives"};
    static_assert(sizeof(kNames) / sizeof(kNames[0]) == std::size_t(kWorkCounts));
    return counter >= 0 && counter < kWorkCounts ? kNames[counter] : "?";
}

WorkCounts workBetween(const WorkCounts& before, const WorkCounts& after) {
    if (before.size() != after.size()) return after;
    WorkCounts d(after.size());
    // The shader counters are 32-bit: the difference modulo 2^32 is right while a stage adds less (the
    // primitives' total is 64-bit, its difference taken the same way).
    for (std::size_t i = 0; i < d.size(); ++i)
        d[i] = std::uint64_t(std::uint32_t(std::uint32_t(after[i]) - std::uint32_t(before[i])));
    return d;
}

}  // namespace viz::gl
