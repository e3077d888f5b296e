// The crack detector's verdict (polyvol, crack_check=1). Along a full ray from the eye, a closed
// watertight surface is left once more than it is entered when the eye is inside it and as often as it
// is entered otherwise, so the signed crossing count (+1 per leaving, -1 per entering fragment) of every
// pixel equals the number of light volumes that contain the eye. A hole lets a ray through without its
// crossing, a T-junction leaves a sliver with no or a doubled fragment: either changes that pixel's count
// by one. The count is an exact small integer in fp32, and it does not depend on the surface distance d
// (crossings beyond d are clamped, not dropped), so the test has no tolerance.
#pragma once

#include <cmath>
#include <map>

#include "core/image.h"

namespace viz::polyvol {

struct CrackReport {
    int badPixels = 0;
    int expected = 0;  // volumes containing the eye
};

// signedCount: channel `channel` of each pixel holds the signed crossing count. The number of volumes
// containing the eye is the same for every pixel; it is taken as the most frequent rounded count (cracks
// touch few pixels), and every pixel whose count differs from it, or is not an integer, is bad.
inline CrackReport countCrackPixels(const Image& signedCount, int channel) {
    std::map<long, int> histogram;
    for (int y = 0; y < signedCount.height; ++y)
        for (int x = 0; x < signedCount.width; ++x) ++histogram[std::lround(signedCount.at(x, y, channel))];
    CrackReport r;
    int best = -1;
    for (const auto& [value, n] : histogram)
        if (n > best) best = n, r.expected = int(value);
    const int volumesContainingEye = r.expected;
    for (int y = 0; y < signedCount.height; ++y)
        for (int x = 0; x < signedCount.width; ++x) {
            const float v = signedCount.at(x, y, channel);
            if (!(std::fabs(v - float(volumesContainingEye)) < 1e-3f)) ++r.badPixels;
        }
    return r;
}

}  // namespace viz::polyvol
