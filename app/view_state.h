// One cell of the window's view grid: what it shows (the final frame, L_air or an intermediate, which
// layer), its pan and zoom, its display settings, the pane built from the last run, and a CPU copy of
// the pane's values with the statistics the display strip shows (refreshed after each run).
#pragma once

#include <optional>
#include <string>

#include "colour_bar.h"
#include "core/image.h"
#include "pane_image.h"
#include "report/error_metrics.h"
#include "ui/image_view.h"
#include "ui/text_renderer.h"
#include "view_stats.h"

namespace airlight {

struct ViewState {
    std::string content = "airlight";  // "final", "airlight" or an intermediate id
    int index = 0;   // which intermediate of that id (ids repeat: one shadow map per light)
    int layer = 0;   // array layer, cube face or 3D slice
    int shown = -1;  // what the last run gave it, as a views-list index (0 final, 1 L_air, 2.. intermediates)
    viz::ui::ImageViewTransform transform;
    DisplaySettings display;

    PaneImage pane;  // rebuilt after each run

    // CPU copy of the pane's texels (row 0 = the row shown at the top, the pane's channel count up to 4)
    // and what the display strip shows of it; empty until read back.
    viz::Image values;
    int meaningful = 0;  // channels of `values` that carry data
    SpecialCounts counts;
    ValueRange finite;                 // of the chosen channel
    std::optional<ValueRange> measured;  // min/max or percentiles per display.range, when measured
    // A mask's white pixels (countMaskPixels) and the mapping they were counted under, kept between frames;
    // updateStatistics drops them with the values they came from.
    struct MaskMemo {
        float lo = 0.0f, hi = 0.0f;
        Channel channel = Channel::Rgb;
        bool log = false;
        MaskPixels pixels;
    };
    std::optional<MaskMemo> maskMemo;
    Histogram histogram;               // of the chosen channel over `finite`
    // Difference mode: the figures against the other technique, and why there is no difference image.
    std::optional<viz::report::ErrorMetrics> error;
    std::string differenceNote;
    // The content chosen, when this run does not make it and the view shows another in its stead: which
    // and why, for the title's warning ("" while the view shows what was chosen).
    std::string standIn;
    bool titleElided = false, noteElided = false;  // shortened to fit the last frame (sidecar)

    // Its colour bar as last drawn, and the tiny images its ramp and legend swatches are drawn from (the
    // values uploaded last, to upload only on change).
    ColourBar colourBar;
    PaneImage barRamp, barSwatches;
    std::vector<float> barUploaded, swatchesUploaded;
    std::vector<viz::ui::ImageViewTransform> swatchViews;

    // Where the last frame drew it (window pixels).
    viz::ui::Rect cell, title, image, strip, bar, ramp;  // bar: the colour bar, ramp: its colour strip
};

// Reads the pane's texture back into `values` (rows flipped so row 0 is the top row shown) and
// recomputes the statistics. A pane without a texture clears them.
void readBackValues(ViewState& view);
// The suggested range of a pane whose range grows to its data (PaneImage::rangeGrowsToData): the
// declared range of `channel` widened to hold `data` (the window passes the data's 1st to 99th
// percentile, so that a few outlying pixels do not squeeze the rest), symmetric about 0 for a diverging
// channel.
ValueRange grownRange(const PaneImage& pane, Channel channel, const ValueRange& data);
// Recomputes the statistics from `values` for the current display settings (channel, range, log).
void updateStatistics(ViewState& view);
// The value of texel (x, y) (row 0 at the top) from the CPU copy; false when there is none.
bool valueAt(const ViewState& view, glm::ivec2 texel, glm::vec4& out);

}  // namespace airlight
