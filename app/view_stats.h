// Numbers behind a view's display controls, computed on the CPU from a readback of the view's image:
// the values of the chosen channel, their finite range (min/max or percentiles), a histogram, the
// counts of NaN, Inf and negative pixels, the mapping to [0, 1] the shader applies (linear or log), and
// the difference of two images shown by a view in difference mode. Pure functions, no GL.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/image.h"

namespace airlight {

// Mirrored by uChannel in shaders/ui/image.frag.
enum class Channel : int { Rgb = 0, R = 1, G = 2, B = 3, A = 4, Luminance = 5 };
const std::vector<std::string>& channelNames();  // "RGB", "R", ..., index = Channel

// Rec. 709 luminance weights, the ones the shader uses.
inline constexpr float kLuminance[3] = {0.2126f, 0.7152f, 0.0722f};

// The values the view shows of `image` for `channel`, considering only its first `meaningful` channels
// (a GL texture read back as RGBA may hold fewer): Rgb gives every meaningful colour channel (at most
// 3) of every pixel; R, G, B, A one value per pixel (none when the image lacks that channel); Luminance
// one value per pixel (a single-channel image gives its value). NaN and Inf are kept.
std::vector<float> channelValues(const viz::Image& image, Channel channel, int meaningful);
// The one value the image shader maps for a texel of `n` meaningful channels: r for Rgb (a one-channel
// image's value), the chosen channel, or the luminance (r when n < 3). NaN when the texel lacks the channel.
float shownScalar(const float* texel, int n, Channel channel);

// Pixels with at least one NaN / Inf / negative value among their first `meaningful` channels.
// Values equal to one of `sentinels` (a pane's "nothing here" values) are not counted as negative; each
// sentinel's own count is the pixels holding it in one of those channels.
struct SpecialCounts {
    std::size_t nan = 0, inf = 0, negative = 0;
    std::vector<std::size_t> sentinel;  // one per sentinel value, in the order given
};
SpecialCounts countSpecial(const viz::Image& image, int meaningful, const std::vector<float>& sentinels = {});
// `values` without the sentinel values (the range, the percentiles and the histogram leave them out).
std::vector<float> withoutSentinels(std::vector<float> values, const std::vector<float>& sentinels);

struct ValueRange {
    float lo = 0.0f, hi = 1.0f;
    bool valid = false;  // false: no finite value
};
// Smallest and largest finite value.
ValueRange finiteRange(const std::vector<float>& values);
// The `lower` and `upper` quantiles (in [0, 1]) of the finite values, nearest rank. Where they are equal
// (most values the same), the smallest and largest value; not valid where every value is the same.
ValueRange percentileRange(std::vector<float> values, double lower, double upper);

// The range the shader maps from on a log scale: [lo, hi] with a non-positive lo replaced by hi * 1e-6
// (and hi <= 0 by [1e-6, 1]), so that log10 is defined at both ends.
ValueRange logSafeRange(float lo, float hi);
// Where the shader puts v in [0, 1] for the range [lo, hi], linear or log10 (through logSafeRange);
// not clamped; a degenerate range maps everything to 0.
float mapToUnit(float v, float lo, float hi, bool logarithmic);
// Where the diverging map puts a signed v for the range [lo, hi], in [-1, 1] (0 white, -1 full blue, 1 full
// red): v / max(|lo|, |hi|), or on a log scale the symmetric log sign(v) log(1 + |v| / l) / log(1 + top / l)
// with l = 1e-4 top, which spreads the four decades below the top evenly and keeps 0 at 0.
float signedUnit(float v, float lo, float hi, bool logarithmic);

// Counts of finite values in `bins` equal bins over [lo, hi] (log10-spaced when `logarithmic`); values
// outside are counted in `below` / `above` (non-positive values are below a log histogram).
struct Histogram {
    std::vector<std::size_t> bins;
    std::size_t below = 0, above = 0;
    float lo = 0.0f, hi = 1.0f;
    bool logarithmic = false;
};
Histogram histogram(const std::vector<float>& values, float lo, float hi, int bins, bool logarithmic);

// The difference a view shows between `test` and `other` (same size; colour channels summed):
//   Absolute: sum_c |test - other|;  Signed: sum_c (test - other);
//   Relative: sum_c |test - other| / max(sum_c |other|, kRelativeFloor * mean over pixels of sum_c |other|)
// (the per-pixel relative error of viz/report/error_metrics.h). One channel.
enum class DifferenceMode : int { Off = 0, Absolute = 1, Signed = 2, Relative = 3 };
const std::vector<std::string>& differenceModeNames();  // index = DifferenceMode
viz::Image differenceImage(const viz::Image& test, const viz::Image& other, DifferenceMode mode);

}  // namespace airlight
