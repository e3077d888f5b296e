#include "render/surface_pass.h"

#include "core/error.h"
#include "render/eye_space.h"

namespace viz::render {

SurfacePass::SurfacePass()
    : mProgram(gl::Program::compile({.stages = {"render/scene.vert", "render/surface.frag"},
                                     .label = "render.surface_program"})),
      mDepthProgram(gl::Program::compile({.stages = {"render/scene.vert", "render/surface_depth.frag"},
                                          .label = "render.surface_depth_program"})),
      mFramebuffer(gl::Framebuffer::create("render.surface_fbo")) {}

void SurfacePass::run(const GpuScene& gpuScene, const GpuLights& lights, const ShadowMaps& shadows,
                      const scene::Scene& scene, int width, int height) {
    VIZ_CHECK(width > 0 && height > 0, "surface pass needs a non-empty image");
    if (width != mWidth || height != mHeight || !mDistance) {
        mDistance = gl::Texture::create({.format = GL_R32F, .size = {width, height, 1}, .label = "render.distance"});
        mRadiance = gl::Texture::create(
            {.format = GL_RGBA32F, .size = {width, height, 1}, .label = "render.surface_radiance"});
        mDepth = gl::Texture::create(
            {.format = GL_DEPTH32F_STENCIL8, .size = {width, height, 1}, .label = "render.depth"});
        for (auto* t : {&mDistance, &mRadiance}) t->setFilter(GL_NEAREST, GL_NEAREST);
        mFramebuffer = gl::Framebuffer::create("render.surface_fbo");
        mFramebuffer.attachColour(0, mDistance);
        mFramebuffer.attachColour(1, mRadiance);
        mFramebuffer.attachDepth(mDepth);
        mFramebuffer.checkComplete();
        mWidth = width;
        mHeight = height;
    }
    const scene::Camera& camera = scene.camera;
    // The eye of the lights' eye-relative space must be the camera, or positions would disagree.
    VIZ_CHECK(lights.eye() == camera.position, "GpuLights were built for another eye position");
    VIZ_CHECK(shadows.size() > 0, "ShadowMaps::build() must run before the surface pass");

    const glm::mat4 model = eyeRelativeModel(camera.position);
    const glm::mat4 viewProj = eyeRelativeViewProjection(camera, width, height);
    mFramebuffer.bind();
    glViewport(0, 0, width, height);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    // Sky: distance zfar, radiance 0.
    const float sky[4] = {float(camera.zfar), 0.0f, 0.0f, 0.0f};
    const float black[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearNamedFramebufferfv(mFramebuffer.id(), GL_COLOR, 0, sky);
    glClearNamedFramebufferfv(mFramebuffer.id(), GL_COLOR, 1, black);
    glClearNamedFramebufferfi(mFramebuffer.id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);

    // 1. Depth alone: the nearest surface within zfar at each pixel. The scene's triangles overlap two
    //    deep and more (colonnade, forest: twice as many fragments as pixels), and each fragment the
    //    shading pass runs looks every light's shadow map up.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    mDepthProgram.use();
    mDepthProgram.set("uModel", model);
    mDepthProgram.set("uViewProj", viewProj);
    mDepthProgram.set("uZfar", float(camera.zfar));
    gpuScene.draw();
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

    // 2. Shading, tested before the shader: the fragments at that depth, and of those only the first
    //    drawn (the stencil), which is the fragment a single pass with GL_LESS kept.
    lights.bind();
    shadows.bind();
    gpuScene.bindMaterials();
    mProgram.use();
    mProgram.set("uModel", model);
    mProgram.set("uViewProj", viewProj);
    mProgram.set("uZfar", float(camera.zfar));
    mMedium.bind(scene.medium);
    mProgram.set("uLightCount", lights.count());
    glDepthFunc(GL_EQUAL);
    glDepthMask(GL_FALSE);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, 0, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    gpuScene.draw();
    glDisable(GL_STENCIL_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    gl::Framebuffer::bindDefault();
}

}  // namespace viz::render
