#include "core/pixel_census.h"

#include <algorithm>
#include <cmath>

namespace viz {

PixelCensus census(const Image& image, int channels) {
    PixelCensus c;
    const std::size_t stride = std::size_t(std::max(image.channels, 1));
    const std::size_t counted = channels > 0 ? std::min(std::size_t(channels), stride) : stride;
    c.pixels = image.pixels.size() / stride;
    for (std::size_t p = 0; p < c.pixels; ++p) {
        bool nan = false, inf = false, negative = false;
        for (std::size_t k = 0; k < counted; ++k) {
            const float v = image.pixels[p * stride + k];
            nan |= std::isnan(v);
            inf |= std::isinf(v);
            negative |= v < 0.0f;
        }
        c.nan += nan;
        c.inf += inf;
        c.negative += negative;
    }
    return c;
}

std::string PixelCensus::describe() const {
    std::string s;
    auto add = [&](std::size_t n, const char* what) {
        if (n == 0) return;
        s += (s.empty() ? "" : ", ") + std::to_string(n) + " " + what;
    };
    add(nan, "NaN");
    add(inf, "Inf");
    add(negative, "negative");
    return (s.empty() ? std::string("no bad") : s) + " of " + std::to_string(pixels) + " pixels";
}

}  // namespace viz
