// The pixels whose first surface the rasteriser and the reference's traced ray disagree on.
//
// Every technique but the reference finds a pixel's surface by rasterising the scene; the reference
// traces the ray through the pixel's centre (Embree). At a silhouette the centre can lie within the
// rasteriser's sub-pixel snapping of an edge: the rasterised depth then sees the sky where the ray hits a
// trunk, or the reverse, and every technique integrates the air over the wrong span, whatever it does.
// On the built-in scenes these are a few pixels in ten thousand (forest at 320x240: 9 of 76,800), but
// each is wrong by all the air between the two hits, so they set a floor under every technique's error.
// `airlight report` counts them per scene and gives each error with them and without them.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/image.h"

namespace viz::report {

// Two first hits agree when their distances along the ray differ by at most this share of the traced one
// (both finite). The window's ray inspector says so of its pixel with the same test.
inline constexpr float kFirstHitTolerance = 1e-3f;
inline bool firstHitsAgree(float traced, float drawn) {
    return std::isfinite(traced) && std::isfinite(drawn) && std::abs(traced - drawn) <= kFirstHitTolerance * std::abs(traced);
}

struct FirstHitMask {
    int width = 0, height = 0;
    std::vector<std::uint8_t> agree;  // per pixel, row-major: 1 = the two first hits agree
    std::size_t disagreeing = 0;      // pixels with agree == 0
};

// traced: the reference's distance to the first surface per pixel (zfar for sky); drawn: the rasterised
// one (render::SurfacePass). One channel each, one size (VIZ_CHECK). A pixel where either is not finite
// disagrees.
FirstHitMask firstHitAgreement(const Image& traced, const Image& drawn);

// ||test - reference||_2 / ||reference||_2 over every channel of the pixels `mask` keeps; the figure
// ErrorMetrics::relativeL2 gives over all of them. Undefined (NaN) as there: a non-finite value in a
// kept pixel of `test`, or a black reference under a non-zero difference.
double relativeL2Over(const Image& test, const Image& reference, const FirstHitMask& mask);

}  // namespace viz::report
