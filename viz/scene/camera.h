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

// The rays of one width x height image: the per-image constants (the field of view's tangent, the aspect,
// the right vector) computed once, for loops over every pixel. rays(x, y) is pixelRay's ray.
class PixelRays {
public:
    PixelRays(const Camera& cam, int width, int height)
        : mForward(cam.forward), mUp(cam.up), mRight(cameraRight(cam)), mTanHalf(std::tan(cam.yfov * 0.5)),
          mAspect(aspectOf(cam, width, height)), mWidth(double(width)), mHeight(double(height)) {}
    // Unit direction of the ray through the centre of pixel (x, y).
    glm::dvec3 operator()(double x, double y) const {
        const double ndcX = 2.0 * (x + 0.5) / mWidth - 1.0;
        const double ndcY = 1.0 - 2.0 * (y + 0.5) / mHeight;
        return glm::normalize(mForward + (ndcX * mTanHalf * mAspect) * mRight + (ndcY * mTanHalf) * mUp);
    }

private:
    glm::dvec3 mForward, mUp, mRight;
    double mTanHalf, mAspect, mWidth, mHeight;
};

// Unit direction of the ray through the centre of pixel (x, y) of a width x height image.
inline glm::dvec3 pixelRay(const Camera& cam, int width, int height, double x, double y) {
    return PixelRays(cam, width, height)(x, y);
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
