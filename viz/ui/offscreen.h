// Drawing a DrawList into an image instead of a window: plots and handouts written to files share the
// exact drawing code of the UI. Needs a current GL 4.5 context (a HeadlessContext will do).
#pragma once

#include <glm/glm.hpp>

#include "core/image.h"
#include "ui/text_renderer.h"

namespace viz::ui {

// Renders `list` over `background` (a display colour) into an RGBA8 target of `size` pixels and returns
// it as a linear RGB image (display values decoded from sRGB), so that writeImage's PNG encoding
// gives back the colours the list asked for.
Image renderOffscreen(const DrawList& list, glm::ivec2 size, glm::vec4 background);

// Display values (sRGB-encoded, as a display target holds them) as linear RGB: what writeImage's PNG
// encoding turns back into those display values.
Image linearFromDisplay(const Image& display);

}  // namespace viz::ui
