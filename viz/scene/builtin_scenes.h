// Scenes generated in code (deterministic, no files), each tuned so that light shafts are clearly
// visible at 160x120 with airlight of the same order as the surface light. Units: metres.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace viz::scene {

// In menu order: colonnade (the default), grate, forest, terrain, stained-glass, tv-room.
std::vector<std::string> builtinSceneNames();
std::string defaultSceneName();
bool isBuiltinScene(const std::string& name);

// Throws viz::InputError for an unknown name, listing the known ones.
Scene makeBuiltinScene(const std::string& name);

// Tiny scenes for tests (not listed): a floor, one box and a spot light (12 + 2 triangles).
Scene makeTestScene();
// The same room with a small textured emissive rectangle as its only light.
Scene makeTestAreaLightScene();

}  // namespace viz::scene
