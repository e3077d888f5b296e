// The medium's uniform block (shaders/common/medium.glsl): every pass that reads sigma_s, sigma_t or g
// binds it through this one helper instead of setting three uniforms.
#pragma once

#include "gl/buffer.h"
#include "scene/scene.h"

namespace viz::render {

class MediumBlock {
public:
    // Uploads the medium as a GpuMedium (sigma_s, sigma_t, g as floats, the precision the shaders compute
    // in) and binds it at hd::kBindingMedium for the draws and dispatches that follow.
    void bind(const scene::Medium& medium);

private:
    gl::Buffer mBuffer;
};

}  // namespace viz::render
