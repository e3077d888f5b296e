// The stiff and extreme cases: scenes and settings that break naive airlight code (extreme media,
// intensities and scales, rays through the light, awkward epipoles, cameras inside things, degenerate
// geometry, huge depth ranges, extreme phase functions). Each is a built-in scene with one edit.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace viz::scene {

struct StiffCase {
    std::string id;           // "extinction-50"
    std::string caseClass;    // what a technique's bound is declared for: "medium", "scale", ...
    std::string description;  // one line
    std::string baseScene;    // built-in scene it edits
    std::function<void(Scene&)> edit;
    // Odd sizes put a pixel centre exactly on the image centre (the camera's forward ray).
    int width = 33, height = 25;
    // Pixels within this many pixels of a point light's projection are left out of the error figures
    // (they stay in the finite checks): the integral of 1/r^2 along a ray through a point light
    // diverges, so there the value depends only on the clamp of h (viz/shared/airlight.h).
    double excludeAroundLight = 0.0;
};

// Every case, in a fixed order. Case classes: medium, intensity, scale, singular-ray (a ray through a
// point light; its pixel is left out), near-light (a ray 1e-6 from one; its pixel counts), epipole, leak
// (a thin occluder grazed by the light), camera-placement, geometry, depth-range, phase
// (docs/numerics.md#stiff-classes).
const std::vector<StiffCase>& stiffCases();

// The base scene with the case's edit applied, validated (throws InputError if an edit broke it).
// Its name is "stiff/<id>", which loadScene() also accepts.
Scene buildStiffScene(const StiffCase& c);

// The case with this id, or nullptr.
const StiffCase* findStiffCase(const std::string& id);

}  // namespace viz::scene
