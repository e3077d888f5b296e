// What a run offers the view grid, as plain functions of its output: the views list (the final frame,
// L_air, then every intermediate the run published, in order), each entry's id and label, and why a view
// chosen earlier is not in this run. The window's sidebar, the [ ] keys, a new split and a lesson step's
// captions all read the list through these.
#pragma once

#include <string>

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

}  // namespace airlight
