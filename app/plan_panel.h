// The plan section of the parameter panel: what the technique does for this scene and why, as
// `airlight plan` prints it: the stages it skips and every shader feature, on or off, with its reason
// (minmax's integrand=auto says there which integrand it took and the figure it went by).
#pragma once

#include "debug/plan.h"
#include "ui/immediate.h"

namespace airlight {

// A header folded by default, then one row per skipped stage and per feature (the reason's full text in
// the row's tooltip).
void drawPlanSection(viz::ui::Context& ui, const viz::Plan& plan);

}  // namespace airlight
