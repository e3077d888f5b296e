#include "report/error_images.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/error.h"

namespace viz::report {

float exposureFor(const Image& image) {
    std::vector<float> brightest;
    brightest.reserve(std::size_t(image.width) * std::size_t(image.height));
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            float m = 0.0f;
            for (int c = 0; c < std::min(image.channels, 3); ++c)
                if (std::isfinite(image.at(x, y, c))) m = std::max(m, image.at(x, y, c));
            brightest.push_back(m);
        }
    if (brightest.empty()) return 1.0f;
    const std::size_t k = std::min(brightest.size() - 1, std::size_t(0.995 * double(brightest.size())));
    std::nth_element(brightest.begin(), brightest.begin() + std::ptrdiff_t(k), brightest.end());
    return brightest[k] > 0.0f ? 1.0f / brightest[k] : 1.0f;
}

Image heatMap(const Image& scalar, float scale) {
    // Display-space control points of a perceptually ordered ramp, decoded to linear at the end.
    static const float kRamp[5][3] = {{0.0f, 0.0f, 0.0f}, {0.34f, 0.06f, 0.42f}, {0.73f, 0.21f, 0.33f},
                                      {0.98f, 0.55f, 0.04f}, {0.99f, 0.98f, 0.55f}};
    auto decode = [](float s) { return s <= 0.04045f ? s / 12.92f : std::pow((s + 0.055f) / 1.055f, 2.4f); };
    Image out(scalar.width, scalar.height, 3);
    for (int y = 0; y < scalar.height; ++y)
        for (int x = 0; x < scalar.width; ++x) {
            const float v = scalar.at(x, y, 0);
            if (!std::isfinite(v)) {
                out.at(x, y, 0) = 1.0f, out.at(x, y, 1) = 0.0f, out.at(x, y, 2) = 1.0f;
                continue;
            }
            const float t = std::clamp(v * scale, 0.0f, 1.0f) * 4.0f;
            const int i = std::min(int(t), 3);
            const float f = t - float(i);
            for (int c = 0; c < 3; ++c) out.at(x, y, c) = decode(kRamp[i][c] + f * (kRamp[i + 1][c] - kRamp[i][c]));
        }
    return out;
}

Image errorHeatMap(const Image& test, const Image& reference, float scale) {
    VIZ_CHECK(test.width == reference.width && test.height == reference.height && test.channels == reference.channels,
              "errorHeatMap: images differ in size");
    // sum_c |test - reference| per pixel; NaN where the test image is not finite (magenta).
    Image difference(test.width, test.height, 1);
    for (int y = 0; y < test.height; ++y)
        for (int x = 0; x < test.width; ++x) {
            double d = 0.0;
            bool finite = true;
            for (int c = 0; c < test.channels; ++c) {
                const float a = test.at(x, y, c);
                finite &= std::isfinite(a);
                d += std::abs(double(a) - double(reference.at(x, y, c)));
            }
            difference.at(x, y) = finite ? float(d) : std::numeric_limits<float>::quiet_NaN();
        }
    return heatMap(difference, scale);
}

}  // namespace viz::report
