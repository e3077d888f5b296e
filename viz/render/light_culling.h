// Leaving out a light whose lit volume cannot reach anything the camera sees: it lights no visible
// surface and no visible air, so it gets no shadow map and no technique work at all.
#pragma once

#include <string>
#include <vector>

#include "debug/technique.h"
#include "scene/scene.h"

namespace viz::render {

// The widest image the test allows for when the camera leaves the aspect to the image: the decision
// must not depend on the image size, so that plan() (which has none) and run() agree.
inline constexpr double kCullingAspect = 2.5;

// False only when the light's lit volume lies entirely outside one plane of the camera's view volume
// (near plane, four sides at aspect max(camera aspect, kCullingAspect), far plane at zfar):
//   spot: the cone (apex, axis, outer angle) is outside a plane when its apex is and its axis makes at
//         least 90 degrees + the outer angle with the plane's inward normal;
//   area: its emitting half-space misses the view volume when every corner of the volume is behind it;
//   point, directional: their light fills all space, never culled.
bool lightReachesView(const scene::Light& light, const scene::Camera& camera);

// Names of the scene's lights that are culled, in scene order.
std::vector<std::string> culledLightNames(const scene::Scene& scene);

// Adds one disabled feature "LIGHT <name>" per culled light to a technique's plan, with the reason.
void planCulledLights(const scene::Scene& scene, Plan& plan);

}  // namespace viz::render
