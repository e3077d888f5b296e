// From a scene's camera and one of its point, spot or directional lights to the epipolar frame and grid that vsv
// uses (pure CPU: the technique and its tests build the same grid).
#pragma once

#include <cmath>

#include "scene/camera.h"
#include "scene/ray_reach.h"
#include "scene/scene.h"
#include "techniques/vsv/epipolar.h"

namespace viz::vsv {

inline EpipolarFrame frameForLight(const scene::Scene& scene, const scene::Light& light) {
    if (light.type == scene::LightType::Directional) return makeDirectionalFrame(light.direction);
    return makeFrame(light.position - scene.camera.position);
}

inline CameraRays cameraRays(const scene::Camera& cam, int width, int height) {
    CameraRays c;
    c.forward = cam.forward;
    c.right = scene::cameraRight(cam);
    c.up = cam.up;
    c.tanY = std::tan(cam.yfov * 0.5);
    c.tanX = c.tanY * scene::aspectOf(cam, width, height);
    return c;
}

inline SpotCone spotConeOf(const scene::Light& light) {
    SpotCone s;
    if (light.type == scene::LightType::Spot) {
        s.present = true;
        s.axis = light.direction;
        s.outer = light.outerConeAngle;
    }
    return s;
}

inline EpipolarGrid gridForLight(const scene::Scene& scene, const scene::Light& light, int width, int height,
                                 int nAlpha, int nTheta, int nPhi, bool dynamic) {
    return selectRanges(frameForLight(scene, light), cameraRays(scene.camera, width, height), scene::depthOfInterest(scene),
                        spotConeOf(light), nAlpha, nTheta, nPhi, dynamic);
}

}  // namespace viz::vsv
