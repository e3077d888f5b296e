// Plan features that are shader permutations: a feature maps to the #define that compiles its code in
// when the plan enables it, or to the one that compiles it out when the plan leaves it out (either may be
// null). One table per technique drives both what plan() says and what the shaders are compiled with.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "debug/technique.h"

namespace viz {

// feature -> {define when enabled, define when disabled}
using PermutationTable = std::map<std::string, std::pair<const char*, const char*>>;

// Appends " (compiled in: NAME)" or " (compiled out: NAME)" to the reason of every feature in the table.
void annotatePermutations(Plan& plan, const PermutationTable& table);

// The {NAME, "1"} defines the plan asks for, in the order of its features; `key` (if given) receives
// them joined, for caching compiled programs per permutation.
std::vector<std::pair<std::string, std::string>> permutationDefines(const Plan& plan, const PermutationTable& table,
                                                                    std::string* key = nullptr);

}  // namespace viz
