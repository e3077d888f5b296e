#include "render/intermediates.h"

#include <algorithm>

#include "gl/readback.h"

namespace viz::render {

Intermediate textureIntermediate(const std::string& id, const std::string& label, const std::string& note,
                                 const std::string& units, ViewKind kind, float rangeMin, float rangeMax,
                                 const gl::Texture& texture) {
    Intermediate i;
    i.id = id, i.label = label, i.note = note, i.units = units, i.kind = kind;
    i.rangeMin = rangeMin, i.rangeMax = rangeMax;
    i.glTexture = texture.id();
    i.glTarget = texture.target();
    i.extent = {texture.size().x, texture.size().y, texture.layers()};
    return i;
}

Image readRgb(const gl::Texture& texture) { return gl::readTexture(texture, 0, -1, 3); }

bool hasLightOfType(const scene::Scene& scene, scene::LightType type) {
    return std::any_of(scene.lights.begin(), scene.lights.end(),
                       [&](const scene::Light& l) { return l.type == type; });
}

void readBackAirlight(const FrameInput& input, const gl::Texture& airlight, FrameOutput& out) {
    if (input.readBack) out.airlight = readRgb(airlight);
}

}  // namespace viz::render
