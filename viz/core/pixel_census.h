// Counting the pixels no output may silently contain: NaN, +-Inf and negative values. Every command that
// writes an image counts them first and says so (README "Outputs").
#pragma once

#include <cstddef>
#include <string>

#include "core/image.h"

namespace viz {

struct PixelCensus {
    std::size_t pixels = 0;
    std::size_t nan = 0;       // a channel is NaN
    std::size_t inf = 0;       // a channel is +-Inf (and none NaN)
    std::size_t negative = 0;  // a channel is < 0 (and all finite)
    bool clean() const { return nan == 0 && inf == 0 && negative == 0; }
    // "3 NaN, 1 Inf, 12 negative of 76800 pixels", naming only the classes present.
    std::string describe() const;
};

PixelCensus census(const Image& image);

}  // namespace viz
