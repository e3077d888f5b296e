#include "colour_bar_images.h"

#include <cstring>

namespace airlight {
namespace {

// Uploads `values` as a one-row image (each value in its one channel) when they changed.
void uploadRow(PaneImage& pane, std::vector<float>& uploaded, const std::vector<float>& values, const char* id) {
    const bool same = uploaded.size() == values.size() &&
                      (values.empty() || std::memcmp(uploaded.data(), values.data(), values.size() * sizeof(float)) == 0);
    if (same && pane.texture != 0) return;
    uploaded = values;
    pane.id = id;
    if (values.empty()) {
        pane.texture = 0;
        return;
    }
    viz::Image row(int(values.size()), 1, 1);
    row.pixels = values;
    uploadImage(pane, row);
}

}  // namespace

std::vector<BarImageDraw> barImageDraws(ViewState& v, const ColourBarLayout& layout, const DisplayMapping& mapping) {
    std::vector<BarImageDraw> draws;
    const ColourBar& bar = v.colourBar;
    // Plain values: every channel alike, no channel pick.
    DisplayMapping plain = mapping;
    plain.channel = Channel::Rgb;
    DisplayMapping rampMapping = plain;
    rampMapping.markNegative = false;
    uploadRow(v.barRamp, v.barUploaded, bar.values, "colour_bar");
    if (v.barRamp.texture != 0) draws.push_back({layout.ramp, &v.barRamp, nullptr, rampMapping});
    std::vector<float> swatchValues;
    for (const LegendSwatch& sw : bar.legend) swatchValues.push_back(sw.value);
    uploadRow(v.barSwatches, v.swatchesUploaded, swatchValues, "colour_bar.legend");
    v.barSwatches.sentinels = v.pane.sentinels;
    v.swatchViews.assign(bar.legend.size(), {});
    for (const auto& [rect, index] : layout.swatches) {
        // Texel `index` of the swatch row, shown alone.
        viz::ui::ImageViewTransform& only = v.swatchViews[index];
        only.zoom = double(bar.legend.size());
        only.center = {(double(index) + 0.5) / double(bar.legend.size()), 0.5};
        draws.push_back({rect, &v.barSwatches, &only, plain});
    }
    return draws;
}

}  // namespace airlight
