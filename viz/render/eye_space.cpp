#include "render/eye_space.h"

#include <glm/gtc/matrix_transform.hpp>

#include "scene/camera.h"

namespace viz::render {

glm::mat4 eyeRelativeModel(const glm::dvec3& eye) {
    return glm::mat4(glm::translate(glm::dmat4(1.0), -eye));
}

glm::mat4 eyeRelativeViewProjection(const scene::Camera& camera, int width, int height) {
    // The view matrix of a camera at the origin: only the rotation of scene::viewMatrix remains.
    const glm::dmat4 view = glm::lookAt(glm::dvec3(0.0), camera.forward, camera.up);
    return glm::mat4(scene::projectionMatrix(camera, width, height) * view);
}

}  // namespace viz::render
