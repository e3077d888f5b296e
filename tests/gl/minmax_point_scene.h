// The point-light test scene of the minmax tests and benchmark: the grate with its spot replaced by a
// point light at the spot's position (400 cd), seen with the light on screen, off screen or behind the
// camera.
#pragma once

#include <string>

#include "scene/builtin_scenes.h"
#include "scene/scene_building.h"

namespace viz::testing {

// camera: "on" looks up past the grate so the light is in the image; "off" is the built-in view (the
// light just above the top edge); "behind" stands under the grate looking down and away (the light
// behind the camera). The light shines through the bars onto the floor and lights the room above.
inline scene::Scene pointGrate(const std::string& camera) {
    scene::Scene s = scene::makeBuiltinScene("grate");
    scene::Light l{.name = "point",
                   .type = scene::LightType::Point,
                   .position = {0.0, 6.0, 0.0},
                   .colour = {1.0, 0.92, 0.8},
                   .intensity = 400.0};
    s.lights = {l};
    s.name = "point-grate-" + camera;
    if (camera == "on") s.camera = scene::lookAt("on", {0.0, 0.8, 7.0}, {0.0, 3.2, 0.0}, 0.9, 0.05, 40.0);
    if (camera == "behind") s.camera = scene::lookAt("behind", {0.0, 2.0, 1.0}, {0.0, 0.5, -3.0}, 1.0, 0.05, 40.0);
    return s;
}

}  // namespace viz::testing
