#include "debug/permutations.h"

namespace viz {

namespace {

const char* defineFor(const FeaturePlan& f, const PermutationTable& table) {
    const auto it = table.find(f.feature);
    if (it == table.end()) return nullptr;  // a run-time branch, not a permutation
    return f.enabled ? it->second.first : it->second.second;
}

}  // namespace

void annotatePermutations(Plan& plan, const PermutationTable& table) {
    for (FeaturePlan& f : plan.features)
        if (const char* define = defineFor(f, table))
            f.why += std::string(f.enabled ? " (compiled in: " : " (compiled out: ") + define + ")";
}

std::vector<std::pair<std::string, std::string>> permutationDefines(const Plan& plan, const PermutationTable& table,
                                                                    std::string* key) {
    std::vector<std::pair<std::string, std::string>> defines;
    if (key) key->clear();
    for (const FeaturePlan& f : plan.features)
        if (const char* define = defineFor(f, table)) {
            defines.push_back({define, "1"});
            if (key) *key += std::string(define) + ";";
        }
    return defines;
}

}  // namespace viz
