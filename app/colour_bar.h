// What a view's colours mean: the colour bar under each image view (and in handouts). It is computed from
// the view's pane and display mapping only, with no GL: the window draws its ramp and swatches as tiny
// images through the view's own shader (shaders/ui/image.frag), so the bar cannot disagree with the
// picture, and the screenshot sidecar lists its ticks for tests.
//
//   Ramp     a continuous map (grey, ramp, heat, diverging, or an HDR image's exposure): values from lo
//            to hi, ticks in the intermediate's units (decades on a log scale)
//   Classes  a discrete map (bits, categorical, mask): one swatch per class with its value
//   Picture  a picture the technique draws (a chart, an orbit view): no map; the caption points to the
//            view's note, which says what its colours mean
// Every bar also carries the legend: each declared sentinel value with its meaning and count, then the
// NaN, Inf and (when marked) negative overlays with their pixel counts.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "pane_image.h"
#include "view_stats.h"

namespace airlight {

struct LegendSwatch {
    std::string label;      // "NaN", "-1: outside the spot's cone"
    float value = 0.0f;     // the value drawn in the swatch (through the view's mapping and sentinels)
    std::size_t pixels = 0; // how many of the view's pixels it marks
    bool sentinel = false;
};

struct ColourBar {
    enum class Kind { None, Ramp, Classes, Picture };
    Kind kind = Kind::None;
    // Ramp: values from left to right in data units (kRampTexels of them), drawn one texel each, RGB equal
    // (an HDR image's greys). Classes: one value per class.
    std::vector<float> values;
    std::vector<std::string> classLabels;  // Classes: one per value
    double lo = 0.0, hi = 1.0;             // Ramp: the values at the two ends
    bool logarithmic = false;
    // Ramp ticks: value, its label and where it sits along the bar (0 left, 1 right); every tick lies
    // inside [lo, hi].
    std::vector<double> ticks;
    std::vector<std::string> tickLabels;
    std::vector<float> tickAt;
    std::string units;    // of the quantity shown (a declared channel's own)
    std::string caption;  // e.g. "exposure +1.3 EV: white at 0.41", "each value its own colour, 0 black"
    std::string shortCaption;  // where `caption` does not fit: a shorter form (empty: `caption` elided)
    std::vector<LegendSwatch> legend;
};

inline constexpr int kRampTexels = 128;

// `v` with `digits` significant digits (%g), as the bar and its captions print numbers.
std::string shortNumber(double v, int digits = 3);

// `counts`: the view's NaN / Inf / negative / sentinel pixel counts (view_stats.h).
ColourBar colourBarFor(const PaneImage& pane, const DisplayMapping& mapping, const SpecialCounts& counts);

// A mask's white pixels, counted from the view's values (first `meaningful` channels) as the shader classes
// them: the shown channel above the middle of the range; NaN, Inf and sentinel pixels, drawn as overlays,
// are not counted. Nothing (nullopt) for another mode or without values.
struct MaskPixels {
    std::size_t white = 0, counted = 0;
};
std::optional<MaskPixels> countMaskPixels(const DisplayMapping& mapping, const viz::Image& values, int meaningful,
                                          const std::vector<viz::Sentinel>& sentinels);
// A mask's bar says how many pixels are white ("...: 0 of 76800 pixels"), so that an all-black mask does not
// leave the reader to wonder whether it was drawn. For a count countMaskPixels made under the bar's mapping.
void describeMaskPixels(ColourBar& bar, const MaskPixels& pixels);

}  // namespace airlight
