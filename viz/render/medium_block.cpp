#include "render/medium_block.h"

#include "render/host_device.h"

namespace viz::render {

static_assert(sizeof(hd::GpuMedium) == 16);

void MediumBlock::bind(const scene::Medium& medium) {
    if (!mBuffer) mBuffer = gl::Buffer::create({.bytes = sizeof(hd::GpuMedium), .label = "render.medium"});
    const hd::GpuMedium block{glm::vec4(float(medium.sigma_s), float(medium.sigma_t()), float(medium.g), 0.0f)};
    mBuffer.upload(0, sizeof block, &block);
    mBuffer.bindBase(GL_UNIFORM_BUFFER, hd::kBindingMedium);
}

}  // namespace viz::render
