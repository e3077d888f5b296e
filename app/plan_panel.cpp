#include "plan_panel.h"

#include <string>

namespace airlight {

void drawPlanSection(viz::ui::Context& ui, const viz::Plan& plan) {
    if (!ui.collapsingHeader("plan: what runs and why", false)) return;
    int skipped = 0, on = 0;
    for (const viz::StagePlan& s : plan.stages) skipped += s.runs ? 0 : 1;
    for (const viz::FeaturePlan& f : plan.features) on += f.enabled ? 1 : 0;
    ui.label(std::to_string(plan.stages.size() - std::size_t(skipped)) + " of " + std::to_string(plan.stages.size()) +
                 " stages run, " + std::to_string(on) + " of " + std::to_string(plan.features.size()) +
                 " features on (hover a row for its reason)",
             true);
    for (const viz::StagePlan& s : plan.stages) {
        if (s.runs) continue;
        ui.label("skip " + s.stage + ": " + s.why, true);
        ui.tooltip(s.why);
    }
    for (const viz::FeaturePlan& f : plan.features) {
        ui.label(std::string(f.enabled ? "on   " : "off  ") + f.feature + ": " + f.why, !f.enabled);
        ui.tooltip(f.why);
    }
}

}  // namespace airlight
