// A CPU image of 32-bit floats, row-major, row 0 at the top (the convention of every image we write).
#pragma once

#include <cstddef>
#include <vector>

namespace viz {

struct Image {
    int width = 0;
    int height = 0;
    int channels = 0;
    std::vector<float> pixels;  // width * height * channels, interleaved

    Image() = default;
    Image(int w, int h, int c) : width(w), height(h), channels(c),
        pixels(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * static_cast<std::size_t>(c), 0.0f) {}

    std::size_t index(int x, int y, int c = 0) const {
        return (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) *
                   static_cast<std::size_t>(channels) + static_cast<std::size_t>(c);
    }
    float& at(int x, int y, int c = 0) { return pixels[index(x, y, c)]; }
    float at(int x, int y, int c = 0) const { return pixels[index(x, y, c)]; }
    bool empty() const { return pixels.empty(); }
};

}  // namespace viz
