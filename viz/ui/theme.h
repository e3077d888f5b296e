// The one theme of everything Airlight draws: the window (its panels, sidebar and step timeline), the
// lesson panel, the widgets (ui::Style's defaults) and the plots. Colours are display values (sRGB-encoded,
// not light); sizes are logical pixels, times the content scale. Colours are named by their role, so two
// roles may share a value.
#pragma once

#include <array>

#include <glm/glm.hpp>

namespace viz::ui::theme {

// ---- screen: dark surfaces, light text ----
inline constexpr glm::vec4 kBackground{0.11f, 0.11f, 0.12f, 1.0f};
inline constexpr glm::vec4 kPanel{0.16f, 0.16f, 0.18f, 1.0f};
inline constexpr glm::vec4 kText{0.90f, 0.90f, 0.90f, 1.0f};
inline constexpr glm::vec4 kDim{0.60f, 0.62f, 0.66f, 1.0f};  // secondary text, captions
inline constexpr glm::vec4 kAccent{0.98f, 0.78f, 0.35f, 1.0f};  // what the eye should find: the cursor, marks
inline constexpr glm::vec4 kHighlight{0.25f, 0.36f, 0.55f, 1.0f};  // the selected item, the current stage
inline constexpr glm::vec4 kHover{0.22f, 0.22f, 0.26f, 1.0f};
inline constexpr glm::vec4 kError{1.0f, 0.45f, 0.40f, 1.0f};
inline constexpr glm::vec4 kRule{0.30f, 0.32f, 0.36f, 1.0f};  // separators

// ---- widgets (ui::Style) ----
inline constexpr glm::vec4 kWidgetPanel{0.12f, 0.13f, 0.15f, 0.96f};
inline constexpr glm::vec4 kFrame{0.22f, 0.24f, 0.28f, 1.0f};
inline constexpr glm::vec4 kFrameHot{0.30f, 0.33f, 0.39f, 1.0f};
inline constexpr glm::vec4 kFrameActive{0.36f, 0.42f, 0.52f, 1.0f};
inline constexpr glm::vec4 kWidgetAccent{0.33f, 0.62f, 0.95f, 1.0f};  // a slider's fill, a checked box
inline constexpr glm::vec4 kFocusRing{0.95f, 0.78f, 0.30f, 1.0f};

// ---- the step timeline ----
inline constexpr glm::vec4 kSegment{0.20f, 0.20f, 0.23f, 1.0f};
inline constexpr glm::vec4 kTick{0.45f, 0.47f, 0.52f, 1.0f};
inline constexpr glm::vec4 kLabel{0.80f, 0.80f, 0.82f, 1.0f};

// ---- lesson prose ----
inline constexpr glm::vec4 kCode{0.55f, 0.92f, 0.72f, 1.0f};  // `code`: a terminal green on a dark box
inline constexpr glm::vec4 kCodeBox{0.20f, 0.23f, 0.22f, 1.0f};
inline constexpr glm::vec4 kEmphasis{0.62f, 0.80f, 1.0f, 1.0f};  // *emphasis*: no italic face, so a colour
inline constexpr glm::vec4 kStrong{1.0f, 1.0f, 1.0f, 1.0f};      // **strong**: drawn twice, one pixel apart
inline constexpr glm::vec4 kFormula{0.80f, 0.86f, 0.95f, 1.0f};
inline constexpr glm::vec4 kFormulaBox{0.17f, 0.18f, 0.22f, 1.0f};

// ---- plots: dark ink on white paper (they go into handouts and reports as they are) ----
inline constexpr glm::vec4 kInk{0.12f, 0.12f, 0.14f, 1.0f};
inline constexpr glm::vec4 kGridLine{0.86f, 0.86f, 0.88f, 1.0f};
inline constexpr glm::vec4 kPaper{1.0f, 1.0f, 1.0f, 1.0f};
// Series and categories: distinct hues that stay apart for common colour-vision deficiencies (Okabe-Ito
// order), then grey.
inline constexpr std::array<glm::vec4, 8> kSeries = {{{0.0f, 0.447f, 0.698f, 1.0f},
                                                      {0.835f, 0.369f, 0.0f, 1.0f},
                                                      {0.0f, 0.620f, 0.451f, 1.0f},
                                                      {0.800f, 0.475f, 0.655f, 1.0f},
                                                      {0.902f, 0.624f, 0.0f, 1.0f},
                                                      {0.337f, 0.706f, 0.914f, 1.0f},
                                                      {0.941f, 0.894f, 0.259f, 1.0f},
                                                      {0.3f, 0.3f, 0.3f, 1.0f}}};

// ---- sizes ----
inline constexpr float kFontSize = 15.0f;
inline constexpr float kPad = 8.0f;

}  // namespace viz::ui::theme
