#include "debug/technique.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.h"

namespace viz {

const char* viewKindName(ViewKind kind) {
    switch (kind) {
        case ViewKind::Color: return "colour";
        case ViewKind::Scalar: return "scalar";
        case ViewKind::Signed: return "signed";
        case ViewKind::BitField: return "bit field";
        case ViewKind::Mask: return "mask";
        case ViewKind::Depth: return "depth";
        case ViewKind::Mesh: return "mesh";
        case ViewKind::Buffer: return "buffer";
    }
    return "unknown";
}

static std::string knownParams(const Technique& technique) {
    std::ostringstream out;
    const auto& params = technique.params();
    for (std::size_t i = 0; i < params.size(); ++i) out << (i ? ", " : "") << params[i].name;
    return params.empty() ? std::string("none") : out.str();
}

Settings completeSettings(const Technique& technique, const Settings& given) {
    Settings result;
    for (const ParamInfo& p : technique.params()) result[p.name] = p.defaultValue;
    for (const auto& [name, value] : given) {
        const ParamInfo* info = nullptr;
        for (const ParamInfo& p : technique.params())
            if (p.name == name) info = &p;
        if (!info)
            throw InputError("unknown parameter '" + name + "' for technique '" + technique.id() +
                             "' (known: " + knownParams(technique) + ")");
        if (!std::isfinite(value))
            throw InputError("parameter '" + name + "' must be a finite number");
        if (info->integer && value != std::floor(value))
            throw InputError("parameter '" + name + "' must be a whole number, got " + std::to_string(value));
        if (value < info->minValue || value > info->maxValue) {
            std::ostringstream msg;
            msg << "parameter '" << name << "' = " << value << " is out of range [" << info->minValue << ", "
                << info->maxValue << "]";
            throw InputError(msg.str());
        }
        result[name] = value;
    }
    return result;
}

ParamInfo forceFeaturesParam() {
    return {"force_features",
            "1: run every stage and compile every feature the plan would leave out for this scene (to measure "
            "what the plan saves; the image is the same)",
            0, 0, 1, true};
}

void forcePlan(Plan& plan, bool force, const std::vector<std::string>& scenePrunedFeatures) {
    if (!force) return;
    for (StagePlan& s : plan.stages)
        if (!s.runs) {
            s.runs = true;
            s.why = "forced on (force_features=1); the plan would skip it: " + s.why;
        }
    for (FeaturePlan& f : plan.features)
        if (!f.enabled && std::find(scenePrunedFeatures.begin(), scenePrunedFeatures.end(), f.feature) !=
                              scenePrunedFeatures.end()) {
            f.enabled = true;
            f.why = "forced on (force_features=1); the plan would leave it out: " + f.why;
        }
}

}  // namespace viz
