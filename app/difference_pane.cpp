#include "difference_pane.h"

#include <algorithm>
#include <cmath>

namespace airlight {

PaneImage differencePane(const PaneImage& shown, const viz::Image& diff, DifferenceMode mode, const std::string& against,
                         bool held, const std::string& technique) {
    PaneImage pane;
    pane.id = shown.id;
    pane.label = shown.label + ": " + differenceModeNames()[std::size_t(mode)] + ", b = " + against +
                 (held ? " (held while playing)" : "");
    pane.note = mode == DifferenceMode::Signed
        ? "sum over RGB of (a - b): blue where a is darker, red where brighter"
        : mode == DifferenceMode::Relative
            ? "sum_c |a - b| / max(sum_c |b|, 1% of its mean): the report's per-pixel relative error"
            : "sum over RGB of |a - b|, a = " + technique;
    pane.units = mode == DifferenceMode::Relative ? "" : "radiance";
    pane.kind = mode == DifferenceMode::Signed ? viz::ViewKind::Signed : viz::ViewKind::Scalar;
    pane.mode = mode == DifferenceMode::Signed ? DisplayMode::Signed : DisplayMode::Heat;
    const ValueRange r = percentileRange(diff.pixels, 0.001, 0.999);
    const float top = r.valid ? std::max({std::abs(r.lo), std::abs(r.hi), 1e-12f}) : 1.0f;
    pane.rangeMin = mode == DifferenceMode::Signed ? -top : 0.0f;
    pane.rangeMax = top;
    return pane;
}

}  // namespace airlight
