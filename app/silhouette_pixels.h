// Silhouette pixels of one view (report/first_hits.h): where the reference's traced first hit and the
// rasterised one that every other technique draws disagree. `airlight report` counts them per scene and
// the window's comparison grid (G) per snapshot, each giving every error again without them.
#pragma once

#include "debug/technique.h"
#include "report/first_hits.h"
#include "scene/scene.h"

namespace airlight {

// The rasterised distance to each pixel's first surface (render::SurfacePass; every technique but the
// reference draws the same): raymarch's run up to the stage that publishes it. Needs a current GL context.
viz::Image rasterisedDistance(const viz::scene::Scene& scene, int width, int height);

// The reference's traced distance in `referenceRun` (its reference.distance), or nullptr when it
// published none.
const viz::Image* tracedDistance(const viz::FrameOutput& referenceRun);

// The pixels of `scene`'s view at the traced distance's size whose two first hits agree. Needs a current
// GL context.
viz::report::FirstHitMask silhouetteMask(const viz::Image& traced, const viz::scene::Scene& scene);

}  // namespace airlight
