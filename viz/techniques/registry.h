// The explicit list of techniques, one line each in techniques.def (no self-registering statics: see
// docs/architecture.md#explicit-registry).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "debug/technique.h"

namespace viz {

std::vector<std::string> techniqueIds();
// Throws InputError("unknown technique 'x' (known: reference, raymarch)") for an unknown id.
std::unique_ptr<Technique> makeTechnique(std::string_view id);
// What makes a technique by id where a caller may be handed another (tests pass fakes); null: makeTechnique.
using TechniqueMaker = std::function<std::unique_ptr<Technique>(const std::string&)>;

// Adds a technique after the listed ones (or replaces the factory of a listed id), for this process: the
// tests register the worked example technique (viz/techniques/example/) this way; the product never does.
void registerTechnique(const std::string& id, std::unique_ptr<Technique> (*make)());

}  // namespace viz
