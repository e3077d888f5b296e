// The one definition of a pixel's ray, used by the reference (double) and mirrored by the GPU
// techniques: pixel (x, y), y = 0 the top row, through the pixel centre.
#pragma once

#include <cmath>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "scene/scene.h"

namespace viz::scene {

inline double aspectOf(const Camera& cam, int width, int height) {
    return cam.aspectRatio > 0.0 ? cam.aspectRatio : double(width) / double(height);
}

inline glm::dvec3 cameraRight(const Camera& cam) { return glm::normalize(glm::cross(cam.forward, cam.up)); }

// Unit direction of the ray through the centre of pixel (x, y) of a width x height image.
inline glm::dvec3 pixelRay(const Camera& cam, int width, int height, double x, double y) {
    const double tanHalf = std::tan(cam.yfov * 0.5);
    const double ndcX = 2.0 * (x + 0.5) / double(width) - 1.0;
    const double ndcY = 1.0 - 2.0 * (y + 0.5) / double(height);
    const glm::dvec3 d = cam.forward + (ndcX * tanHalf * aspectOf(cam, width, height)) * cameraRight(cam) +
                         (ndcY * tanHalf) * cam.up;
    return glm::normalize(d);
}

// Right-handed view matrix (camera looks down -Z) and an OpenGL projection whose far plane is pushed out
// so that no point within Euclidean distance zfar of the eye is clipped; techniques clamp t to zfar.
inline glm::dmat4 viewMatrix(const Camera& cam) {
    return glm::lookAt(cam.position, cam.position + cam.forward, cam.up);
}
inline double projectionFar(const Camera& cam, int width, int height) {
    const double tanHalf = std::tan(cam.yfov * 0.5);
    const double tx = tanHalf * aspectOf(cam, width, height);
    return cam.zfar * 1.0001 * std::sqrt(1.0 + tx * tx + tanHalf * tanHalf);
}
inline glm::dmat4 projectionMatrix(const Camera& cam, int width, int height) {
    return glm::perspective(cam.yfov, aspectOf(cam, width, height), cam.znear, projectionFar(cam, width, height));
}

}  // namespace viz::scene
