#include "render/mesh_view.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "render/eye_space.h"
#include "scene/camera.h"

namespace viz::render {

namespace {

constexpr double kOrbitFov = 0.8;  // radians, vertical

// The box holding the scene's bounds and the main camera's eye (world space).
scene::Bounds withCamera(const scene::Bounds& bounds, const glm::dvec3& eye) {
    return {glm::min(bounds.lo, eye), glm::max(bounds.hi, eye), false};
}

// The box's radius, which sizes the orbit camera and the markers; a box of one point (a scene whose
// meshes and camera coincide) takes a millionth of its distance from the origin instead. No absolute floor:
// a model a micrometre across is framed as one a kilometre across.
double viewRadius(const scene::Bounds& box) {
    const double r = box.radius();
    return r > 0.0 ? r : std::max(1e-6 * glm::length(box.centre()), 1e-30);
}

void cross(std::vector<glm::vec3>& out, glm::dvec3 p, const glm::dvec3& eye, double size) {
    for (int axis = 0; axis < 3; ++axis) {
        glm::dvec3 d(0.0);
        d[axis] = size;
        out.push_back(toEyeRelative(p - d, eye));
        out.push_back(toEyeRelative(p + d, eye));
    }
}

}  // namespace

glm::mat4 orbitViewProjection(const scene::Scene& scene, const scene::Bounds& bounds, const OrbitView& orbit, int width,
                              int height) {
    const scene::Bounds box = withCamera(bounds, scene.camera.position);
    const glm::dvec3 target = box.centre() - scene.camera.position;  // eye-relative
    const double radius = viewRadius(box);
    const double distance = radius / std::sin(0.5 * kOrbitFov) / std::max(orbit.zoom, 1e-3);
    const double yaw = glm::radians(orbit.yawDegrees);
    const double pitch = glm::radians(std::clamp(orbit.pitchDegrees, -89.0, 89.0));
    const glm::dvec3 offset{std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw)};
    const glm::dvec3 eye = target + distance * offset;
    const glm::dmat4 view = glm::lookAt(eye, target, glm::dvec3(0.0, 1.0, 0.0));
    const double aspect = double(std::max(width, 1)) / double(std::max(height, 1));
    const double nearPlane = std::max(distance - 2.0 * radius, 1e-4 * distance);
    const glm::dmat4 projection = glm::perspective(kOrbitFov, aspect, nearPlane, distance + 2.0 * radius);
    return glm::mat4(projection * view);
}

std::vector<glm::vec3> cameraFrustumLines(const scene::Camera& camera, int width, int height, double depth) {
    const glm::dvec3 right = scene::cameraRight(camera);
    const double ty = std::tan(0.5 * camera.yfov), tx = ty * scene::aspectOf(camera, width, height);
    glm::dvec3 corners[4];
    for (int i = 0; i < 4; ++i) {
        const double sx = (i == 1 || i == 2) ? 1.0 : -1.0, sy = i >= 2 ? 1.0 : -1.0;
        corners[i] = depth * (camera.forward + sx * tx * right + sy * ty * camera.up);
    }
    std::vector<glm::vec3> lines;
    for (int i = 0; i < 4; ++i) {
        lines.push_back(glm::vec3(0.0f));
        lines.push_back(glm::vec3(corners[i]));
        lines.push_back(glm::vec3(corners[i]));
        lines.push_back(glm::vec3(corners[(i + 1) % 4]));
    }
    return lines;
}

std::vector<glm::vec3> lightMarkerLines(const scene::Scene& scene, glm::dvec3 center, double size) {
    const glm::dvec3& eye = scene.camera.position;
    std::vector<glm::vec3> lines;
    for (const scene::Light& l : scene.lights) {
        const bool directional = l.type == scene::LightType::Directional;
        const glm::dvec3 at = directional ? center : l.position;
        if (!directional) cross(lines, at, eye, size);
        if (l.type != scene::LightType::Point) {
            const glm::dvec3 dir = glm::normalize(l.direction);
            lines.push_back(toEyeRelative(at, eye));
            lines.push_back(toEyeRelative(at + 4.0 * size * dir, eye));
        }
    }
    return lines;
}

void MeshView::begin(const scene::Scene& scene, const GpuScene& gpuScene, const OrbitView& orbit, int width,
                     int height) {
    if (!mColour || mSize != glm::ivec2(width, height)) {
        mColour = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_RGBA8, .size = {width, height, 1},
                                      .levels = 1, .label = "mesh_view.colour"});
        mDepth = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_DEPTH_COMPONENT32F,
                                      .size = {width, height, 1}, .levels = 1, .label = "mesh_view.depth"});
        mFramebuffer = gl::Framebuffer::create("mesh_view.fbo");
        mFramebuffer.attachColour(0, mColour);
        mFramebuffer.attachDepth(mDepth);
        mFramebuffer.checkComplete();
        mSize = {width, height};
    }
    if (!mSurfaces) {
        mSurfaces = gl::Program::compile({.stages = {"render/scene.vert", "render/mesh_view.frag"},
                                          .label = "mesh_view.surfaces"});
        mLines = gl::Program::compile({.stages = {"render/mesh_view_lines.vert", "render/mesh_view.frag"},
                                       .label = "mesh_view.lines"});
        mLineArray = gl::VertexArray::create("mesh_view.lines");
    }
    mViewProj = orbitViewProjection(scene, gpuScene.bounds(), orbit, width, height);
    mModel = eyeRelativeModel(scene.camera.position);
    bindTarget();
    glClearColor(0.06f, 0.06f, 0.07f, 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    // The scene's surfaces, flat and dim: enough to place the meshes, not to hide them.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    mSurfaces.use();
    mSurfaces.set("uModel", mModel);
    mSurfaces.set("uViewProj", mViewProj);
    mSurfaces.set("uColour", glm::vec4(0.32f, 0.32f, 0.35f, 1.0f));
    mSurfaces.set("uShade", 1);
    gpuScene.draw();
    // Markers on top of the surfaces where they are hidden: drawn without depth test by lines().
    const scene::Bounds box = withCamera(gpuScene.bounds(), scene.camera.position);
    const double size = 0.03 * viewRadius(box);
    lines(cameraFrustumLines(scene.camera, width, height, 0.25 * viewRadius(box)),
          glm::vec4(0.35f, 0.65f, 1.0f, 1.0f));
    lines(lightMarkerLines(scene, box.centre(), size), glm::vec4(1.0f, 0.85f, 0.3f, 1.0f));
}

void MeshView::bindTarget() const {
    mFramebuffer.bind();
    glViewport(0, 0, mSize.x, mSize.y);
}

void MeshView::lines(const std::vector<glm::vec3>& segments, glm::vec4 colour) {
    if (segments.empty()) return;
    const std::size_t bytes = segments.size() * sizeof(glm::vec3);
    if (bytes > mLineCapacity) {
        mLineCapacity = std::max<std::size_t>(bytes, 4096);
        mLineBuffer = gl::Buffer::create({.bytes = mLineCapacity, .label = "mesh_view.line_vertices"});
        mLineArray.vertexBuffer(0, mLineBuffer, 0, int(sizeof(glm::vec3)));
        mLineArray.attribute(0, 0, 3, GL_FLOAT, 0);
    }
    mLineBuffer.upload(0, bytes, segments.data());
    bindTarget();
    glDisable(GL_DEPTH_TEST);
    mLines.use();
    mLines.set("uViewProj", mViewProj);
    mLines.set("uColour", colour);
    mLines.set("uShade", 0);
    mLineArray.bind();
    glDrawArrays(GL_LINES, 0, GLsizei(segments.size()));
    glEnable(GL_DEPTH_TEST);
}

}  // namespace viz::render
