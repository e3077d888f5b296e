#include "techniques/reference/linear_texture.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "scene/texture_sampling.h"

namespace viz::reference {

// ---- textures ----

LinearTexture::LinearTexture(const scene::Texture& texture) : mWidth(texture.width), mHeight(texture.height) {
    VIZ_CHECK(texture.rgba8.size() == std::size_t(mWidth) * std::size_t(mHeight) * 4u,
              "texture '" + texture.name + "' has the wrong byte count");
    // Decode once: 256-entry table.
    double table[256];
    for (int i = 0; i < 256; ++i) table[i] = scene::srgbToLinearExact(i / 255.0);
    mTexels.resize(std::size_t(mWidth) * std::size_t(mHeight));
    for (std::size_t i = 0; i < mTexels.size(); ++i) {
        mTexels[i] = glm::dvec3(table[texture.rgba8[4 * i + 0]], table[texture.rgba8[4 * i + 1]],
                                table[texture.rgba8[4 * i + 2]]);
    }
}

glm::dvec3 LinearTexture::sample(glm::dvec2 uv) const {
    if (mWidth == 0) return glm::dvec3(1.0);
    // Texel space: texel (i, j) has its centre at (i + 0.5, j + 0.5); uv outside [0,1] clamps.
    const double fx = std::clamp(uv.x, 0.0, 1.0) * mWidth - 0.5;
    const double fy = std::clamp(uv.y, 0.0, 1.0) * mHeight - 0.5;
    const double x0f = std::floor(fx), y0f = std::floor(fy);
    const double ax = fx - x0f, ay = fy - y0f;
    const int x0 = std::clamp(int(x0f), 0, mWidth - 1), x1 = std::clamp(int(x0f) + 1, 0, mWidth - 1);
    const int y0 = std::clamp(int(y0f), 0, mHeight - 1), y1 = std::clamp(int(y0f) + 1, 0, mHeight - 1);
    const glm::dvec3 top = (1.0 - ax) * texel(x0, y0) + ax * texel(x1, y0);
    const glm::dvec3 bottom = (1.0 - ax) * texel(x0, y1) + ax * texel(x1, y1);
    return (1.0 - ay) * top + ay * bottom;
}

}  // namespace viz::reference
