// The light gizmo drawn over the frame: two handles the user drags to place the scene's first light.
//   position handle (point and spot lights): the light's position; dragging moves the light in the
//     plane through it parallel to the image plane, so it stays under the cursor at its depth;
//   direction handle (spot and directional lights): the tip of an arm of fixed length in the scene;
//     dragging turns the light so that the tip stays under the cursor, on the sphere of the arm's
//     length about the arm's root. A spot's arm grows from its position along the direction the light
//     travels; a directional light's arm ends at an anchor (the orbit target) and comes from where the
//     light comes from, so the tip is the "sun" and the arm shows the rays' direction.
// Area lights are scene geometry (their rectangle is a mesh) and have no handles.
// Plain math on the camera's pixel rays (scene::pixelRay) in frame pixels: x right, y down, pixel (i, j)
// covering [i, i+1) x [j, j+1); no window or GL, so it is tested on the CPU.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace airlight {

struct GizmoHandles {
    std::optional<glm::dvec2> position;  // in front of the camera only
    std::optional<glm::dvec2> tip;       // the direction handle
    std::optional<glm::dvec2> root;      // where the arm starts on screen (the position, or the anchor)
};

class LightGizmo {
public:
    // camera and frame: the view the handles are drawn over; arm: the direction arm's length (scene
    // units, > 0); anchor: where a directional light's arm ends.
    LightGizmo(const viz::scene::Camera& camera, glm::ivec2 frame, double arm, glm::dvec3 anchor);

    static bool hasHandles(const viz::scene::Light& light);
    GizmoHandles handles(const viz::scene::Light& light) const;

    // Moves `light` so that its position handle is at `pixel`. False (light unchanged) when the light
    // is not in front of the camera or has no position handle.
    bool dragPosition(viz::scene::Light& light, glm::dvec2 pixel) const;
    // Turns `light` so that its direction handle is at `pixel` (or as near as the arm's sphere allows
    // when the cursor's ray misses it). False when the light has no direction handle.
    bool dragDirection(viz::scene::Light& light, glm::dvec2 pixel) const;

    // A world point in frame pixels; none when it is not in front of the camera.
    std::optional<glm::dvec2> project(glm::dvec3 world) const;
    // The unit ray from the eye through a frame point (continuous pixels).
    glm::dvec3 rayThrough(glm::dvec2 pixel) const;

private:
    // The arm's root (spot: position; directional: the tip's opposite end is the anchor) and its tip.
    glm::dvec3 armRoot(const viz::scene::Light& light) const;
    glm::dvec3 armTip(const viz::scene::Light& light) const;

    viz::scene::Camera mCamera;
    glm::ivec2 mFrame;
    double mArm;
    glm::dvec3 mAnchor;
};

}  // namespace airlight
