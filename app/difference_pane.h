// The pane a difference view shows in place of its final frame or L_air: named after the view and the
// other side ("Airlight L_air: a - b, b = reference"), its note saying what is subtracted from what, its
// units, kind and colour map (signed: blue-white-red; absolute and relative: a heat map), and a suggested
// range up to the 99.9th percentile of the differences, so that a few outliers do not wash out the map.
// The window uploads the image into it.
#pragma once

#include <string>

#include "core/image.h"
#include "pane_image.h"
#include "view_stats.h"

namespace airlight {

// `shown`: the view's pane before the difference (its id and label); `diff`: differenceImage(a, b, mode);
// `held`: the other side's image is held while the animation plays; `technique`: a's id.
PaneImage differencePane(const PaneImage& shown, const viz::Image& diff, DifferenceMode mode, const std::string& against,
                         bool held, const std::string& technique);

}  // namespace airlight
