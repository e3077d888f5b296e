// vsv and ivsv shade the light types they do not handle with each other (vsv: area lights through
// ivsv; ivsv: point, spot and directional lights through vsv). The other technique's L_air texture is
// added to this one's on the GPU (shaders/vsv/add_airlight.comp): no read-back, no upload.
#pragma once

#include <string>

#include "debug/technique.h"
#include "gl/program.h"
#include "gl/texture.h"

namespace viz::vsv {

class AirlightAdder {
public:
    // target (RGBA32F) += the L_air texture `airlightId` that `other` (the other technique's output of the
    // same size) publishes. A run that published no such texture adds nothing.
    void add(gl::Texture& target, const FrameOutput& other, const std::string& airlightId);

private:
    gl::Program mProgram;
};

}  // namespace viz::vsv
