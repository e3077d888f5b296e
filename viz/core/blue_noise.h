// A tileable blue-noise threshold map: an S x S image holding each of the values (k + 1/2) / S^2,
// k = 0 .. S^2 - 1, exactly once, arranged so that every threshold level is spread evenly (little
// low-frequency energy). Built with Ulichney's void-and-cluster method (1993) on a torus with a Gaussian
// filter (sigma 1.5 texels), from a fixed seed: the same map on every run and machine.
//
// Used where a per-pixel offset should look like even grain rather than clumps (raymarch jitter=blue).
#pragma once

#include <vector>

namespace viz {

// Row-major, size * size values in (0, 1). size: a power of two from 4 to 256. The 64 x 64 map takes a
// few tens of milliseconds; callers keep it.
std::vector<float> blueNoise(int size);

}  // namespace viz
