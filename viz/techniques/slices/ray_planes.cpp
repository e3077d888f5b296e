#include "techniques/slices/ray_planes.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace viz::slices {

namespace {

constexpr int kBarsHeight = 72;
constexpr int kStripHeight = 8;
constexpr int kGap = 2;
constexpr int kTargetWidth = 384;

using Rgb = std::array<float, 3>;

Rgb statusColour(int status) {
    switch (PickStatus(status)) {
        case PickStatus::Added: return {0.25f, 0.75f, 0.3f};
        case PickStatus::BeyondSurface: return {0.25f, 0.45f, 0.95f};
        case PickStatus::LightFrustum: return {0.4f, 0.4f, 0.4f};
        case PickStatus::UserPlane: return {0.65f, 0.35f, 0.85f};
        case PickStatus::OutsideQuad: return {0.12f, 0.12f, 0.12f};
        case PickStatus::None: break;
    }
    return {0.9f, 0.15f, 0.15f};
}

}  // namespace

Image rayPlanesChart(const Image& table) {
    const int rows = table.height;
    // Draw sets in order, each back to front; shown nearest first.
    int sets = 0;
    for (int r = 0; r < rows; ++r) sets = std::max(sets, int(table.at(kColSet, r, 1)) + 1);
    const int cell = std::max(1, kTargetWidth / std::max(rows, 1));
    const int width = std::max(1, rows * cell + std::max(sets - 1, 0) * kGap);
    const int height = kBarsHeight + kGap + kStripHeight + kGap + kStripHeight;
    Image img(width, height, 3);
    std::fill(img.pixels.begin(), img.pixels.end(), 0.06f);
    float largest = 0.0f;
    for (int r = 0; r < rows; ++r)
        largest = std::max({largest, table.at(kColSet, r, 2), table.at(kColSet, r, 3)});
    auto fill = [&](int x0, int x1, int y0, int y1, Rgb c) {
        for (int y = std::max(y0, 0); y < std::min(y1, height); ++y)
            for (int x = std::max(x0, 0); x < std::min(x1, width); ++x)
                for (int k = 0; k < 3; ++k) img.at(x, y, k) = c[std::size_t(k)];
    };
    // Position of each row: sets left to right, inside a set the last row (nearest plane) first.
    int x = 0;
    for (int set = 0; set < sets; ++set) {
        for (int r = rows - 1; r >= 0; --r) {
            if (int(table.at(kColSet, r, 1)) != set) continue;
            const int x1 = x + cell;
            const int inner = cell >= 3 ? 1 : 0;  // a dark gap between planes when there is room
            auto barTop = [&](float v) {
                const float f = largest > 0.0f && std::isfinite(v) ? std::clamp(v / largest, 0.0f, 1.0f) : 0.0f;
                return kBarsHeight - int(std::lround(f * float(kBarsHeight - 2)));
            };
            fill(x, x1 - inner, barTop(table.at(kColSet, r, 3)), kBarsHeight, {0.55f, 0.55f, 0.55f});
            // The stored value as a bar of half the width over the shaded one: where they differ, the
            // quantisation shows.
            const int half = std::max(1, (cell - inner) / 2);
            fill(x + (cell - inner - half) / 2, x + (cell - inner - half) / 2 + half, barTop(table.at(kColSet, r, 2)),
                 kBarsHeight, {1.0f, 0.6f, 0.15f});
            const int strip = kBarsHeight + kGap;
            fill(x, x1 - inner, strip, strip + kStripHeight, statusColour(int(table.at(kColTest, r, 0))));
            const float v = table.at(kColTest, r, 1);
            const Rgb vc = v < 0.0f ? Rgb{0.1f, 0.12f, 0.35f} : Rgb{v, v, v};
            fill(x, x1 - inner, strip + kStripHeight + kGap, height, vc);
            x = x1;
        }
        x += kGap;
    }
    return img;
}

}  // namespace viz::slices
