#include "techniques/registry.h"

#include <utility>

#include "core/error.h"

namespace viz {

// Each factory of techniques.def, declared here so the list is the one place a technique is named.
#define VIZ_TECHNIQUE(id, factory) std::unique_ptr<Technique> factory();
#include "techniques/techniques.def"
#undef VIZ_TECHNIQUE

namespace {

using Factory = std::unique_ptr<Technique> (*)();

std::vector<std::pair<std::string, Factory>>& entries() {
    static std::vector<std::pair<std::string, Factory>> list = {
#define VIZ_TECHNIQUE(id, factory) {#id, &factory},
#include "techniques/techniques.def"
#undef VIZ_TECHNIQUE
    };
    return list;
}

}  // namespace

std::vector<std::string> techniqueIds() {
    std::vector<std::string> ids;
    for (const auto& [id, make] : entries()) ids.push_back(id);
    return ids;
}

std::unique_ptr<Technique> makeTechnique(std::string_view id) {
    for (const auto& [known, make] : entries())
        if (known == id) return make();
    std::string known;
    for (const std::string& t : techniqueIds()) known += (known.empty() ? "" : ", ") + t;
    throw InputError("unknown technique '" + std::string(id) + "' (known: " + known + ")");
}

void registerTechnique(const std::string& id, std::unique_ptr<Technique> (*make)()) {
    for (auto& [known, factory] : entries())
        if (known == id) {
            factory = make;
            return;
        }
    entries().emplace_back(id, make);
}

}  // namespace viz
