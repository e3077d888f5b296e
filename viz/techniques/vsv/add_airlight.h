// vsv and ivsv shade the light types they do not handle with each other (vsv: area lights through
// ivsv; ivsv: point, spot and directional lights through vsv). The other technique's L_air comes back as
// a CPU image and is added to this one's L_air texture here.
#pragma once

#include <vector>

#include "core/image.h"
#include "gl/texture.h"
#include "render/intermediates.h"

namespace viz::vsv {

// target (RGBA32F, GL rows) += extra (RGB, row 0 at the top), through the CPU.
inline void addAirlight(gl::Texture& target, const Image& extra) {
    const Image sum = render::readRgb(target);
    const int w = sum.width, h = sum.height;
    std::vector<float> rgba(std::size_t(w) * std::size_t(h) * 4, 1.0f);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c)
                rgba[(std::size_t(h - 1 - y) * std::size_t(w) + std::size_t(x)) * 4 + std::size_t(c)] =
                    sum.at(x, y, c) + (extra.empty() ? 0.0f : extra.at(x, y, c));
    target.upload(GL_RGBA, GL_FLOAT, rgba.data());
}

}  // namespace viz::vsv
