// Reading epipolar grids (RGBA32UI 2D arrays, 128 phi bits per texel) back for the debugger: one theta
// row of one grid tile, an alpha x phi slice, and CPU-image intermediates. Needs a current GL context.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/image.h"
#include "debug/technique.h"
#include "gl/texture.h"
#include "techniques/vsv/bits128.h"

namespace viz::vsv {

// Texels (x0 .. x0 + width) of row y of every layer; index layer * width + x.
inline std::vector<Bits128> readGridRow(const gl::Texture& grid, int x0, int width, int y) {
    const int layers = grid.size().z;
    std::vector<Bits128> texels(std::size_t(width) * std::size_t(layers));
    glGetTextureSubImage(grid.id(), 0, x0, y, 0, width, 1, layers, GL_RGBA_INTEGER, GL_UNSIGNED_INT,
                         GLsizei(texels.size() * sizeof(Bits128)), texels.data());
    return texels;
}

// alpha (x) x phi (y) slice at row y of the grid tile starting at x0: 1 = shadowed voxel. Row 0 of the
// image (its top) is phi cell 0, next to the eye.
inline std::shared_ptr<Image> sliceImage(const gl::Texture& grid, int x0, int nAlpha, int y, int nPhi) {
    const std::vector<Bits128> texels = readGridRow(grid, x0, nAlpha, y);
    auto image = std::make_shared<Image>(nAlpha, nPhi, 1);
    for (int k = 0; k < nPhi; ++k)
        for (int a = 0; a < nAlpha; ++a)
            image->at(a, k) = testBitPlain(texels[std::size_t((k >> 7) * nAlpha + a)], k & 127) ? 1.0f : 0.0f;
    return image;
}

}  // namespace viz::vsv
