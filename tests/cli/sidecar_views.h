// The screenshot sidecar's views (the window's named images: grid views, comparison tiles, the plot), by
// name, for the window tests.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace viz::testing {

// The first view of that name in the sidecar, or null.
inline const nlohmann::json* sidecarView(const nlohmann::json& sidecar, const std::string& name) {
    for (const auto& v : sidecar.at("views"))
        if (v.value("name", std::string()) == name) return &v;
    return nullptr;
}

// Its title, or "(no view NAME)" so that an expectation on the text names what is missing.
inline std::string sidecarViewTitle(const nlohmann::json& sidecar, const std::string& name) {
    const nlohmann::json* v = sidecarView(sidecar, name);
    return v ? v->value("title", std::string()) : "(no view " + name + ")";
}

}  // namespace viz::testing
