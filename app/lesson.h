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
//   ```
//   Prose: paragraphs, `code`, *emphasis*, **strong**, and formulas as plain text.
//
// A step inherits scene, technique and size from the step before when it does not name them.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "debug/technique.h"

namespace airlight {

struct LessonStep {
    std::string title;
    std::string prose;  // Markdown
    int line = 0;       // of the heading, for messages
    std::string scene, technique;
    int width = 160, height = 120;
    viz::Settings settings;
    std::string stage;               // empty: run everything
    std::vector<std::string> views;  // empty: final and airlight
    std::optional<glm::ivec2> inspect;
};

struct Lesson {
    std::string path, title, intro;
    std::vector<LessonStep> steps;
};

// Throws InputError "FILE:LINE: reason" for an unknown key, a bad value, a step without a scene, a
// second block in one step, an unclosed block or a lesson without steps.
Lesson parseLesson(const std::string& path);

// A lesson by name: lessons/NAME.md in the source tree or the working folder, or a path to a .md file.
std::string findLesson(const std::string& nameOrPath);

// Renders every step headlessly (each named view as PNG) and writes DIR/index.html with the text and the
// images. `size` (if non-zero) overrides every step's image size. Checks that every named view exists.
void exportLesson(const Lesson& lesson, const std::string& folder, glm::ivec2 size = glm::ivec2(0));

// Minimal Markdown to HTML for lesson prose: paragraphs, #/##/### headings, `code`, *em*, **strong**,
// "- " lists and four-space indented lines as preformatted text; everything else is escaped text.
std::string markdownToHtml(const std::string& markdown);

}  // namespace airlight
