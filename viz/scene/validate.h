// Checks that apply to any Scene, whether loaded from glTF or built in code: finite geometry, at least
// one triangle and one light, indices and references in range, a physical medium and camera.
#pragma once

#include "scene/scene.h"

namespace viz::scene {

// Throws viz::InputError with a one-line message naming the scene and the offending item.
void validateScene(const Scene& scene);

}  // namespace viz::scene
