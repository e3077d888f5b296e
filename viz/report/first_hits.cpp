#include "report/first_hits.h"

#include <cmath>

#include "core/error.h"
#include "report/error_metrics.h"

namespace viz::report {

FirstHitMask firstHitAgreement(const Image& traced, const Image& drawn) {
    VIZ_CHECK(traced.width == drawn.width && traced.height == drawn.height && traced.channels == 1 &&
                  drawn.channels == 1,
              "firstHitAgreement: distance images differ in size or are not one channel");
    FirstHitMask mask;
    mask.width = traced.width;
    mask.height = traced.height;
    mask.agree.resize(traced.pixels.size());
    for (std::size_t i = 0; i < traced.pixels.size(); ++i) {
        const bool agree = firstHitsAgree(traced.pixels[i], drawn.pixels[i]);
        mask.agree[i] = agree ? 1 : 0;
        mask.disagreeing += agree ? 0 : 1;
    }
    return mask;
}

double relativeL2Over(const Image& test, const Image& reference, const FirstHitMask& mask) {
    VIZ_CHECK(test.width == reference.width && test.height == reference.height && test.channels == reference.channels &&
                  test.width == mask.width && test.height == mask.height,
              "relativeL2Over: images and mask differ in size or channels");
    double diff2 = 0.0, ref2 = 0.0;
    const std::size_t channels = std::size_t(test.channels);
    for (std::size_t p = 0; p < mask.agree.size(); ++p) {
        if (!mask.agree[p]) continue;
        for (std::size_t c = 0; c < channels; ++c) {
            const double a = test.pixels[p * channels + c], b = reference.pixels[p * channels + c];
            if (!std::isfinite(a)) return kUndefined;
            diff2 += (a - b) * (a - b);
            ref2 += b * b;
        }
    }
    return relativeL2FromSums(diff2, ref2);
}

}  // namespace viz::report
