// The box around a scene's geometry, walked once per stamped scene.
//
// Many passes size themselves by the scene's bounds every frame (shadow maps, the far-camera policy in
// ray_reach.h, the mesh view), and the GPU upload is reused by the geometry's content hash. On a model of
// a million vertices one walk takes milliseconds and the hash tens of them, per call. A scene whose owner
// has stamped it (stampGeometry in scene_source.h: the window, bench and report, after loading) has
// both once.
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace viz::scene {

struct Bounds {
    glm::dvec3 lo{0.0}, hi{0.0};  // both 0 when empty
    bool empty = true;
    glm::dvec3 centre() const { return 0.5 * (lo + hi); }
    double diagonal() const { return empty ? 0.0 : glm::length(hi - lo); }
    double radius() const { return 0.5 * diagonal(); }  // of the bounding sphere about centre()
};

// The box around every mesh vertex (empty when there are none). A stamped scene's box is walked once per
// key and kept (a few keys at a time, for every thread).
Bounds sceneBounds(const Scene& scene);

}  // namespace viz::scene
