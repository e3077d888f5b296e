// The explicit list of techniques (no self-registering statics: see docs/architecture.md#explicit-registry).
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "debug/technique.h"

namespace viz {

std::vector<std::string> techniqueIds();
// Throws InputError("unknown technique 'x' (known: reference, raymarch)") for an unknown id.
std::unique_ptr<Technique> makeTechnique(std::string_view id);

}  // namespace viz
