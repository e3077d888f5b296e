// A technique's plan for a scene and settings: which stages run and which shader features are compiled
// in, each with its reason.
#pragma once

#include <string>
#include <vector>

namespace viz {

// Which stages run for a scene and settings, and for each one left out, why.
struct StagePlan {
    std::string stage;
    bool runs = true;
    std::string why;  // for a skipped stage: the reason; for a running one: optional detail
};
struct FeaturePlan {
    std::string feature;  // shader feature / code path, e.g. "SPOT_FALLOFF"
    bool enabled = true;
    std::string why;
};
struct Plan {
    std::vector<StagePlan> stages;
    std::vector<FeaturePlan> features;
};

// With force = true, turns every skipped stage on and every listed scene-pruned feature on, keeping
// the reason it would have been skipped in `why`. Features chosen by settings are not touched.
void forcePlan(Plan& plan, bool force, const std::vector<std::string>& scenePrunedFeatures);

// The plan's entry for feature `name` / stage `id`; null when the plan does not list it.
const FeaturePlan* findFeature(const Plan& plan, const std::string& name);
const StagePlan* findStage(const Plan& plan, const std::string& id);

// Whether the plan lists feature `name` as enabled (false when it does not list it).
bool featureEnabled(const Plan& plan, const std::string& name);

}  // namespace viz
