#include "render/compose.h"

#include "core/error.h"

namespace viz::render {

FullscreenTriangle::FullscreenTriangle() : mVao(gl::VertexArray::create("render.fullscreen_vao")) {}

void FullscreenTriangle::draw() const {
    mVao.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

Composer::Composer()
    : mProgram(gl::Program::compile({.stages = {"render/fullscreen.vert", "render/compose.frag"},
                                     .label = "render.compose_program"})),
      mFramebuffer(gl::Framebuffer::create("render.compose_fbo")) {}

void Composer::run(const gl::Texture& surfaceRadiance, const gl::Texture& distance, const gl::Texture& airlight,
                   const scene::Medium& medium, const gl::Texture& out) {
    const glm::ivec2 size(out.size());
    VIZ_CHECK(glm::ivec2(surfaceRadiance.size()) == size && glm::ivec2(distance.size()) == size &&
                  glm::ivec2(airlight.size()) == size,
              "composeFinal: inputs and output must have the same size");
    mFramebuffer.attachColour(0, out);
    mFramebuffer.checkComplete();
    mFramebuffer.bind();
    glViewport(0, 0, size.x, size.y);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    surfaceRadiance.bindUnit(0);
    distance.bindUnit(1);
    airlight.bindUnit(2);
    mProgram.use();
    mMedium.bind(medium);
    mTriangle.draw();
    gl::Framebuffer::bindDefault();
}

void composeFinal(const gl::Texture& surfaceRadiance, const gl::Texture& distance, const gl::Texture& airlight,
                  const scene::Medium& medium, const gl::Texture& out) {
    Composer composer;
    composer.run(surfaceRadiance, distance, airlight, medium, out);
}

}  // namespace viz::render
