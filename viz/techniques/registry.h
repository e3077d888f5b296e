// The explicit list of techniques, one line each in techniques.def (no self-registering statics: see
// docs/architecture.md#explicit-registry).
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

// Adds a technique after the listed ones (or replaces the factory of a listed id), for this process: the
// tests register the worked example technique (viz/techniques/example/) this way; the product never does.
void registerTechnique(const std::string& id, std::unique_ptr<Technique> (*make)());

}  // namespace viz
