#include "report/error_metrics.h"

#include "core/pixel_census.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/error.h"

namespace viz::report {

double toneMapScale(const Image& reference) {
    double sum = 0.0;
    for (float v : reference.pixels) sum += std::isfinite(v) ? std::max(0.0, double(v)) : 0.0;
    const double mean = reference.pixels.empty() ? 0.0 : sum / double(reference.pixels.size());
    return mean > 0.0 ? kToneKey / mean : 1.0;
}

void countNonFinite(const Image& image, ErrorMetrics& into) {
    const PixelCensus c = census(image);
    into.pixels = std::size_t(image.width) * std::size_t(image.height);
    into.nanPixels = c.nan;
    into.infPixels = c.inf;
    into.negativePixels = c.negative;
}

ErrorMetrics compareImages(const Image& test, const Image& reference) {
    VIZ_CHECK(test.width == reference.width && test.height == reference.height &&
                  test.channels == reference.channels,
              "compareImages: images differ in size or channels");
    ErrorMetrics m;
    countNonFinite(test, m);
    if (!m.finite() || test.pixels.empty()) {
        m.relativeL2 = m.rmse = m.maxAbsolute = m.relativeP999 = m.psnr = kUndefined;
        return m;
    }
    const double scale = toneMapScale(reference);
    double diff2 = 0.0, ref2 = 0.0, tone2 = 0.0, maxAbs = 0.0, refMagnitude = 0.0;
    for (std::size_t i = 0; i < test.pixels.size(); ++i) {
        const double a = test.pixels[i], b = reference.pixels[i];
        diff2 += (a - b) * (a - b);
        ref2 += b * b;
        maxAbs = std::max(maxAbs, std::abs(a - b));
        refMagnitude += std::abs(b);
        const double t = toneMap(std::max(a, 0.0), scale) - toneMap(std::max(b, 0.0), scale);
        tone2 += t * t;
    }
    const double values = double(test.pixels.size());
    m.relativeL2 = relativeL2FromSums(diff2, ref2);
    m.rmse = std::sqrt(diff2 / values);
    m.maxAbsolute = maxAbs;
    m.psnr = tone2 > 0.0 ? -10.0 * std::log10(tone2 / values) : std::numeric_limits<double>::infinity();

    const double floor = kRelativeFloor * refMagnitude / double(m.pixels);
    std::vector<double> relative;
    relative.reserve(m.pixels);
    for (int y = 0; y < test.height; ++y)
        for (int x = 0; x < test.width; ++x) {
            double d = 0.0, r = 0.0;
            for (int c = 0; c < test.channels; ++c) {
                d += std::abs(double(test.at(x, y, c)) - double(reference.at(x, y, c)));
                r += std::abs(double(reference.at(x, y, c)));
            }
            const double denominator = std::max(r, floor);
            relative.push_back(denominator > 0.0 ? d / denominator : (d == 0.0 ? 0.0 : kUndefined));
        }
    // Nearest-rank percentile.
    const std::size_t rank = std::min(relative.size() - 1, std::size_t(std::ceil(0.999 * double(relative.size()))) - 1);
    std::nth_element(relative.begin(), relative.begin() + std::ptrdiff_t(rank), relative.end(),
                     [](double a, double b) { return a < b || (std::isnan(b) && !std::isnan(a)); });
    m.relativeP999 = relative[rank];
    return m;
}

}  // namespace viz::report
