// Small pieces every GPU technique needs to publish its results: an Intermediate that points at a GL
// texture, an RGB CPU copy of an RGBA texture, and which light types a scene has.
#pragma once

#include <string>

#include "core/image.h"
#include "debug/technique.h"
#include "gl/texture.h"
#include "scene/scene.h"

namespace viz::render {

// An Intermediate for a texture the technique owns (valid until its next run()).
Intermediate textureIntermediate(const std::string& id, const std::string& label, const std::string& note,
                                 const std::string& units, ViewKind kind, float rangeMin, float rangeMax,
                                 const gl::Texture& texture);

// Reads an RGBA float texture back as an RGB image (row 0 at the top): technique outputs are RGB.
Image readRgb(const gl::Texture& texture);
// L_air read back into out.airlight, unless the run's caller reads no CPU images (FrameInput::readBack).
void readBackAirlight(const FrameInput& input, const gl::Texture& airlight, FrameOutput& out);

bool hasLightOfType(const scene::Scene& scene, scene::LightType type);

}  // namespace viz::render
