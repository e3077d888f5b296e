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

Image readRgb(const gl::Texture& texture) {
    const Image rgba = gl::readTexture(texture);
    if (rgba.channels == 3) return rgba;
    Image rgb(rgba.width, rgba.height, 3);
    for (int y = 0; y < rgba.height; ++y)
        for (int x = 0; x < rgba.width; ++x)
            for (int c = 0; c < 3; ++c) rgb.at(x, y, c) = c < rgba.channels ? rgba.at(x, y, c) : 0.0f;
    return rgb;
}

bool hasLightOfType(const scene::Scene& scene, scene::LightType type) {
    return std::any_of(scene.lights.begin(), scene.lights.end(),
                       [&](const scene::Light& l) { return l.type == type; });
}

void readBackAirlight(const FrameInput& input, const gl::Texture& airlight, FrameOutput& out) {
    if (input.readBack) out.airlight = readRgb(airlight);
}

}  // namespace viz::render
