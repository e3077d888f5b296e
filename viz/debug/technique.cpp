#include "debug/technique.h"

#include <cstdio>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "core/error.h"
#include "core/text.h"

namespace viz {

const char* viewKindName(ViewKind kind) {
    switch (kind) {
        case ViewKind::Colour: return "colour";
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

std::string settingText(const std::vector<ParamInfo>& params, const std::string& name, double value) {
    for (const ParamInfo& p : params) {
        if (p.name != name || p.choices.empty()) continue;
        if (value >= 0.0 && value == std::floor(value) && value < double(p.choices.size())) {
            return name + "=" + p.choices[std::size_t(value)];
        }
    }
    return name + "=" + exactNumber(value);
}

std::vector<std::string> onDemandAmong(const Technique& technique, const std::vector<std::string>& shown,
                                       bool everything) {
    std::set<std::string> wanted;
    for (const StageInfo& st : technique.stages())
        for (const std::string& id : st.onDemand)
            if (everything || std::find(shown.begin(), shown.end(), id) != shown.end()) wanted.insert(id);
    return {wanted.begin(), wanted.end()};
}

int stageOfIntermediate(const std::vector<StageInfo>& stages, const std::string& id) {
    const auto declares = [&](const StageInfo& st, const std::string& name) {
        return std::find(st.intermediates.begin(), st.intermediates.end(), name) != st.intermediates.end();
    };
    for (int k = 0; k < int(stages.size()); ++k)
        if (declares(stages[std::size_t(k)], id)) return k;
    const std::size_t dot = id.find_last_of('.');
    if (dot == std::string::npos || dot + 1 == id.size()) return -1;
    for (std::size_t i = dot + 1; i < id.size(); ++i)
        if (id[i] < '0' || id[i] > '9') return -1;
    const std::string first = id.substr(0, dot);
    for (int k = 0; k < int(stages.size()); ++k)
        if (declares(stages[std::size_t(k)], first)) return k;
    return -1;
}

const ParamInfo* findParam(const Technique& technique, const std::string& name) {
    for (const ParamInfo& p : technique.params())
        if (p.name == name) return &p;
    return nullptr;
}

Settings measuredSettings(const Technique& technique, Settings given) {
    for (const auto& [name, value] : technique.measurementSettings()) given.try_emplace(name, value);
    return given;
}

Settings completeSettings(const Technique& technique, const Settings& given) {
    Settings result;
    for (const ParamInfo& p : technique.params()) result[p.name] = p.defaultValue;
    for (const auto& [name, value] : given) {
        const ParamInfo* info = findParam(technique, name);
        if (!info)
            throw InputError("unknown parameter '" + name + "' for technique '" + technique.id() +
                             "' (known: " + knownParams(technique) + ")");
        if (!std::isfinite(value))
            throw InputError("parameter '" + name + "' must be a finite number");
        if (info->integer && value != std::floor(value))
            throw InputError("parameter '" + name + "' must be a whole number, got " + exactNumber(value));
        if (value < info->minValue || value > info->maxValue) {
            throw InputError("parameter '" + name + "' = " + exactNumber(value) + " is out of range [" +
                             exactNumber(info->minValue) + ", " + exactNumber(info->maxValue) + "]");
        }
        result[name] = value;
    }
    return result;
}

ParamInfo pickParam(char axis, const std::string& what) {
    // 16384: twice the largest image `--size` accepts, as both techniques with a 16384 maximum had.
    const bool x = axis == 'x';
    constexpr FrameControls kDefault{};
    return {x ? kPickX : kPickY,
            std::string(x ? "picked pixel's column (0 = left)" : "picked pixel's row (0 = top)") + ", whose " + what +
                " the views show; -1: image centre",
            double(x ? kDefault.pickX : kDefault.pickY), -1, 16384, true};
}

std::vector<ParamInfo> orbitParams(const std::string& when) {
    constexpr FrameControls kDefault{};
    return {{kOrbitYaw, when + ": orbit camera's angle about the vertical (degrees)", kDefault.orbitYaw, -360, 360,
             false},
            {kOrbitPitch, when + ": orbit camera's angle above the horizon (degrees)", kDefault.orbitPitch, -89, 89,
             false},
            {kOrbitZoom, when + ": orbit camera's zoom (1 fits the scene and the camera)", kDefault.orbitZoom, 0.05, 50,
             false}};
}

ParamInfo animationTimeParam(const std::string& what) {
    return {kAnimationTime, "seconds: " + what, FrameControls{}.time, 0, 1e6, false};
}

namespace {
// Each control's name and field, in one list for both directions.
template <class F>
void forEachControl(FrameControls& c, F&& f) {
    f(kPickX, [&](double v) { c.pickX = int(v); }, double(c.pickX));
    f(kPickY, [&](double v) { c.pickY = int(v); }, double(c.pickY));
    f(kOrbitYaw, [&](double v) { c.orbitYaw = v; }, c.orbitYaw);
    f(kOrbitPitch, [&](double v) { c.orbitPitch = v; }, c.orbitPitch);
    f(kOrbitZoom, [&](double v) { c.orbitZoom = v; }, c.orbitZoom);
    f(kAnimationTime, [&](double v) { c.time = v; }, c.time);
}
}  // namespace

FrameControls takeControls(Settings& settings) {
    FrameControls c;
    forEachControl(c, [&](const char* name, auto set, double) {
        const auto it = settings.find(name);
        if (it == settings.end()) return;
        set(it->second);
        settings.erase(it);
    });
    return c;
}

Settings controlSettings(const FrameControls& controls) {
    FrameControls c = controls;
    Settings s;
    forEachControl(c, [&](const char* name, auto, double value) { s[name] = value; });
    return s;
}

std::optional<StiffBound> boundOf(const std::map<std::string, StiffBound>& bounds, const std::string& caseClass) {
    const auto it = bounds.find(caseClass);
    return it == bounds.end() ? std::nullopt : std::optional<StiffBound>(it->second);
}

Plan planEveryStage(const std::vector<StageInfo>& stages) {
    Plan p;
    for (const StageInfo& s : stages) p.stages.push_back({s.id, true, ""});
    return p;
}

void setRunSettings(FrameInput& input, Settings complete) {
    input.controls = takeControls(complete);
    input.settings = std::move(complete);
}

FrameInput frameInput(const scene::Scene* scene, int width, int height, Settings complete, int stopAfterStage) {
    FrameInput input;
    input.scene = scene;
    input.width = width;
    input.height = height;
    setRunSettings(input, std::move(complete));
    input.stopAfterStage = stopAfterStage;
    return input;
}

glm::ivec2 pickedPixel(const FrameInput& input) {
    int x = input.controls.pickX, y = input.controls.pickY;
    if (x < 0) x = input.width / 2;
    if (y < 0) y = input.height / 2;
    return {std::min(x, input.width - 1), std::min(y, input.height - 1)};
}

ParamInfo forceFeaturesParam() {
    return {"force_features",
            "1: run every stage and compile every feature the plan would leave out for this scene (to measure "
            "what the plan saves; the image is the same)",
            0, 0, 1, true};
}

const FeaturePlan* findFeature(const Plan& plan, const std::string& name) {
    for (const FeaturePlan& f : plan.features)
        if (f.feature == name) return &f;
    return nullptr;
}

const StagePlan* findStage(const Plan& plan, const std::string& id) {
    for (const StagePlan& s : plan.stages)
        if (s.stage == id) return &s;
    return nullptr;
}

bool featureEnabled(const Plan& plan, const std::string& name) {
    const FeaturePlan* f = findFeature(plan, name);
    return f && f->enabled;
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

std::vector<double> Technique::substepValues(int stage, const Settings& settings) const {
    const StageInfo& st = stages().at(std::size_t(stage));
    if (st.substepParam.empty()) return {};
    int count = st.substeps;
    if (!st.substepCountParam.empty()) {
        const auto it = settings.find(st.substepCountParam);
        if (it != settings.end()) count = int(it->second);
    }
    if (count < 1) return {};
    double all = 0.0;
    for (const ParamInfo& p : params())
        if (p.name == st.substepParam) all = p.defaultValue;
    std::vector<double> values;
    for (int k = 1; k < count; ++k) values.push_back(double(k));
    values.push_back(all);
    return values;
}

double Technique::substepLimit(const FrameInput& input, int stage) const {
    const StageInfo& st = stages().at(std::size_t(stage));
    const double set = input.settings.at(st.substepParam);
    if (input.substep <= 0 || input.stopAfterStage != stage) return set;
    const std::vector<double> values = substepValues(stage, input.settings);
    if (values.empty()) return set;
    return values[std::size_t(std::clamp(input.substep, 1, int(values.size())) - 1)];
}

SubstepPosition substepPosition(const Technique& technique, int stage, const Settings& settings) {
    if (stage < 0 || stage >= int(technique.stages().size())) return {};
    const Settings complete = completeSettings(technique, settings);
    const std::vector<double> values = technique.substepValues(stage, complete);
    if (values.empty()) return {};
    const double current = complete.at(technique.stages()[std::size_t(stage)].substepParam);
    const int count = int(values.size());
    for (int k = 0; k < count; ++k)
        if (values[std::size_t(k)] == current) return {k + 1, count};
    return {count, count};  // a value outside the steps (e.g. set by hand): treat as the whole stage
}

bool setSubstep(const Technique& technique, int stage, Settings& settings, int k) {
    if (stage < 0 || stage >= int(technique.stages().size())) return false;
    const std::vector<double> values = technique.substepValues(stage, completeSettings(technique, settings));
    if (values.empty()) return false;
    k = std::clamp(k, 1, int(values.size()));
    settings[technique.stages()[std::size_t(stage)].substepParam] = values[std::size_t(k - 1)];
    return true;
}

}  // namespace viz
