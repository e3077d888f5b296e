// Sampling of 8-bit sRGB textures (base colour, emission, light cookies) on the CPU, as the reference
// needs it. Conventions: uv in [0,1]^2, v = 0 at the top row (row 0 of Texture::rgba8, glTF's
// convention), clamp to edge; texel (i, j) has its centre at ((i + 0.5) / width, (j + 0.5) / height).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace viz::scene {

// IEC 61966-2-1 decoding of one 8-bit sRGB value to linear [0,1].
inline double srgbToLinearExact(double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

inline float srgbToLinear(std::uint8_t v) {
    static const std::array<float, 256> kTable = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) t[std::size_t(i)] = float(srgbToLinearExact(double(i) / 255.0));
        return t;
    }();
    return kTable[v];
}

// Linear RGB of texel (x, y), indices clamped to the texture (clamp to edge).
inline glm::vec3 texelLinearRgb(const Texture& tex, int x, int y) {
    x = std::clamp(x, 0, tex.width - 1);
    y = std::clamp(y, 0, tex.height - 1);
    const std::size_t i = (std::size_t(y) * std::size_t(tex.width) + std::size_t(x)) * 4;
    return {srgbToLinear(tex.rgba8[i]), srgbToLinear(tex.rgba8[i + 1]), srgbToLinear(tex.rgba8[i + 2])};
}

// Nearest texel to uv.
inline glm::vec3 sampleNearestRgb(const Texture& tex, glm::dvec2 uv) {
    if (tex.width <= 0 || tex.height <= 0) return glm::vec3(1.0f);
    const int x = int(std::floor(std::clamp(uv.x, 0.0, 1.0) * tex.width));
    const int y = int(std::floor(std::clamp(uv.y, 0.0, 1.0) * tex.height));
    return texelLinearRgb(tex, x, y);
}

// Bilinear filter of the sRGB-decoded texels (decode first, then filter, as GL does for SRGB8_ALPHA8).
inline glm::vec3 sampleLinearRgb(const Texture& tex, glm::dvec2 uv) {
    if (tex.width <= 0 || tex.height <= 0) return glm::vec3(1.0f);
    // Texel space with texel centres on integers.
    const double fx = std::clamp(uv.x, 0.0, 1.0) * tex.width - 0.5;
    const double fy = std::clamp(uv.y, 0.0, 1.0) * tex.height - 0.5;
    const double x0 = std::floor(fx), y0 = std::floor(fy);
    const float ax = float(fx - x0), ay = float(fy - y0);
    const int ix = int(x0), iy = int(y0);
    const glm::vec3 top = glm::mix(texelLinearRgb(tex, ix, iy), texelLinearRgb(tex, ix + 1, iy), ax);
    const glm::vec3 bottom = glm::mix(texelLinearRgb(tex, ix, iy + 1), texelLinearRgb(tex, ix + 1, iy + 1), ax);
    return glm::mix(top, bottom, ay);
}

}  // namespace viz::scene
