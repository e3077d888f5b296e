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

// The scene generators' detail parameter: grate, forest and terrain built with about `detail` times the
// triangles (more bars, more and thinner trunks, a finer heightfield) over the same extent, for measuring
// how a technique's cost grows with the scene. detail = 1 is makeBuiltinScene's scene exactly. Throws
// InputError for another scene or a detail outside [kMinSceneDetail, kMaxSceneDetail].
constexpr double kMinSceneDetail = 0.1, kMaxSceneDetail = 1000.0;
std::vector<std::string> detailedSceneNames();
Scene makeDetailedScene(const std::string& name, double detail);

// Tiny scenes for tests (not listed): a floor, one box and a spot light (12 + 2 triangles).
Scene makeTestScene();
// The same room with a small textured emissive rectangle as its only light.
Scene makeTestAreaLightScene();

}  // namespace viz::scene
