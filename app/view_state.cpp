#include "view_state.h"

#include <algorithm>
#include <cmath>
#include <exception>

#include "gl/readback.h"

namespace airlight {

namespace {
constexpr int kHistogramBins = 48;
}

void readBackValues(ViewState& view) {
    view.values = {};
    view.meaningful = 0;
    if (view.pane.texture != 0 && view.pane.size.x > 0 && view.pane.size.y > 0) {
        try {
            viz::Image read = viz::gl::readTexture(view.pane.texture);  // GL row 0 (the bottom) last
            if (!view.pane.flipY) {
                // Uploaded CPU images keep row 0 at the top in GL too: undo readTexture's flip.
                viz::Image flipped = read;
                for (int y = 0; y < read.height; ++y)
                    std::copy_n(&read.pixels[read.index(0, read.height - 1 - y)], std::size_t(read.width * read.channels),
                                &flipped.pixels[flipped.index(0, y)]);
                read = std::move(flipped);
            }
            view.values = std::move(read);
            view.meaningful = std::clamp(view.pane.channels, 1, view.values.channels);
        } catch (const std::exception&) {
            view.values = {};  // the strip says there are no values; the image still shows
        }
    }
    updateStatistics(view);
}

ValueRange grownRange(const PaneImage& pane, Channel channel, const ValueRange& data) {
    const viz::ChannelInfo* declared = declaredChannel(pane, channel);
    ValueRange r{declared ? declared->rangeMin : pane.rangeMin, declared ? declared->rangeMax : pane.rangeMax, true};
    if (data.valid) {
        r.lo = std::min(r.lo, data.lo);
        r.hi = std::max(r.hi, data.hi);
    }
    if ((declared ? declared->kind : pane.kind) == viz::ViewKind::Signed) {
        const float m = std::max(std::abs(r.lo), std::abs(r.hi));
        r = {-m, m, true};
    }
    return r;
}

void updateStatistics(ViewState& view) {
    view.counts = {};
    view.finite = {};
    view.measured.reset();
    view.maskMemo.reset();
    view.histogram = {};
    if (view.values.empty()) return;
    std::vector<float> sentinels;
    for (const viz::Sentinel& s : view.pane.sentinels) sentinels.push_back(s.value);
    view.counts = countSpecial(view.values, view.meaningful, sentinels);
    // Vertex positions and signed quantities are negative by nature: only the other kinds report them.
    if (view.pane.kind == viz::ViewKind::Mesh || view.pane.kind == viz::ViewKind::Signed) view.counts.negative = 0;
    const std::vector<float> values =
        withoutSentinels(channelValues(view.values, view.display.channel, view.meaningful), sentinels);
    view.finite = finiteRange(values);
    if (view.display.range == RangeMode::Percentiles) view.measured = percentileRange(values, 0.001, 0.999);
    else if (view.display.range == RangeMode::Suggested && view.pane.rangeFromData)
        view.measured = percentileRange(values, 0.02, 0.98);
    else if (view.display.range == RangeMode::Suggested && view.pane.rangeGrowsToData)
        view.measured = grownRange(view.pane, view.display.channel, percentileRange(values, 0.01, 0.99));
    else view.measured = view.finite;
    ValueRange axis = view.finite;
    if (view.display.logScale) axis = logSafeRange(axis.lo, axis.hi);
    if (axis.valid) view.histogram = histogram(values, axis.lo, axis.hi, kHistogramBins, view.display.logScale);
}

bool valueAt(const ViewState& view, glm::ivec2 texel, glm::vec4& out) {
    const viz::Image& v = view.values;
    if (v.empty() || texel.x < 0 || texel.y < 0 || texel.x >= v.width || texel.y >= v.height) return false;
    out = glm::vec4(0.0f);
    for (int c = 0; c < std::min(v.channels, 4); ++c) out[c] = v.at(texel.x, texel.y, c);
    return true;
}

}  // namespace airlight
