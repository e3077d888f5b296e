#include "techniques/vsv/add_airlight.h"

#include <epoxy/gl.h>

#include "core/error.h"

namespace viz::vsv {

void AirlightAdder::add(gl::Texture& target, const FrameOutput& other, const std::string& airlightId) {
    GLuint extra = 0;
    for (const Intermediate& i : other.intermediates)
        if (i.id == airlightId) extra = i.glTexture;
    if (extra == 0) return;
    if (!mProgram) mProgram = gl::Program::compile({.stages = {"vsv/add_airlight.comp"}, .label = "vsv.add_airlight"});
    // The other technique's compute passes wrote its L_air through image stores.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    mProgram.use();
    target.bindImage(0, GL_READ_WRITE);
    glBindTextureUnit(0, extra);
    const glm::ivec3 size = target.size();
    glDispatchCompute(GLuint((size.x + 7) / 8), GLuint((size.y + 7) / 8), 1);
    // Read next by the compose pass (a texture fetch) and by the read-back of L_air.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

}  // namespace viz::vsv
