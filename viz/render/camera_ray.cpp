#include "render/camera_ray.h"

#include <cmath>

#include <glm/glm.hpp>

#include "scene/camera.h"

namespace viz::render {

void bindCameraRay(const gl::Program& program, const scene::Camera& camera, int width, int height) {
    program.set("uSize", glm::ivec2(width, height));
    program.set("uForward", glm::vec3(camera.forward));
    program.set("uRight", glm::vec3(scene::cameraRight(camera)));
    program.set("uUp", glm::vec3(camera.up));
    program.set("uTanHalf", float(std::tan(camera.yfov * 0.5)));
    program.set("uAspect", float(scene::aspectOf(camera, width, height)));
}

}  // namespace viz::render
