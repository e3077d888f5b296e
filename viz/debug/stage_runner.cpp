#include "debug/stage_runner.h"

#include <string>

#include "core/error.h"

namespace viz {

void checkStageOrder(const std::vector<StageInfo>& stages, const std::string_view* order, std::size_t count) {
    VIZ_CHECK(stages.size() == count, "a technique declares " + std::to_string(stages.size()) +
                                          " stages but its stage order lists " + std::to_string(count));
    for (std::size_t i = 0; i < count; ++i)
        VIZ_CHECK(stages[i].id == order[i], "stage " + std::to_string(i) + " is declared as " + stages[i].id +
                                                " but the stage order says " + std::string(order[i]));
}

StageRunner::StageRunner(const std::vector<StageInfo>& stages, const FrameInput& input, FrameOutput& out,
                         StageReuse& reuse, StageTimer& timer)
    : mStages(stages), mOut(out), mReuse(reuse), mTimer(input.timer ? *input.timer : timer) {
    // The controls reach a run as FrameInput::controls only; a request built without setRunSettings or
    // frameInput would leave them in the settings, where no technique reads them.
    static const Settings kControlNames = controlSettings({});  // built once, not per run
    for (const auto& [name, value] : kControlNames)
        VIZ_CHECK(!input.settings.contains(name), "FrameInput::settings holds the control '" + name +
                                                      "': build the run request with setRunSettings or frameInput");
    const int last = int(stages.size()) - 1;
    mStop = input.stopAfterStage < 0 || input.stopAfterStage > last ? last : input.stopAfterStage;
    out.timing.clock = mTimer.name();
    reuse.begin(input, out);
}

}  // namespace viz
