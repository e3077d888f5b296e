// A view of the scene in 3D from an orbit camera of its own, for meshes a technique builds (polyvol's
// light volume, slices' sampling planes): the scene's surfaces shaded flat and dim, the main camera's
// frustum, each light as a marker, and whatever the technique draws into it. Everything is in the
// eye-relative space of the main camera (eye_space.h), so a technique draws its meshes with the same
// vertex code it uses for the camera view, only with orbitViewProjection() as the view-projection.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "gl/framebuffer.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "debug/params.h"
#include "gl/buffer.h"
#include "gl/vertex_array.h"
#include "render/gpu_scene.h"
#include "scene/scene.h"

namespace viz::render {

// Where the orbit camera stands: yaw about world +Y and pitch above the horizon (degrees), looking at
// the centre of the scene and the main camera together; zoom > 1 moves closer.
struct OrbitView {
    double yawDegrees = 35.0;
    double pitchDegrees = 25.0;
    double zoom = 1.0;
};
// The run request's orbit camera (FrameControls::orbitYaw, orbitPitch, orbitZoom).
inline OrbitView orbitOf(const FrameControls& c) { return {c.orbitYaw, c.orbitPitch, c.orbitZoom}; }

// The orbit camera's view-projection for a width x height image, taking the main camera's eye-relative
// space to clip space. The orbit target is the centre of the box holding the scene's bounds and the
// main camera; the distance fits that box's bounding sphere in the vertical field of view.
glm::mat4 orbitViewProjection(const scene::Scene& scene, const scene::Bounds& bounds, const OrbitView& orbit, int width,
                              int height);

// Line segments (pairs of points, eye-relative to scene.camera) for the main camera's frustum, from the
// eye to `depth` along its view, for a width x height image.
std::vector<glm::vec3> cameraFrustumLines(const scene::Camera& camera, int width, int height, double depth);
// A cross of half-size `size` at each point or spot light and at the centre of each area light, plus a
// segment of length 4 size along each spot, directional and area light's direction (for a directional
// light it starts at the orbit target `center`).
std::vector<glm::vec3> lightMarkerLines(const scene::Scene& scene, glm::dvec3 center, double size);

// The render target of a mesh view: RGBA8 colour with a depth buffer. begin() clears and binds it and
// draws the scene dim; the caller then draws its meshes with `viewProj()`; lines() adds line segments.
class MeshView {
public:
    void begin(const scene::Scene& scene, const GpuScene& gpuScene, const OrbitView& orbit, int width, int height);
    void lines(const std::vector<glm::vec3>& segments, glm::vec4 colour);
    const glm::mat4& viewProj() const { return mViewProj; }
    const gl::Texture& texture() const { return mColour; }
    void bindTarget() const;

private:
    gl::Texture mColour, mDepth;
    gl::Framebuffer mFramebuffer;
    gl::Program mSurfaces, mLines;
    gl::Buffer mLineBuffer;
    gl::VertexArray mLineArray;
    std::size_t mLineCapacity = 0;
    glm::mat4 mViewProj{1.0f};
    glm::mat4 mModel{1.0f};
    glm::ivec2 mSize{0};
};

}  // namespace viz::render
