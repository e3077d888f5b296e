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

// Integral over [a, b] (texel-centre coordinates, a <= b) of texel i's share of the linear
// interpolation along one axis of n texels, clamp to edge: the tent max(0, 1 - |x - i|), whose outer
// half is 1 for the first texel (x <= 0) and for the last (x >= n - 1).
inline double texelShare(int i, int n, double a, double b) {
    // Antiderivative of the tent about 0: 0 below -1, 1 above 1.
    const auto tent = [](double x) {
        if (x <= -1.0) return 0.0;
        if (x <= 0.0) return 0.5 * (x + 1.0) * (x + 1.0);
        if (x <= 1.0) return 1.0 - 0.5 * (1.0 - x) * (1.0 - x);
        return 1.0;
    };
    const double lo = a - i, hi = b - i;
    double share = tent(hi) - tent(lo);
    // The first texel's outer half is 1 below 0, the last one's above n - 1 (in place of the tent's).
    if (i == 0) share += std::max(0.0, std::min(hi, 0.0) - lo) - (tent(std::min(hi, 0.0)) - tent(std::min(lo, 0.0)));
    if (i == n - 1)
        share += std::max(0.0, hi - std::max(lo, 0.0)) - (tent(std::max(hi, 0.0)) - tent(std::max(lo, 0.0)));
    return share;
}

// Mean of sampleLinearRgb over the uv rectangle [uv0, uv1] (uv0 <= uv1 componentwise, inside [0,1]^2),
// exactly: the bilinear interpolant is separable, so each texel weighs the product of its two axes'
// shares. An emitter's cell thus carries the colour of its whole area, not of one point in it. A
// rectangle wider or taller than kMaxExactTexels texels (a large emission texture: every VPL set is laid
// out again when the camera moves) takes the mean of a kMaxExactTexels^2 midpoint grid of the filter
// instead, so that the cost per rectangle stays bounded.
inline constexpr int kMaxExactTexels = 128;

inline glm::dvec3 averageLinearRgb(const Texture& tex, glm::dvec2 uv0, glm::dvec2 uv1) {
    if (tex.width <= 0 || tex.height <= 0) return glm::dvec3(1.0);
    uv0 = glm::clamp(uv0, glm::dvec2(0.0), glm::dvec2(1.0));
    uv1 = glm::clamp(uv1, uv0, glm::dvec2(1.0));
    if (uv1.x - uv0.x <= 0.0 || uv1.y - uv0.y <= 0.0)
        return glm::dvec3(sampleLinearRgb(tex, 0.5 * (uv0 + uv1)));
    const double ax = uv0.x * tex.width - 0.5, bx = uv1.x * tex.width - 0.5;
    const double ay = uv0.y * tex.height - 0.5, by = uv1.y * tex.height - 0.5;
    // Texels whose share can be non-zero: those within one texel of the interval.
    const int x0 = std::max(0, int(std::floor(ax))), x1 = std::min(tex.width - 1, int(std::ceil(bx)));
    const int y0 = std::max(0, int(std::floor(ay))), y1 = std::min(tex.height - 1, int(std::ceil(by)));
    glm::dvec3 sum(0.0);
    if (x1 - x0 >= kMaxExactTexels || y1 - y0 >= kMaxExactTexels) {
        const int n = kMaxExactTexels;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                sum += glm::dvec3(sampleLinearRgb(tex, glm::mix(uv0, uv1, glm::dvec2((i + 0.5) / n, (j + 0.5) / n))));
        return sum / double(n * n);
    }
    std::array<double, kMaxExactTexels + 1> wx{};
    for (int x = x0; x <= x1; ++x) wx[std::size_t(x - x0)] = texelShare(x, tex.width, ax, bx);
    for (int y = y0; y <= y1; ++y) {
        const double wy = texelShare(y, tex.height, ay, by);
        if (wy == 0.0) continue;
        for (int x = x0; x <= x1; ++x) {
            const double w = wx[std::size_t(x - x0)];
            if (w != 0.0) sum += w * wy * glm::dvec3(texelLinearRgb(tex, x, y));
        }
    }
    return sum / ((bx - ax) * (by - ay));
}

}  // namespace viz::scene
