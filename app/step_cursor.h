// The stepping cursor's rules, as plain functions of a technique, its settings and the last run's own
// sub-step counts: which stage a cursor shows, where it stands inside that stage, what S, Shift+S, D,
// Shift+D, Home and End do from there, and how a frame that is not the complete algorithm says so. The
// window keeps the cursor (AppState::cursor) and calls these; tests call them on every technique.
#pragma once

#include <map>
#include <string>

#include "debug/technique.h"
#include "run_scheduler.h"

namespace airlight {

// The stage index the cursor resolves to: its own, or the last stage for the complete frame.
int stageShownBy(const viz::Technique& technique, StepCursor cursor);

// Where the cursor stands inside the stage it shows: sub-step `at` of `count` (1-based; a whole stage is at
// its last), or {0, 0} for a stage without sub-steps. `runCounts`: FrameOutput::substepCounts of the last
// run, where a run counts fewer than listed (minmax's walk: the picked ray's nodes).
struct SubstepAt {
    int at = 0, count = 0;
};
SubstepAt substepAt(const viz::Technique& technique, const viz::Settings& settings, StepCursor cursor,
                    const std::map<int, int>& runCounts);

// The cursor in its one spelling: the complete frame is {-1, 0} (the last stage whole, or any stage index
// out of range, is the complete frame); a sub-step of the complete frame is one of the last stage.
StepCursor normalisedCursor(const viz::Technique& technique, StepCursor cursor);

// S (delta 1) and Shift+S (delta -1): the next or previous stage, wrapping through the complete frame; a
// stage with sub-steps is entered at its first.
StepCursor stageStepped(const viz::Technique& technique, const viz::Settings& settings, StepCursor cursor,
                        int delta);

// D, Shift+D, Home, End: sub-step k of the shown stage. Outside 1..count, or in a stage without
// sub-steps, the cursor stays and `notice` says why (the status bar shows it).
struct SubstepMove {
    StepCursor cursor;
    std::string notice;  // empty when the cursor moved
};
SubstepMove substepMovedTo(const viz::Technique& technique, const viz::Settings& settings, StepCursor cursor,
                           const std::map<int, int>& runCounts, int k);

// Why the frame is not the complete algorithm ("stopped after stage 2/5 slices.surface", "stopped in
// vsv.scan at sub-step 3/10", a sub-step parameter set away from its default that cuts a stage short);
// empty for the complete frame.
std::string stoppedEarly(const viz::Technique& technique, const viz::Settings& settings, StepCursor cursor,
                         const std::map<int, int>& runCounts);

}  // namespace airlight
