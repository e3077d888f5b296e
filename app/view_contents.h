// What a run offers the view grid, as plain functions of its output: the views list (the final frame,
// L_air, then every intermediate the run published, in order), each entry's id and label, and why a view
// chosen earlier is not in this run. The window's sidebar, the [ ] keys, a new split and a lesson step's
// captions all read the list through these.
#pragma once

#include <string>
#include <vector>

#include "debug/technique.h"

namespace airlight {

// Entries in the views list: 0 the final frame, 1 L_air, 2 + i the run's intermediate i.
int contentCount(const viz::FrameOutput& out);
std::string contentId(const viz::FrameOutput& out, int index);
std::string contentLabel(const viz::FrameOutput& out, int index);
// The index of the first entry with this id; -1 when the run has none.
int contentIndexOf(const viz::FrameOutput& out, const std::string& id);

// Why the run `out` of `technique` has no intermediate `id` (a view's stand-in note): a view of another
// technique, a stage after where the run stopped or one the plan skipped (with the plan's reason), or a
// stage that ran without it (its settings leave it out).
std::string notMadeBecause(const viz::Technique& technique, const viz::FrameOutput& out, const std::string& id);

// What a view that chose `chosen` shows of the run `out`: the chosen content when the run has it (an
// intermediate whose id repeats, one shadow map per light, at the view's `index` in out.intermediates
// when that still holds it, else the first); L_air in its stead, with the stand-in note, when it does not;
// and, for a run stepped to a stage before the final frame or L_air exists, what that stage published,
// preferring what no other view shows (`elsewhere`: the other views' chosen contents and what they show).
// A final-frame view standing in leaves the stage's first view to an L_air view elsewhere; where L_air
// exists and another view shows it, the final-frame view shows the stage's views rather than L_air again.
struct ShownContent {
    std::string content;  // "final", "airlight" or an intermediate id
    int index = -1;       // its position in out.intermediates; -1 for the final frame and L_air
    std::string standIn;  // why the chosen content is not shown ("" when it is)
};
ShownContent shownContent(const viz::Technique& technique, const viz::FrameOutput& out, const std::string& chosen,
                          int index, const std::vector<std::string>& elsewhere);

}  // namespace airlight
