#include "view_contents.h"

namespace airlight {

int contentCount(const viz::FrameOutput& out) { return 2 + int(out.intermediates.size()); }

std::string contentId(const viz::FrameOutput& out, int index) {
    return index == 0 ? "final" : index == 1 ? "airlight" : out.intermediates[std::size_t(index - 2)].id;
}

std::string contentLabel(const viz::FrameOutput& out, int index) {
    return index == 0 ? "Final image" : index == 1 ? "Airlight L_air" : out.intermediates[std::size_t(index - 2)].label;
}

int contentIndexOf(const viz::FrameOutput& out, const std::string& id) {
    if (id == "final") return 0;
    if (id == "airlight") return 1;
    for (std::size_t i = 0; i < out.intermediates.size(); ++i)
        if (out.intermediates[i].id == id) return 2 + int(i);
    return -1;
}

std::string notMadeBecause(const viz::Technique& technique, const viz::FrameOutput& out, const std::string& id) {
    const int k = viz::stageOfIntermediate(technique.stages(), id);
    if (k < 0) return "chosen: " + id + ", not a view of " + technique.id();
    const viz::StageInfo& stage = technique.stages()[std::size_t(k)];
    if (k > out.lastStageRun) return "chosen: " + id + ", made by " + stage.label + ", after where the run stops";
    if (k < int(out.plan.stages.size()) && !out.plan.stages[std::size_t(k)].runs)
        return "chosen: " + id + ", not made: " + stage.label + " skipped (" + out.plan.stages[std::size_t(k)].why + ")";
    return "chosen: " + id + ", not made with these settings";
}

}  // namespace airlight
