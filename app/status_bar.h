// The status lines at the top of the window: where the frame is (scene, technique, size, pass, stage and
// sub-step), what its stages cost, and what the plan left out, or the error, notice or note that matters
// more. Built as plain text from plain facts, so the rules (which message wins the third line, what a
// reduced or partial frame says) are tested without a window.
#pragma once

#include <array>
#include <string>

#include <glm/glm.hpp>

#include "debug/plan.h"
#include "debug/timing.h"
#include "ui/text_renderer.h"

namespace airlight {

struct StatusFacts {
    std::string scene;        // its title (a glTF file's name)
    std::string technique;    // id
    std::string description;  // the technique's one line
    glm::ivec2 renderSize{0};
    bool haveOutput = false;   // a run has finished; the rest of the run facts describe it
    bool reduced = false;      // it ran smaller while the user interacts
    glm::ivec2 outputSize{0};  // its size (reduced, or the progressive pass's)
    int pass = 0, passCount = 1;
    // The stepping cursor: stage shown (0-based) of stageCount, its id, and the sub-step (0 of 0: none).
    int stage = 0, stageCount = 1;
    std::string stageId;
    int substep = 0, substepCount = 0;
    bool fly = false;       // the camera is in fly mode: the stepping keys it takes are not offered
    int firstStageRun = 0;  // > 0: the run resumed there, the earlier stages kept
    viz::Timing timing;     // with its clock named
    viz::Plan plan;         // the plan shown: its skipped stages
    std::string error;          // the last run's error
    std::string settingsError;  // settings refused (the run used the defaults)
    std::string notice;         // the last session or file message
    std::string note;           // the run's first note
};

enum class StatusTone { Text, Dim, Accent, Error };

struct StatusLine {
    std::string text;
    StatusTone tone = StatusTone::Dim;
};

// The three lines, top to bottom.
std::array<StatusLine, 3> statusLines(const StatusFacts& facts);

// "timings:  stage 1.0 ms ...  | total ... (clock: ...)", or that there are none yet.
std::string timingLine(const viz::Timing& timing);
// "skipped: stage (why);  ..." over the plan's stages that do not run, or "skipped: none".
std::string skippedLine(const viz::Plan& plan);

// Draws the lines on a panel across the top of the window `width` wide; returns the panel's height.
float drawStatusLines(viz::ui::DrawList& background, viz::ui::DrawList& text, const std::array<StatusLine, 3>& lines,
                      float width, float pad, float line);

}  // namespace airlight
