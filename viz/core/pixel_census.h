// Counting the pixels no output may silently contain: NaN, +-Inf and negative values. Every command that
// writes an image counts them first and says so (README "Outputs").
#pragma once

#include <cstddef>
#include <string>

#include "core/image.h"

namespace viz {

// Pixels with at least one such value among the counted channels; the classes are counted independently
// (-Inf is both Inf and negative). The one count behind the window's view titles, the report's figures
// and the warnings every image writer prints.
struct PixelCensus {
    std::size_t pixels = 0;
    std::size_t nan = 0;       // a channel is NaN
    std::size_t inf = 0;       // a channel is +-Inf
    std::size_t negative = 0;  // a channel is < 0
    bool clean() const { return nan == 0 && inf == 0 && negative == 0; }
    // "3 NaN, 1 Inf, 12 negative of 76800 pixels", naming only the classes present.
    std::string describe() const;
};

// channels: how many leading channels count (0: all of them).
PixelCensus census(const Image& image, int channels = 0);

}  // namespace viz
