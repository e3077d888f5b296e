// Checks a JSON text before a recursive consumer (tinygltf, our own readers) walks it: well formed and
// nested at most maxDepth objects/arrays deep. nlohmann's SAX parser is iterative, so this check itself
// cannot overflow the stack, whatever the text.
#pragma once

#include <string>

namespace viz {

// Empty when the text is well formed and shallow enough; otherwise one line: "JSON nested deeper than N"
// or "malformed JSON (parse error at line L, column C: ...)".
std::string jsonProblem(const std::string& text, int maxDepth);

}  // namespace viz
