// A lesson's prose as the lesson panel draws it: the blocks of lesson_markdown.h (paragraphs, headings,
// list items, formulas) with `code`, *emphasis* and **strong** inline, wrapped to the panel's width. Also the
// panel's colours, which the player's own text uses.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "lesson_markdown.h"
#include "ui/text_renderer.h"
#include "ui/theme.h"

namespace airlight {

// Display colours: the window's text colours on the widgets' panel colour, contrast for a projector.


// One line of text in `style` with its inline Markdown, wrapped within `width` from `at`; returns the
// height it took.
float drawLessonText(viz::ui::DrawList& dl, const std::string& text, SpanStyle style, glm::vec2 at, float width,
                     float scale);

// Draws parsed prose from `at` (top left) within `width` pixels; returns the height it took.
float drawLessonProse(viz::ui::DrawList& dl, const std::vector<ProseBlock>& prose, glm::vec2 at, float width,
                      float scale);

}  // namespace airlight
