#include "step_cursor.h"

#include <algorithm>
#include <string>

#include "core/text.h"
#include "step_timeline.h"

namespace airlight {

int stageShownBy(const viz::Technique& technique, StepCursor cursor) {
    const int n = int(technique.stages().size());
    return cursor.stage < 0 || cursor.stage >= n ? n - 1 : cursor.stage;
}

SubstepAt substepAt(const viz::Technique& technique, const viz::Settings& settings, StepCursor cursor,
                    const std::map<int, int>& runCounts) {
    const int count = substepCountOf(technique, stageShownBy(technique, cursor), settings, runCounts);
    if (count == 0) return {};
    return {cursor.substep <= 0 ? count : std::min(cursor.substep, count), count};
}

StepCursor normalisedCursor(const viz::Technique& technique, StepCursor c) {
    const int n = int(technique.stages().size());
    if ((c.stage < 0 || c.stage >= n - 1) && c.substep <= 0) return {};
    if (c.stage < 0 || c.stage >= n) c.stage = n - 1;
    return c;
}

StepCursor stageStepped(const viz::Technique& technique, const viz::Settings& settings, StepCursor cursor,
                        int delta) {
    const int n = int(technique.stages().size());
    const int stage = ((stageShownBy(technique, cursor) + delta) % n + n) % n;
    if (stage == n - 1) return {};
    const bool substeps = !technique.substepValues(stage, settings).empty();
    return {stage, substeps ? 1 : 0};
}

SubstepMove substepMovedTo(const viz::Technique& technique, const viz::Settings& settings, StepCursor cursor,
                           const std::map<int, int>& runCounts, int k) {
    const SubstepAt pos = substepAt(technique, settings, cursor, runCounts);
    const int shown = stageShownBy(technique, cursor);
    const std::string& id = technique.stages()[std::size_t(shown)].id;
    if (pos.count <= 0) return {cursor, id + " has no sub-steps (S steps the stages)"};
    if (k < 1 || k > pos.count)
        return {cursor, (k < 1 ? "already at the first sub-step of " : "already at the last sub-step of ") + id +
                            " (" + std::to_string(pos.at) + "/" + std::to_string(pos.count) + ")"};
    return {normalisedCursor(technique, {shown, k == pos.count ? 0 : k}), ""};
}

std::string stoppedEarly(const viz::Technique& technique, const viz::Settings& settings, StepCursor cursor,
                         const std::map<int, int>& runCounts) {
    const auto& stages = technique.stages();
    const int shown = stageShownBy(technique, cursor);
    const SubstepAt pos = substepAt(technique, settings, cursor, runCounts);
    std::string why;
    if (shown < int(stages.size()) - 1)
        why = "stopped after stage " + std::to_string(shown + 1) + "/" + std::to_string(stages.size()) + " " +
              stages[std::size_t(shown)].id;
    if (pos.count > 0 && pos.at < pos.count)
        why += (why.empty() ? "stopped in " + stages[std::size_t(shown)].id : std::string()) + " at sub-step " +
               std::to_string(pos.at) + "/" + std::to_string(pos.count);
    const viz::Settings defaults = viz::completeSettings(technique, {});
    for (const viz::StageInfo& st : stages)
        if (!st.substepParam.empty() && settings.count(st.substepParam) &&
            settings.at(st.substepParam) != defaults.at(st.substepParam))
            why += (why.empty() ? "" : "; ") + st.substepParam + "=" + viz::format("%g", settings.at(st.substepParam)) +
                   " cuts " + st.id + " short";
    return why;
}

}  // namespace airlight
