#include "status_bar.h"

#include "input_table.h"
#include "ui/theme.h"
#include "window_common.h"

namespace airlight {

namespace {
std::string sizeText(glm::ivec2 size) { return std::to_string(size.x) + "x" + std::to_string(size.y); }

glm::vec4 colourOf(StatusTone tone) {
    switch (tone) {
    case StatusTone::Text: return viz::ui::theme::kText;
    case StatusTone::Accent: return viz::ui::theme::kAccent;
    case StatusTone::Error: return viz::ui::theme::kError;
    case StatusTone::Dim: break;
    }
    return viz::ui::theme::kDim;
}
}  // namespace

std::string timingLine(const viz::Timing& timing) {
    if (timing.stages.empty()) return "timings: (none yet)";
    // The total and its clock first: a narrow window cuts the line at its end, and the stages are also in
    // the stage-times chart under the views.
    // A run that compiled shaders (a first run, a new permutation) says so: its times are no warm figures,
    // and the stages that compiled carry a '*'.
    const int compiled = timing.programsCompiled();
    std::string line = "timings: total " + viz::format("%.1f ms", timing.totalMilliseconds()) + " (clock: " +
                       timing.clock +
                       (compiled ? ", * includes compiling " + std::to_string(compiled) + " shader program" +
                                       (compiled == 1 ? "" : "s") + " (first use)"
                                 : std::string()) +
                       ")   |";
    for (const auto& st : timing.stages)
        line += "  " + st.stage + " " + viz::format("%.1f ms", st.milliseconds) + (st.programsCompiled ? "*" : "");
    return line;
}

std::string skippedLine(const viz::Plan& plan) {
    std::string line;
    for (const auto& st : plan.stages) {
        if (st.runs) continue;
        line += (line.empty() ? "skipped: " : ";  ") + st.stage + (st.why.empty() ? "" : " (" + st.why + ")");
    }
    return line.empty() ? "skipped: none" : line;
}

std::array<StatusLine, 3> statusLines(const StatusFacts& f) {
    // Where the frame is comes first, the technique's one-line description last: at a narrow window the
    // line is cut at its end, and the cursor matters more than the description.
    std::string head = "scene: " + f.scene + "   technique: " + f.technique + "   render " + sizeText(f.renderSize);
    if (f.haveOutput && f.reduced) head += "   (interactive: " + sizeText(f.outputSize) + ")";
    if (f.haveOutput && f.passCount > 1)
        head += "   (showing pass " + std::to_string(f.pass) + "/" + std::to_string(f.passCount) + ": " +
                sizeText(f.outputSize) + ")";
    head += "   stage " + std::to_string(f.stage + 1) + "/" + std::to_string(f.stageCount) + " " + f.stageId;
    if (f.substepCount > 0) head += " sub-step " + std::to_string(f.substep) + "/" + std::to_string(f.substepCount);
    const std::string keys = keyNames({Command::NextStage, Command::NextSubstep, Command::FirstSubstep,
                                        Command::LastSubstep},
                                       KeyState{.fly = f.fly});
    if (!keys.empty()) head += " (" + keys + ")";
    if (f.haveOutput && f.firstStageRun > 0)
        head += "   re-ran from stage " + std::to_string(f.firstStageRun + 1) + " (earlier ones kept)";
    if (!f.description.empty()) head += "   (" + f.technique + ": " + f.description + ")";

    // The third line: an error wins, then the session's notice, then the run's first note, each ahead of
    // the skipped stages (which an error replaces: the plan shown is not this run's).
    StatusLine third{skippedLine(f.plan), StatusTone::Dim};
    if (!f.error.empty() || !f.settingsError.empty()) {
        third = {"error: " + firstLine(f.error.empty() ? f.settingsError + " (using defaults)" : f.error), StatusTone::Error};
    } else if (!f.notice.empty()) {
        third.text = f.notice + "   |   " + third.text;
    } else if (f.haveOutput && !f.note.empty()) {
        third = {"note: " + f.note + "   |   " + third.text, StatusTone::Accent};
    }
    return {StatusLine{head, StatusTone::Text},
            StatusLine{f.haveOutput ? timingLine(f.timing) : "timings: (no run yet)", StatusTone::Dim}, third};
}

float drawStatusLines(viz::ui::DrawList& background, viz::ui::DrawList& text, const std::array<StatusLine, 3>& lines,
                      float width, float pad, float line) {
    background.rect({{0.0f, 0.0f}, {width, 3.0f * line + 2.0f * pad}}, viz::ui::theme::kPanel);
    for (std::size_t i = 0; i < lines.size(); ++i)
        text.textClipped({pad, pad + float(i) * line}, lines[i].text, colourOf(lines[i].tone), width - pad);
    return 3.0f * line + 3.0f * pad;
}

}  // namespace airlight
