#include "view_stats.h"

#include "core/pixel_census.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "report/error_metrics.h"

namespace airlight {

const std::vector<std::string>& channelNames() {
    static const std::vector<std::string> names = {"RGB", "R", "G", "B", "A", "luminance"};
    return names;
}

const std::vector<std::string>& differenceModeNames() {
    static const std::vector<std::string> names = {"off", "|a - b|", "a - b", "relative |a - b| / |b|"};
    return names;
}

float shownScalar(const float* texel, int n, Channel channel) {
    if (channel == Channel::Luminance)
        return n < 3 ? texel[0] : kLuminance[0] * texel[0] + kLuminance[1] * texel[1] + kLuminance[2] * texel[2];
    const int c = channel == Channel::Rgb ? 0 : int(channel) - 1;
    return c < n ? texel[c] : std::numeric_limits<float>::quiet_NaN();
}

std::vector<float> channelValues(const viz::Image& image, Channel channel, int meaningful) {
    const int n = std::clamp(meaningful, 1, image.channels > 0 ? image.channels : 1);
    const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
    std::vector<float> out;
    if (image.empty()) return out;
    const std::size_t stride = std::size_t(image.channels);
    if (channel == Channel::Rgb) {
        const int colours = std::min(n, 3);
        out.reserve(pixels * std::size_t(colours));
        for (std::size_t p = 0; p < pixels; ++p)
            for (int c = 0; c < colours; ++c) out.push_back(image.pixels[p * stride + std::size_t(c)]);
    } else if (channel == Channel::Luminance) {
        out.reserve(pixels);
        for (std::size_t p = 0; p < pixels; ++p) out.push_back(shownScalar(&image.pixels[p * stride], n, channel));
    } else {
        const int c = int(channel) - 1;
        if (c >= n) return out;
        out.reserve(pixels);
        for (std::size_t p = 0; p < pixels; ++p) out.push_back(image.pixels[p * stride + std::size_t(c)]);
    }
    return out;
}

SpecialCounts countSpecial(const viz::Image& image, int meaningful, const std::vector<float>& sentinels) {
    SpecialCounts out;
    out.sentinel.assign(sentinels.size(), 0);
    if (sentinels.empty()) {
        const viz::PixelCensus c = viz::census(image, std::max(meaningful, 1));  // -Inf counts as Inf and negative
        out.nan = c.nan, out.inf = c.inf, out.negative = c.negative;
        return out;
    }
    // The census of the image with its sentinel values set to 0, and each sentinel's pixels counted apart.
    viz::Image cleaned = image;
    const int n = std::clamp(meaningful, 1, std::max(image.channels, 1));
    const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
    for (std::size_t p = 0; p < pixels; ++p) {
        unsigned long long holds = 0;  // bit k: sentinel k (the first 64 are counted)
        for (int c = 0; c < n; ++c) {
            float& v = cleaned.pixels[p * std::size_t(image.channels) + std::size_t(c)];
            for (std::size_t k = 0; k < sentinels.size(); ++k)
                if (v == sentinels[k]) holds |= k < 64 ? 1ull << k : 0ull, v = 0.0f;
        }
        for (std::size_t k = 0; k < std::min<std::size_t>(sentinels.size(), 64); ++k) out.sentinel[k] += (holds >> k) & 1u;
    }
    const viz::PixelCensus c = viz::census(cleaned, n);
    out.nan = c.nan, out.inf = c.inf, out.negative = c.negative;
    return out;
}

std::vector<float> withoutSentinels(std::vector<float> values, const std::vector<float>& sentinels) {
    if (sentinels.empty()) return values;
    values.erase(std::remove_if(values.begin(), values.end(),
                                [&](float v) { return std::find(sentinels.begin(), sentinels.end(), v) != sentinels.end(); }),
                 values.end());
    return values;
}

ValueRange finiteRange(const std::vector<float>& values) {
    ValueRange r;
    for (float v : values) {
        if (!std::isfinite(v)) continue;
        if (!r.valid) r.lo = r.hi = v, r.valid = true;
        r.lo = std::min(r.lo, v);
        r.hi = std::max(r.hi, v);
    }
    return r;
}

ValueRange percentileRange(std::vector<float> values, double lower, double upper) {
    values.erase(std::remove_if(values.begin(), values.end(), [](float v) { return !std::isfinite(v); }),
                 values.end());
    ValueRange r;
    if (values.empty()) return r;
    // Nearest rank: the value at index round(q (n - 1)) of the sorted values.
    const auto at = [&](double q) {
        const double clamped = std::clamp(q, 0.0, 1.0);
        const auto k = std::size_t(std::llround(clamped * double(values.size() - 1)));
        std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
        return values[k];
    };
    r.lo = at(lower);
    r.hi = at(upper);
    r.valid = true;
    // A range that collapses to a point maps every other value to one end: a plane that adds light on 2 %
    // of the pixels, or a difference on a few, showed all white. Then the smallest and largest value,
    // and none where the image holds one value (the caller keeps its declared range).
    if (!(r.hi > r.lo)) {
        r = finiteRange(values);
        r.valid = r.hi > r.lo;
    }
    return r;
}

ValueRange logSafeRange(float lo, float hi) {
    ValueRange r{lo, hi, true};
    if (!(r.hi > 0.0f)) return {1e-6f, 1.0f, true};
    if (!(r.lo > 0.0f)) r.lo = r.hi * 1e-6f;
    return r;
}

float mapToUnit(float v, float lo, float hi, bool logarithmic) {
    if (logarithmic) {
        const ValueRange r = logSafeRange(lo, hi);
        const float a = std::log10(r.lo), b = std::log10(r.hi);
        if (!(b > a)) return 0.0f;
        return (std::log10(std::max(v, 1e-30f)) - a) / (b - a);
    }
    if (!(hi > lo)) return 0.0f;
    return (v - lo) / (hi - lo);
}

float signedUnit(float v, float lo, float hi, bool logarithmic) {
    const float top = std::max({std::abs(lo), std::abs(hi), 1e-30f});
    float s = v / top;
    if (logarithmic) s = std::copysign(std::log1p(std::abs(s) * 1e4f) / std::log1p(1e4f), s);
    return std::clamp(s, -1.0f, 1.0f);
}

Histogram histogram(const std::vector<float>& values, float lo, float hi, int bins, bool logarithmic) {
    VIZ_CHECK(bins >= 1, "histogram needs at least one bin");
    Histogram h;
    h.bins.assign(std::size_t(bins), 0);
    h.lo = lo;
    h.hi = hi;
    h.logarithmic = logarithmic;
    for (float v : values) {
        if (!std::isfinite(v)) continue;
        if (logarithmic && v <= 0.0f) {
            ++h.below;
            continue;
        }
        const float t = mapToUnit(v, lo, hi, logarithmic);
        if (t < 0.0f) {
            ++h.below;
        } else if (t > 1.0f) {
            ++h.above;
        } else {
            ++h.bins[std::min(std::size_t(t * float(bins)), std::size_t(bins - 1))];
        }
    }
    return h;
}

viz::Image differenceImage(const viz::Image& test, const viz::Image& other, DifferenceMode mode) {
    VIZ_CHECK(test.width == other.width && test.height == other.height && test.channels == other.channels,
              "differenceImage: images differ in size or channels");
    viz::Image out(test.width, test.height, 1);
    const int channels = std::min(test.channels, 3);
    double magnitude = 0.0;
    for (int y = 0; y < test.height; ++y)
        for (int x = 0; x < test.width; ++x)
            for (int c = 0; c < channels; ++c) magnitude += std::abs(double(other.at(x, y, c)));
    const double pixels = std::max(1.0, double(test.width) * double(test.height));
    const double floor = viz::report::kRelativeFloor * magnitude / pixels;
    for (int y = 0; y < test.height; ++y)
        for (int x = 0; x < test.width; ++x) {
            double d = 0.0, signedSum = 0.0, r = 0.0;
            for (int c = 0; c < channels; ++c) {
                const double a = test.at(x, y, c), b = other.at(x, y, c);
                d += std::abs(a - b);
                signedSum += a - b;
                r += std::abs(b);
            }
            double v = d;
            if (mode == DifferenceMode::Signed) v = signedSum;
            // A black `other` everywhere leaves no scale: the relative figure falls back to the absolute one.
            if (mode == DifferenceMode::Relative) v = std::max(r, floor) > 0.0 ? d / std::max(r, floor) : d;
            out.at(x, y) = float(v);
        }
    return out;
}

}  // namespace airlight
