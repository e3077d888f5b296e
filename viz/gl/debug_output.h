// GL debug output (KHR_debug): a callback that logs driver messages to stderr and counts
// GL_DEBUG_TYPE_ERROR messages, so tests can assert that a run produced none.
#pragma once

namespace viz::gl {

// Installs the callback on the current context (synchronous output, so a message is reported inside
// the GL call that caused it). Harmless on a non-debug context (the driver then may send nothing).
void installDebugOutput();

// GL_DEBUG_TYPE_ERROR messages since start (or since resetDebugErrorCount), over all contexts.
int debugErrorCount();
void resetDebugErrorCount();

}  // namespace viz::gl
