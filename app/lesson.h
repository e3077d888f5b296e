// Lessons: guided walkthroughs in plain Markdown files (lessons/*.md), readable and editable without
// building anything. A lesson is a title and an introduction, then steps: each step starts at a level-2
// heading and holds prose plus one fenced block tagged `airlight` that says what to show:
//
//   ## 2. More samples
//   ```airlight
//   scene: grate              built-in scene, stiff/ID or a glTF path (the first step must name one)
//   technique: raymarch
//   size: 160x120
//   set: samples=256          name=value, repeatable; a step's settings replace the previous step's
//   stage: raymarch.march     stop after this stage (default: run everything)
//   views: final, raymarch.airlight   what to show (final, airlight or intermediate ids)
//   inspect: 80 60            a pixel for the ray inspector
//   compare: raymarch, slices time these techniques live on the reader's machine (the window's comparison
//                             grid; a table in the handout): run time and error against the reference
//   animate: substeps 2s      optional: in the window, run the stage's sub-steps 1..N over 2 seconds
//                             (the stage must declare them, StageInfo::substepParam), or
//   animate: light orbit 4s   move the first light once round a cone about its aim point (GPU
//                             techniques; point, spot and directional lights)
//   ```
//   Prose: paragraphs, `code`, *emphasis*, **strong**, and formulas as plain text.
//
// A step inherits scene, technique and size from the step before when it does not name them; settings
// and the animation belong to the step that names them. An animation ends where it started or where the
// static step stands (all sub-steps; the light back at its place), so the export renders that state: the
// animation's last frame.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "lesson_markdown.h"
#include "debug/technique.h"

namespace airlight {

// A short animation a step plays in the window (Space pauses and replays it).
struct LessonAnimation {
    enum class Kind { None, Substeps, LightOrbit };
    Kind kind = Kind::None;
    double seconds = 0.0;  // duration of one run
    int line = 0;          // of the `animate:` line, for messages
};

struct LessonStep {
    std::string title;
    std::vector<ProseBlock> prose;  // its Markdown, parsed once (lesson_markdown.h)
    int line = 0;       // of the heading, for messages
    std::string scene, technique;
    int width = 160, height = 120;
    viz::Settings settings;
    std::string stage;               // empty: run everything
    std::vector<std::string> views;  // empty: final and airlight
    std::optional<glm::ivec2> inspect;
    LessonAnimation animation;
    // Techniques to time and compare live (never figures measured elsewhere): empty for none.
    std::vector<std::string> compare;
};

struct Lesson {
    std::string path, title;
    std::vector<ProseBlock> intro;  // the text before the first step, parsed once
    std::vector<LessonStep> steps;
};

// Throws InputError "FILE:LINE: reason" for an unknown key, a bad value, a step without a scene, an
// unknown technique, a stage or setting the step's technique does not have, an animation the step cannot
// play, a second block in one step, an unclosed block or a lesson without steps.
Lesson parseLesson(const std::string& path);

// The lessons/ folder: $AIRLIGHT_LESSON_DIR when set, else the source tree's lessons/.
std::string lessonDirectory();

// A lesson by name: NAME.md in lessonDirectory() or the working folder's lessons/, or a path to a .md file.
// NAME may be shortened as far as it stays one lesson's: its number ("3" or "03") or the start or any part
// of its name ("slices", "min-max"); unknown or ambiguous names are an InputError listing the lessons.
std::string findLesson(const std::string& nameOrPath);
// The lesson `name` picks among `lessons` (file stems, "01-airlight-integral", ...), as findLesson reads
// it; empty when none or several do, with `matches` holding the several.
std::string matchLesson(const std::string& name, const std::vector<std::string>& lessons,
                        std::vector<std::string>& matches);

// Renders every step headlessly (each named view as PNG) and writes DIR/index.html with the text and the
// images. `size` (if non-zero) overrides every step's image size. Checks that every named view exists.
void exportLesson(const Lesson& lesson, const std::string& folder, glm::ivec2 size = glm::ivec2(0));

// "substeps over 2 s", "light orbit over 4 s", or empty.
std::string describeAnimation(const LessonAnimation& animation);

}  // namespace airlight
