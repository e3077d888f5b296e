#include "report/temporal_error.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "report/error_metrics.h"

namespace viz::report {

namespace {

// a / b with relative L2's convention: 0 / 0 is 0 (nothing moved, nothing to compare with), x / 0 is NaN.
double relative(double value, double mean) {
    if (std::isnan(value)) return kUndefined;
    if (mean > 0.0) return value / mean;
    return value == 0.0 ? 0.0 : kUndefined;
}

}  // namespace

void TemporalAccumulator::add(const Image& test, const Image& reference) {
    VIZ_CHECK(test.width == reference.width && test.height == reference.height && test.channels == reference.channels,
              "TemporalAccumulator: technique and reference frames differ in size or channels");
    if (mFrames == 0) {
        mWidth = test.width, mHeight = test.height, mChannels = test.channels;
        const std::size_t pixels = std::size_t(mWidth) * std::size_t(mHeight);
        mPrevious.assign(pixels * std::size_t(mChannels), 0.0);
        mValid.assign(pixels, 0);
        mSumSquares.assign(pixels, 0.0);
        mCount.assign(pixels, 0);
    }
    VIZ_CHECK(test.width == mWidth && test.height == mHeight && test.channels == mChannels,
              "TemporalAccumulator: a frame differs in size or channels from the first");
    mFrameError.push_back(compareImages(test, reference).relativeL2);

    const std::size_t pixels = std::size_t(mWidth) * std::size_t(mHeight);
    const std::size_t channels = std::size_t(mChannels);
    double frameSquares = 0.0;
    std::size_t frameCount = 0;
    for (std::size_t p = 0; p < pixels; ++p) {
        bool testFinite = true, referenceFinite = true;
        for (std::size_t c = 0; c < channels; ++c) {
            testFinite &= std::isfinite(test.pixels[p * channels + c]);
            referenceFinite &= std::isfinite(reference.pixels[p * channels + c]);
        }
        if (referenceFinite) {
            for (std::size_t c = 0; c < channels; ++c) mReferenceSum += double(reference.pixels[p * channels + c]);
            mReferenceValues += channels;
        }
        mNonFiniteTest += testFinite ? 0 : 1;
        mNonFiniteReference += referenceFinite ? 0 : 1;
        const bool valid = testFinite && referenceFinite;
        if (mFrames > 0 && !(valid && mValid[p])) ++mExcluded;
        double squares = 0.0;
        for (std::size_t c = 0; c < channels && valid; ++c) {
            const std::size_t i = p * channels + c;
            // The difference of two floats in double: the same inputs give the same e, so an error
            // constant in time gives d = 0 exactly.
            const double e = double(test.pixels[i]) - double(reference.pixels[i]);
            const double d = e - mPrevious[i];
            squares += d * d;
            mPrevious[i] = e;
        }
        if (valid && mValid[p]) {
            mSumSquares[p] += squares;
            ++mCount[p];
            frameSquares += squares;
            ++frameCount;
        }
        mValid[p] = valid ? 1 : 0;
    }
    mFrameSquares.push_back(frameSquares);
    mFrameCount.push_back(frameCount);
    ++mFrames;
}

void TemporalAccumulator::gap() { std::fill(mValid.begin(), mValid.end(), 0); }

double TemporalAccumulator::referenceMean() const {
    return mReferenceValues > 0 ? mReferenceSum / double(mReferenceValues) : kUndefined;
}

double TemporalAccumulator::temporalRms() const {
    double total = 0.0;
    std::size_t count = 0;
    for (std::size_t p = 0; p < mSumSquares.size(); ++p)
        if (mCount[p] > 0) total += mSumSquares[p], count += mCount[p];
    const double channels = double(std::max(mChannels, 1));
    return relative(count > 0 ? 0.5 * std::sqrt(total / (double(count) * channels)) : kUndefined, referenceMean());
}

TemporalMetrics TemporalAccumulator::finish() const {
    TemporalMetrics m;
    m.frames = mFrames;
    m.frameError = mFrameError;
    m.nonFiniteTestPixels = mNonFiniteTest;
    m.nonFiniteReferencePixels = mNonFiniteReference;
    m.excludedDifferences = mExcluded;
    m.referenceMean = referenceMean();

    double errorSum = 0.0;
    std::size_t errorFrames = 0;
    for (double e : mFrameError) {
        if (std::isfinite(e)) errorSum += e, ++errorFrames;
        else ++m.framesWithoutError;
    }
    m.meanFrameError = errorFrames > 0 ? errorSum / double(errorFrames) : kUndefined;

    const double channels = double(std::max(mChannels, 1));
    for (std::size_t t = 0; t < mFrameSquares.size(); ++t) {
        const double rms = mFrameCount[t] > 0 ? 0.5 * std::sqrt(mFrameSquares[t] / (double(mFrameCount[t]) * channels)) : kUndefined;
        m.frameTemporal.push_back(relative(rms, m.referenceMean));
    }

    m.flicker = Image(mWidth, mHeight, 1);
    std::vector<double> perPixel;
    perPixel.reserve(mSumSquares.size());
    for (std::size_t p = 0; p < mSumSquares.size(); ++p) {
        if (mCount[p] == 0) {
            m.flicker.pixels[p] = std::numeric_limits<float>::quiet_NaN();
            ++m.pixelsWithoutDifference;
            continue;
        }
        const double f = 0.5 * std::sqrt(mSumSquares[p] / (double(mCount[p]) * channels));
        m.flicker.pixels[p] = float(f);
        perPixel.push_back(f);
    }
    m.temporalRms = temporalRms();
    if (perPixel.empty()) {
        m.worstFlicker = kUndefined;
    } else {
        // Nearest rank, as the single-frame percentile.
        const std::size_t rank =
            std::min(perPixel.size() - 1, std::size_t(std::ceil(0.99 * double(perPixel.size()))) - 1);
        std::nth_element(perPixel.begin(), perPixel.begin() + std::ptrdiff_t(rank), perPixel.end());
        m.worstFlicker = relative(perPixel[rank], m.referenceMean);
    }
    return m;
}

TemporalMetrics temporalMetrics(const std::vector<Image>& test, const std::vector<Image>& reference) {
    VIZ_CHECK(test.size() == reference.size(), "temporalMetrics: sequences differ in length");
    TemporalAccumulator accumulator;
    for (std::size_t t = 0; t < test.size(); ++t) accumulator.add(test[t], reference[t]);
    return accumulator.finish();
}

}  // namespace viz::report
