// What a loaded model gets when its file lacks a light or a medium, sized from the model itself so
// that a millimetre-scale part and a building look alike: a spot light above the model aimed at it (its
// shadow is a shaft seen from the scene's camera) and a medium with optical depth 0.5 across the model.
#pragma once

#include <glm/glm.hpp>

#include "scene/bounds.h"
#include "scene/scene.h"

namespace viz::scene {

// A spot light 2.5 bounding radii above the model's centre, shifted a radius towards the camera's
// right so its shadow leans across the view, aimed at the centre with a cone that covers the bounding
// sphere; irradiance 10 at the centre, whatever the scale.
Light defaultSpotLight(const Scene& scene);

// sigma_s = 0.5 / bounding-box diagonal, no absorption, isotropic.
Medium scaleAwareMedium(const Scene& scene);

}  // namespace viz::scene
