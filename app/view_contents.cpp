#include "view_contents.h"

#include <algorithm>

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

ShownContent shownContent(const viz::Technique& technique, const viz::FrameOutput& out, const std::string& chosen,
                          int index, const std::vector<std::string>& elsewhere) {
    const auto& all = out.intermediates;
    ShownContent shown{chosen, -1, ""};
    if (chosen != "final" && chosen != "airlight") {
        if (index >= 0 && index < int(all.size()) && all[std::size_t(index)].id == chosen) {
            shown.index = index;
        } else if (const int first = contentIndexOf(out, chosen); first >= 2) {
            shown.index = first - 2;
        }
        if (shown.index < 0) {  // not in this run: L_air, saying so (the choice is kept for later runs)
            shown.standIn = notMadeBecause(technique, out, chosen);
            shown.content = "airlight";
        }
    }
    const auto shownElsewhere = [&](const std::string& id) {
        return std::find(elsewhere.begin(), elsewhere.end(), id) != elsewhere.end();
    };
    // A final-frame view before the final frame exists shows L_air, unless another view shows L_air
    // already: then the stage's own views, as when L_air does not exist yet (not the same image twice).
    const bool finalAbsent = shown.content == "final" && out.final.empty() && out.lastStageRun >= 0;
    const bool airlightTwice = finalAbsent && !out.airlight.empty() && shownElsewhere("airlight");
    if (finalAbsent) shown.content = "airlight";
    if (shown.content == "airlight" && (out.airlight.empty() || airlightTwice) && out.lastStageRun >= 0 &&
        out.lastStageRun < int(technique.stages().size())) {
        const auto& declared = technique.stages()[std::size_t(out.lastStageRun)].intermediates;
        // Both views standing in: the L_air view takes the stage's first view, this one the next.
        const bool leaveFirst = chosen == "final" && shownElsewhere("airlight") && out.airlight.empty();
        int first = -1, unshown = -1;
        for (int i = 0; i < int(all.size()); ++i) {
            const std::string& id = all[std::size_t(i)].id;
            if (std::find(declared.begin(), declared.end(), id) == declared.end()) continue;
            const bool isFirst = first < 0;
            if (isFirst) first = i;
            if (isFirst && leaveFirst) continue;
            if (unshown < 0 && !shownElsewhere(id)) unshown = i;
        }
        const int pick = unshown >= 0 ? unshown : first;
        if (pick >= 0) {
            shown.index = pick;
            shown.content = all[std::size_t(pick)].id;
        }
    }
    return shown;
}

}  // namespace airlight
